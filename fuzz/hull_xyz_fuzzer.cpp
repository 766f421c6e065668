// Fuzz harness: the `kmr hull` point file (spec/formats.md), through the CLI's own reader
// kmr::hull::read_xyz (src/hull/xyz_file.hpp). Judged by a reader written here that shares no code
// with it (its own line splitter, a hand-written decimal grammar, std::from_chars for the
// value — fast_float in libstdc++ 12, not strtod):
//  * only kmr::InputError escapes; it is thrown exactly when the harness finds a bad line, and its
//    message starts with "in.xyz:N: " for the first bad line N;
//  * an accepted file gives one point per content line (a line with a field before any '#'), each
//    coordinate bit-identical to from_chars' nearest double (or, where from_chars reports the
//    value out of range, a finite value below DBL_MIN in magnitude: an underflow read as 0 or a
//    subnormal, which the format accepts).
#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "exact/error.hpp"
#include "fuzz_common.hpp"
#include "hull/xyz_file.hpp"

namespace {

struct Expect {
  std::size_t bad_line = 0;  // 0: the file is valid
  std::vector<std::vector<std::string>> lines;  // fields of the content lines
};

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool finite_decimal(const std::string& w) {
  // [+-]?(digits[.digits?] | .digits)([eE][+-]?digits)? (std::regex is not used: its recursion
  // overflows the stack on long fields).
  auto digits = [](const std::string& t) {
    for (char c : t)
      if (c < '0' || c > '9') return false;
    return true;
  };
  std::size_t ep = w.find_first_of("eE");
  std::string m = w.substr(0, ep), ex = ep == std::string::npos ? "0" : w.substr(ep + 1);
  if (!m.empty() && (m[0] == '+' || m[0] == '-')) m.erase(0, 1);
  if (!ex.empty() && (ex[0] == '+' || ex[0] == '-')) ex.erase(0, 1);
  std::size_t dp = m.find('.');
  std::string ip = m.substr(0, dp), fp = dp == std::string::npos ? "" : m.substr(dp + 1);
  if (!digits(ip) || !digits(fp) || ip.size() + fp.size() == 0 || ex.empty() || !digits(ex)) return false;
  // Overflow: a finite double cannot hold it. from_chars reports overflow and underflow alike as
  // out of range, so tell them apart by the sign of the decimal exponent of the leading digit.
  double v;
  auto [end, ec] = std::from_chars(w.data() + (w[0] == '+'), w.data() + w.size(), v);
  if (ec == std::errc()) return end == w.data() + w.size() && std::isfinite(v);
  FUZZ_CHECK(ec == std::errc::result_out_of_range, "from_chars refused a decimal: " + w);
  std::size_t e = w.find_first_of("eE");
  std::string mant = w.substr(0, e);
  long long exp10 = 0;
  if (e != std::string::npos) {
    std::string ex = w.substr(e + 1);
    bool neg = ex[0] == '-';
    if (ex[0] == '-' || ex[0] == '+') ex.erase(0, 1);
    ex.erase(0, std::min(ex.find_first_not_of('0'), ex.size()));
    exp10 = ex.empty() ? 0 : ex.size() > 12 ? 1000000000000LL : std::stoll(ex);
    if (neg) exp10 = -exp10;
  }
  std::size_t dot = mant.find('.'), first = mant.find_first_of("123456789");
  FUZZ_CHECK(first != std::string::npos, "out of range but zero: " + w);
  long long int_digits = static_cast<long long>(dot == std::string::npos ? mant.size() : dot);
  long long lead = int_digits - static_cast<long long>(first) - (first < static_cast<std::size_t>(int_digits) ? 1 : 0);
  return exp10 + lead < 0;  // the value is below 1: an underflow, accepted
}

Expect expect(const std::string& text) {
  Expect x;
  std::size_t number = 0, start = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    std::string line = text.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    start = nl == std::string::npos ? text.size() : nl + 1;
    ++number;
    line = line.substr(0, line.find('#'));
    std::vector<std::string> fields;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && space(line[i])) ++i;
      std::size_t j = i;
      while (j < line.size() && !space(line[j])) ++j;
      if (j > i) fields.push_back(line.substr(i, j - i));
      i = j;
    }
    if (fields.empty()) continue;
    bool ok = fields.size() == 3;
    for (const auto& f : fields) ok = ok && finite_decimal(f);
    if (!ok) {
      x.bad_line = number;
      return x;
    }
    x.lines.push_back(fields);
  }
  return x;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  std::string text(reinterpret_cast<const char*>(data), size);
  Expect x = expect(text);
  std::vector<kmr::geometry::Point3d> points;
  std::istringstream in(text);
  try {
    points = kmr::hull::read_xyz(in, "in.xyz");
  } catch (const kmr::InputError& e) {
    std::string want = "in.xyz:" + std::to_string(x.bad_line) + ": ";
    FUZZ_CHECK(x.bad_line != 0, std::string("a valid file refused: ") + e.what());
    FUZZ_CHECK(std::string(e.what()).rfind(want, 0) == 0, std::string("message '") + e.what() + "' does not start with " + want);
    return 0;
  }
  FUZZ_CHECK(x.bad_line == 0, "bad line " + std::to_string(x.bad_line) + " accepted");
  FUZZ_CHECK(points.size() == x.lines.size(), "point count");
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::string& w = x.lines[i][static_cast<std::size_t>(k)];
      double v = points[i][static_cast<std::size_t>(k)], ref;
      auto [end, ec] = std::from_chars(w.data() + (w[0] == '+'), w.data() + w.size(), ref);
      if (ec == std::errc()) {
        FUZZ_CHECK(std::memcmp(&v, &ref, sizeof v) == 0, "value of '" + w + "' is not the nearest double");
      } else {
        FUZZ_CHECK(std::isfinite(v) && std::fabs(v) < DBL_MIN, "value of out-of-range '" + w + "' is not an underflow");
      }
    }
  return 0;
}
