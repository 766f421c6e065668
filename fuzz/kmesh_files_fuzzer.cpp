// Fuzz harness: the `kmr kmesh` FILE and --updates formats (spec/formats.md), through the CLI's own
// entry points kmr::cli::parse_kmesh_points / parse_kmesh_updates (src/cli/formats.hpp). The first
// byte gives the lattice bits B ∈ [0, 62] (the range of --lattice-bits); the rest is the point file,
// then (after a line "%%") the update file. Judged by a reader written here (its own line splitter,
// hand-written grammars, values as Boost rationals built from the digits; no kmr parsing code):
//  * only kmr::InputError escapes; it is thrown exactly when the harness finds a bad line (or no
//    content line in the point file), and names the first bad line ("pts.txt:N: ", "upd.txt:N: ");
//  * accepted points: one per content line, x y [vx vy] equal to the harness's integers (0 if omitted);
//  * accepted updates: one per content line, in order, + or - as written, the time equal to the
//    harness's rational value of the decimal, which is ≥ 0 and a multiple of 2^-B. A time is refused
//    exactly when it is malformed, not dyadic, negative, off the lattice, or beyond the documented
//    exponent limits of dyadic decimals (an exponent field of more than 8 characters, or a decimal
//    exponent, after the fraction digits, beyond ±100000).
#include <boost/multiprecision/gmp.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/formats.hpp"
#include "exact/error.hpp"
#include "fuzz_common.hpp"

namespace {

using Q = boost::multiprecision::mpq_rational;
using Z = boost::multiprecision::mpz_int;

struct Line {
  std::size_t number;
  std::vector<std::string> fields;
};

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<Line> content_lines(const std::string& text) {
  std::vector<Line> out;
  std::size_t number = 0, start = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    std::string line = text.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    start = nl == std::string::npos ? text.size() : nl + 1;
    ++number;
    line = line.substr(0, line.find('#'));
    Line l{number, {}};
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && space(line[i])) ++i;
      std::size_t j = i;
      while (j < line.size() && !space(line[j])) ++j;
      if (j > i) l.fields.push_back(line.substr(i, j - i));
      i = j;
    }
    if (!l.fields.empty()) out.push_back(l);
  }
  return out;
}

// Digits read in base 10 by GMP itself (Boost's string constructor reads a leading 0 as octal).
Z decimal(const std::string& digits) {
  Z v;
  FUZZ_CHECK(mpz_set_str(v.backend().data(), digits.c_str(), 10) == 0, "mpz_set_str: " + digits);
  return v;
}

bool all_digits(const std::string& w) {
  for (char c : w)
    if (c < '0' || c > '9') return false;
  return true;
}

// [+-]?[0-9]+ (std::regex is not used: its recursion overflows the stack on long fields).
bool integer(const std::string& w, Z& v) {
  std::string d = (!w.empty() && (w[0] == '+' || w[0] == '-')) ? w.substr(1) : w;
  if (d.empty() || !all_digits(d)) return false;
  v = decimal(d);
  if (w[0] == '-') v = -v;
  return true;
}

// A lattice time: [+-]digits[.digits][(e|E)exponent] with at least one digit, its value dyadic,
// ≥ 0 and a multiple of 2^-bits (and within the documented exponent limits).
bool lattice_time(const std::string& w, long long bits, Q& v) {
  std::size_t e = w.find_first_of("eE");
  std::string mant = w.substr(0, e);
  bool negative = !mant.empty() && mant[0] == '-';
  if (!mant.empty() && (mant[0] == '+' || mant[0] == '-')) mant.erase(0, 1);
  std::size_t dot = mant.find('.');
  std::string whole = mant.substr(0, dot), frac = dot == std::string::npos ? "" : mant.substr(dot + 1);
  if (!all_digits(whole) || !all_digits(frac) || whole.size() + frac.size() == 0) return false;
  long long exp10 = -static_cast<long long>(frac.size());
  if (e != std::string::npos) {
    std::string ex = w.substr(e + 1);
    Z x;
    if (ex.size() > 8 || !integer(ex, x)) return false;
    exp10 += x.convert_to<long long>();
  }
  if (exp10 > 100000 || exp10 < -100000) return false;
  Z n = decimal(whole + frac);
  if (negative) n = -n;
  Z ten = boost::multiprecision::pow(Z(10), static_cast<unsigned>(exp10 < 0 ? -exp10 : exp10));
  v = exp10 >= 0 ? Q(n * ten) : Q(n, ten);
  Z den = boost::multiprecision::denominator(v);
  if (boost::multiprecision::lsb(den) != boost::multiprecision::msb(den)) return false;  // not a power of 2
  if (v < 0) return false;
  Q scaled = v * Q(Z(1) << static_cast<unsigned>(bits));
  return boost::multiprecision::denominator(scaled) == 1;
}

