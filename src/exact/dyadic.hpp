#pragma once
// Dyadic: exact numbers m·2^e (m an Integer, e a 64-bit exponent).
// Guarantees:
//  * +, −, ×, shifts and comparisons are exact; the representation is canonical (m odd, or m = 0
//    with e = 0), so equal values have equal representations.
//  * from_double is exact for every finite double and refuses NaN and ±∞.
//  * to_decimal prints the exact value; parse reads it back to the same value (a round trip).
//  * parse accepts only decimal texts whose value is dyadic ("0.375", "-2.5e-1", "3"); "0.1" is
//    refused with an InputError, because 1/10 has no finite binary expansion.
#include <compare>
#include <cstdint>
#include <string>
#include <string_view>

#include "exact/integer.hpp"

namespace kmr::exact {

class Dyadic {
 public:
  Dyadic() = default;
  Dyadic(int v) : Dyadic(Integer(v), 0) {}
  Dyadic(long long v) : Dyadic(Integer(v), 0) {}
  Dyadic(Integer mantissa, std::int64_t exponent = 0);

  static Dyadic from_double(double x);
  static Dyadic pow2(std::int64_t e) { return Dyadic(Integer(1), e); }
  static Dyadic parse(std::string_view text);

  const Integer& mantissa() const { return m_; }
  std::int64_t exponent() const { return e_; }
  int sign() const { return m_.sign(); }
  bool is_zero() const { return m_.is_zero(); }
  bool is_integer() const { return e_ >= 0; }

  Dyadic shifted(std::int64_t k) const { return is_zero() ? *this : Dyadic(m_, e_ + k, Raw{}); }
  Integer floor() const;
  Integer ceil() const;
  double to_double() const;  // nearest-ish double (for reports only, never for decisions)
  std::string to_decimal() const;

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b);
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) { return a + (-b); }
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) { return Dyadic(a.m_ * b.m_, a.e_ + b.e_); }
  Dyadic operator-() const { return Dyadic(-m_, e_, Raw{}); }
  Dyadic& operator+=(const Dyadic& o) { return *this = *this + o; }
  Dyadic& operator-=(const Dyadic& o) { return *this = *this - o; }
  Dyadic& operator*=(const Dyadic& o) { return *this = *this * o; }

  friend bool operator==(const Dyadic& a, const Dyadic& b) { return a.e_ == b.e_ && a.m_ == b.m_; }
  friend std::strong_ordering operator<=>(const Dyadic& a, const Dyadic& b);

 private:
  struct Raw {};
  Dyadic(Integer m, std::int64_t e, Raw) : m_(std::move(m)), e_(e) {}
  Integer m_{0};
  std::int64_t e_{0};
};

// A closed interval [lo, hi] of dyadics.
struct Interval {
  Dyadic lo, hi;
  bool contains(const Dyadic& x) const { return lo <= x && x <= hi; }
  Dyadic width() const { return hi - lo; }
  Dyadic midpoint() const { return (lo + hi).shifted(-1); }
};

}  // namespace kmr::exact
