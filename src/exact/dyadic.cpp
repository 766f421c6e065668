#include "exact/dyadic.hpp"

#include <cmath>
#include <limits>

#include "exact/error.hpp"

namespace kmr::exact {

namespace {
// Number of trailing zero bits of a nonzero integer.
std::int64_t trailing_zeros(const Integer& m) { return static_cast<std::int64_t>(boost::multiprecision::lsb(abs(m))); }

constexpr std::int64_t kMaxDecimalExponent = 100000;

// Decimal digits to an Integer. Leading zeros are stripped first: Boost/GMP would read "0123" as octal.
Integer from_decimal_digits(std::string_view digits) {
  std::size_t first = digits.find_first_not_of('0');
  if (first == std::string_view::npos) return Integer(0);
  return Integer(std::string(digits.substr(first)));
}
}  // namespace

Integer parse_integer(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
  if (i == text.size()) throw InputError("not an integer: '" + std::string(text) + "'");
  for (std::size_t j = i; j < text.size(); ++j)
    if (text[j] < '0' || text[j] > '9') throw InputError("not an integer: '" + std::string(text) + "'");
  Integer v = from_decimal_digits(text.substr(i));
  return text[0] == '-' ? Integer(-v) : v;
}

Dyadic::Dyadic(Integer mantissa, std::int64_t exponent) : m_(std::move(mantissa)), e_(exponent) {
  if (m_.is_zero()) {
    e_ = 0;
    return;
  }
  std::int64_t z = trailing_zeros(m_);
  if (z > 0) {
    m_ >>= static_cast<unsigned>(z);  // exact: the low z bits are zero (works on negatives too)
    e_ += z;
  }
}

Dyadic Dyadic::from_double(double x) {
  if (!std::isfinite(x)) throw InputError("not a finite number: " + std::to_string(x));
  if (x == 0) return Dyadic();
  int exp = 0;
  double frac = std::frexp(x, &exp);                  // x = frac·2^exp, 0.5 ≤ |frac| < 1
  double scaled = std::ldexp(frac, 53);               // an integer of at most 53 bits
  return Dyadic(Integer(static_cast<long long>(scaled)), exp - 53);
}

Dyadic operator+(const Dyadic& a, const Dyadic& b) {
  if (a.is_zero()) return b;
  if (b.is_zero()) return a;
  if (a.e_ <= b.e_) return Dyadic(a.m_ + (b.m_ << static_cast<unsigned>(b.e_ - a.e_)), a.e_);
  return Dyadic((a.m_ << static_cast<unsigned>(a.e_ - b.e_)) + b.m_, b.e_);
}

std::strong_ordering operator<=>(const Dyadic& a, const Dyadic& b) {
  int sa = a.sign(), sb = b.sign();
  if (sa != sb) return sa <=> sb;
  if (sa == 0) return std::strong_ordering::equal;
  // Same nonzero sign: compare magnitudes by bit position first, then exactly.
  std::int64_t ta = bit_length(a.m_) + a.e_, tb = bit_length(b.m_) + b.e_;
  if (ta != tb) return sa > 0 ? ta <=> tb : tb <=> ta;
  int c = (a - b).sign();
  return c <=> 0;
}

Integer Dyadic::floor() const {
  if (e_ >= 0) return m_ << static_cast<unsigned>(e_);
  return m_ >> static_cast<unsigned>(-e_);  // GMP's right shift of negatives rounds toward −∞
}

Integer Dyadic::ceil() const {
  Integer f = floor();
  return Dyadic(f) == *this ? f : Integer(f + 1);
}

double Dyadic::to_double() const {
  if (is_zero()) return 0;
  std::int64_t bits = bit_length(m_);
  Integer top = bits > 60 ? Integer(m_ >> static_cast<unsigned>(bits - 60)) : m_;
  std::int64_t e = e_ + (bits > 60 ? bits - 60 : 0);
  if (e > std::numeric_limits<int>::max() / 2) return sign() > 0 ? HUGE_VAL : -HUGE_VAL;
  if (e < std::numeric_limits<int>::min() / 2) return 0.0 * sign();
  return std::ldexp(top.convert_to<double>(), static_cast<int>(e));
}

std::string Dyadic::to_decimal() const {
  if (e_ >= 0) return Integer(m_ << static_cast<unsigned>(e_)).str();
  // m·2^e = m·5^(−e) / 10^(−e): print the integer and place the decimal point.
  std::int64_t places = -e_;
  Integer five_pow = boost::multiprecision::pow(Integer(5), static_cast<unsigned>(places));
  Integer scaled = abs(m_) * five_pow;
  std::string digits = scaled.str();
  auto width = static_cast<std::size_t>(places);
  if (digits.size() <= width) digits = std::string(width + 1 - digits.size(), '0') + digits;
  std::string head = digits.substr(0, digits.size() - width), tail = digits.substr(digits.size() - width);
  return (m_.sign() < 0 ? "-" : "") + head + "." + tail;
}

Dyadic Dyadic::parse(std::string_view text) {
  auto bad = [&](const std::string& why) {
    return InputError("not a dyadic number: '" + std::string(text) + "' (" + why + ")");
  };
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  std::string digits;
  std::int64_t exp10 = 0;
  bool seen_digit = false, seen_point = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    char c = text[i];
    if (c == '.') {
      if (seen_point) throw bad("two decimal points");
      seen_point = true;
    } else if (c >= '0' && c <= '9') {
      digits += c;
      seen_digit = true;
      if (seen_point) --exp10;
    } else {
      throw bad(std::string("unexpected character '") + c + "'");
    }
  }
  if (!seen_digit) throw bad("no digits");
  if (i < text.size()) {  // exponent part
    std::string_view e = text.substr(i + 1);
    if (e.empty() || e.size() > 8) throw bad("malformed or huge exponent");
    exp10 += static_cast<std::int64_t>(parse_integer(e).convert_to<long long>());
  }
  if (exp10 > kMaxDecimalExponent || exp10 < -kMaxDecimalExponent) throw bad("exponent out of range");
  Integer n = from_decimal_digits(digits);
  if (negative) n = -n;
  if (n.is_zero()) return Dyadic();
  if (exp10 >= 0) return Dyadic(n * boost::multiprecision::pow(Integer(10), static_cast<unsigned>(exp10)));
  // n·10^exp10 = (n / 5^k)·2^(−k) with k = −exp10: dyadic iff 5^k divides n.
  std::int64_t k = -exp10;
  Integer five_pow = boost::multiprecision::pow(Integer(5), static_cast<unsigned>(k));
  Integer q, r;
  boost::multiprecision::divide_qr(n, five_pow, q, r);
  if (!r.is_zero()) throw bad("its value has no finite binary expansion");
  return Dyadic(q, -k);
}

}  // namespace kmr::exact