Q value(const kmr::exact::Dyadic& d) {
  Z m(d.mantissa().str());
  std::int64_t e = d.exponent();
  return e >= 0 ? Q(m << static_cast<unsigned>(e)) : Q(m, Z(1) << static_cast<unsigned>(-e));
}

bool same(const kmr::exact::Integer& a, const Z& b) { return Z(a.str()) == b; }

void check_message(const kmr::InputError& e, const std::string& name, std::size_t bad) {
  std::string want = name + ":" + std::to_string(bad) + ": ";
  FUZZ_CHECK(bad != 0, std::string("a valid file refused: ") + e.what());
  FUZZ_CHECK(std::string(e.what()).rfind(want, 0) == 0, std::string("message '") + e.what() + "' does not start with " + want);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > 4096) return 0;
  long long bits = data[0] % 63;
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::size_t sep = text.find("\n%%\n");
  std::string pts = sep == std::string::npos ? text : text.substr(0, sep + 1);
  std::string upd = sep == std::string::npos ? "" : text.substr(sep + 4);

  // Points: the harness's verdict first.
  auto plines = content_lines(pts);
  std::size_t pbad = 0;
  std::vector<std::vector<Z>> pvals;
  for (const auto& l : plines) {
    std::vector<Z> v(4, Z(0));
    bool ok = l.fields.size() == 2 || l.fields.size() == 4;
    for (std::size_t k = 0; ok && k < l.fields.size(); ++k) ok = integer(l.fields[k], v[k]);
    if (!ok) {
      pbad = l.number;
      break;
    }
    pvals.push_back(v);
  }
  std::istringstream pin(pts);
  std::vector<kmr::cli::KmeshTrajectory> points;
  try {
    points = kmr::cli::parse_kmesh_points(pin, "pts.txt");
  } catch (const kmr::InputError& e) {
    if (plines.empty() && pbad == 0) {
      FUZZ_CHECK(std::string(e.what()) == "pts.txt: no input point", std::string("message: ") + e.what());
    } else {
      check_message(e, "pts.txt", pbad);
    }
    return 0;
  }
  FUZZ_CHECK(pbad == 0, "bad point line " + std::to_string(pbad) + " accepted");
  FUZZ_CHECK(!plines.empty(), "an empty point file accepted");
  FUZZ_CHECK(points.size() == pvals.size(), "point count");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    FUZZ_CHECK(p.line == plines[i].number, "line number of point " + std::to_string(i));
    FUZZ_CHECK(same(p.x, pvals[i][0]) && same(p.y, pvals[i][1]) && same(p.vx, pvals[i][2]) && same(p.vy, pvals[i][3]),
               "values of point line " + std::to_string(p.line));
  }
  if (sep == std::string::npos) return 0;

  // Updates.
  auto ulines = content_lines(upd);
  std::size_t ubad = 0;
  std::vector<std::pair<Q, std::vector<Z>>> uvals;
  for (const auto& l : ulines) {
    std::vector<Z> v(4);
    Q t;
    bool ok = l.fields.size() == 6 && (l.fields[1] == "+" || l.fields[1] == "-");
    // The CLI checks the fields left to right, the time first: a bad time or a bad integer both
    // refuse the line, so the order does not change the verdict.
    ok = ok && lattice_time(l.fields[0], bits, t);
    for (std::size_t k = 0; ok && k < 4; ++k) ok = integer(l.fields[k + 2], v[k]);
    if (!ok) {
      ubad = l.number;
      break;
    }
    uvals.push_back({t, v});
  }
  std::istringstream uin(upd);
  std::vector<kmr::cli::KmeshUpdate> updates;
  try {
    updates = kmr::cli::parse_kmesh_updates(uin, "upd.txt", bits);
  } catch (const kmr::InputError& e) {
    check_message(e, "upd.txt", ubad);
    return 0;
  }
  FUZZ_CHECK(ubad == 0, "bad update line " + std::to_string(ubad) + " accepted (bits " + std::to_string(bits) + ")");
  FUZZ_CHECK(updates.size() == uvals.size(), "update count");
  for (std::size_t i = 0; i < updates.size(); ++i) {
    const auto& u = updates[i];
    std::string what = "update line " + std::to_string(ulines[i].number);
    FUZZ_CHECK(u.where == "upd.txt:" + std::to_string(ulines[i].number), what + ": where = " + u.where);
    FUZZ_CHECK(u.insert == (ulines[i].fields[1] == "+"), what + ": sign");
    FUZZ_CHECK(value(u.t) == uvals[i].first, what + ": time " + u.t.to_decimal() + " is not " + ulines[i].fields[0]);
    const auto& v = uvals[i].second;
    FUZZ_CHECK(same(u.p.x, v[0]) && same(u.p.y, v[1]) && same(u.p.vx, v[2]) && same(u.p.vy, v[3]), what + ": values");
  }
  return 0;
}
