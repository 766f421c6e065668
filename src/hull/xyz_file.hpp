#pragma once
// Reading `kmr hull` point files: one point per line, `x y z` as decimal numbers read as the
// nearest doubles (as CGAL's XYZ reader does); `#` starts a comment; blank lines are skipped.
// Guarantees: a line with other than three fields, a field that is not a decimal number
// ([+-]digits[.digits][(e|E)[+-]digits], at least one digit), or a value that is not finite as a
// double (overflow) throws InputError naming file:line and the field. Underflow reads as the
// nearest double (possibly 0), like every other decimal.
#include <istream>
#include <string>
#include <vector>

#include "geometry/filtered_orientation.hpp"

namespace kmr::hull {

std::vector<geometry::Point3d> read_xyz(std::istream& in, const std::string& filename);

}  // namespace kmr::hull
