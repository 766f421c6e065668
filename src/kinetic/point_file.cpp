#include "kinetic/point_file.hpp"

#include <sstream>

#include "exact/error.hpp"

namespace kmr::kinetic {

std::vector<LinearMotion1> parse_sort_points(std::istream& in, const std::string& filename) {
  std::vector<LinearMotion1> points;
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number) {
    auto where = [&] { return filename + ":" + std::to_string(number) + ": "; };
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;
    if (words.size() != 2)
      throw InputError(where() + "expected 2 integers 'x0 v', found " + std::to_string(words.size()) + " fields: '" +
                       line + "'");
    try {
      points.push_back({exact::parse_integer(words[0]), exact::parse_integer(words[1])});
    } catch (const InputError& e) {
      throw InputError(where() + e.what());
    }
  }
  if (in.bad()) throw InputError(filename + ": read error");
  if (points.empty()) throw InputError(filename + ": no points");
  return points;
}

}  // namespace kmr::kinetic
