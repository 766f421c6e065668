#pragma once
// Point files for `kmr simulate sort`: one point per line, "x0 v" (decimal integers of any size),
// meaning position x0 + v·t. Blank lines and text after '#' are ignored.
// Guarantees: every malformed line is refused with an InputError naming "file:line" and the text;
// a file with no point is refused; nothing is returned unless the whole file is valid.
#include <istream>
#include <string>
#include <vector>

#include "exact/integer.hpp"

namespace kmr::kinetic {

struct LinearMotion1 {
  exact::Integer x0, v;
};

std::vector<LinearMotion1> parse_sort_points(std::istream& in, const std::string& filename);

}  // namespace kmr::kinetic
