#include "hull/xyz_file.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "exact/error.hpp"
#include "exact/text_lines.hpp"

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
  for (const exact::TextLine& l : exact::read_text_lines(in, filename)) {
    auto where = [&] { return filename + ":" + std::to_string(l.number) + ": "; };
    if (l.tokens.size() != 3)
      throw InputError(where() + "expected 3 numbers 'x y z', found " + std::to_string(l.tokens.size()) +
                       " fields: '" + l.text() + "'");
    geometry::Point3d p;
    for (int k = 0; k < 3; ++k) {
      const std::string& w = l.tokens[k];
      if (!is_decimal(w)) throw InputError(where() + "not a decimal number: '" + w + "'");
      p[k] = std::strtod(w.c_str(), nullptr);  // correctly rounded (glibc)
      if (!std::isfinite(p[k])) throw InputError(where() + "not a finite double: '" + w + "'");
    }
    points.push_back(p);
  }
  return points;
}

}  // namespace kmr::hull
