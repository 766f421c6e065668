#include "kinetic/point_file.hpp"


#include "exact/error.hpp"
#include "exact/text_lines.hpp"

namespace kmr::kinetic {

std::vector<LinearMotion1> parse_sort_points(std::istream& in, const std::string& filename) {
  std::vector<LinearMotion1> points;
  for (const exact::TextLine& l : exact::read_text_lines(in, filename)) {
    auto where = [&] { return filename + ":" + std::to_string(l.number) + ": "; };
    if (l.tokens.size() != 2)
      throw InputError(where() + "expected 2 integers 'x0 v', found " + std::to_string(l.tokens.size()) + " fields: '" +
                       l.text() + "'");
    try {
      points.push_back({exact::parse_integer(l.tokens[0]), exact::parse_integer(l.tokens[1])});
    } catch (const InputError& e) {
      throw InputError(where() + e.what());
    }
  }
  if (points.empty()) throw InputError(filename + ": no points");
  return points;
}

}  // namespace kmr::kinetic
