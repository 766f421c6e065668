// Fuzz harness (d): the sort-point-file parser, kmr::kinetic::parse_sort_points (one point per line,
// "x0 v", decimal integers; InputError naming file:line on bad input). Checks:
//  * only kmr::InputError may escape, and its message names the file ("fuzz.pts:<line>");
//  * a parsed file round-trips: printing every point as "x0 v" and parsing that again gives the
//    same points in the same order.
#include <sstream>
#include <string>

#include "exact/error.hpp"
#include "fuzz_common.hpp"
#include "kinetic/point_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  std::vector<kmr::kinetic::LinearMotion1> points;
  try {
    points = kmr::kinetic::parse_sort_points(in, "fuzz.pts");
  } catch (const kmr::InputError& e) {
    FUZZ_CHECK(std::string(e.what()).find("fuzz.pts:") != std::string::npos, std::string("message: ") + e.what());
    return 0;
  }
  std::ostringstream out;
  for (const auto& p : points) out << p.x0 << ' ' << p.v << '\n';
  std::istringstream again(out.str());
  auto reparsed = kmr::kinetic::parse_sort_points(again, "again.pts");
  FUZZ_CHECK(reparsed.size() == points.size(), out.str());
  for (std::size_t i = 0; i < points.size(); ++i)
    FUZZ_CHECK(reparsed[i].x0 == points[i].x0 && reparsed[i].v == points[i].v, out.str());
  return 0;
}
