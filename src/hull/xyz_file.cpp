#include "hull/xyz_file.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "exact/error.hpp"

namespace kmr::hull {
namespace {

bool is_decimal(const std::string& w) {
  std::size_t i = 0, n = w.size();
  auto digits = [&] {
    std::size_t s = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(w[i]))) ++i;
    return i - s;
  };
  if (i < n && (w[i] == '+' || w[i] == '-')) ++i;
  std::size_t mant = digits();
  if (i < n && w[i] == '.') {
    ++i;
    mant += digits();
  }
  if (mant == 0) return false;
  if (i < n && (w[i] == 'e' || w[i] == 'E')) {
    ++i;
    if (i < n && (w[i] == '+' || w[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == n;
}

}  // namespace

std::vector<geometry::Point3d> read_xyz(std::istream& in, const std::string& filename) {
  std::vector<geometry::Point3d> points;
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number) {
    auto where = [&] { return filename + ":" + std::to_string(number) + ": "; };
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;
    if (words.size() != 3)
      throw InputError(where() + "expected 3 numbers 'x y z', found " + std::to_string(words.size()) +
                       " fields: '" + line + "'");
    geometry::Point3d p;
    for (int k = 0; k < 3; ++k) {
      if (!is_decimal(words[k])) throw InputError(where() + "not a decimal number: '" + words[k] + "'");
      p[k] = std::strtod(words[k].c_str(), nullptr);  // correctly rounded (glibc)
      if (!std::isfinite(p[k])) throw InputError(where() + "not a finite double: '" + words[k] + "'");
    }
    points.push_back(p);
  }
  if (in.bad()) throw InputError(filename + ": read error");
  return points;
}

}  // namespace kmr::hull
