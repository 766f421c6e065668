#pragma once
// IntervalNT: closed intervals [lo, hi] of doubles with outward rounding — the fast tier of a
// filtered-exact computation (Shewchuk's fast/exact split; CGAL's Interval_nt).
// Guarantees (tests/exact/interval_nt_test.cpp):
//  * Enclosure: for x ∈ a, y ∈ b, x∘y ∈ a∘b for ∘ ∈ {+, −, ×, ÷}. Rounding is directed by the
//    exact error of each double operation (TwoSum; fma for × and ÷), so no rounding-mode switch is
//    needed, and an operation whose result is a double gives a point interval (exact stays exact).
//    fma's error terms are exact only away from underflow: products below 2^-900 in magnitude get
//    the bound [0, 2^-899] (or its negative), never an exception — exact-tier filters use +, −, ×
//    only and must not throw; divisions throw Uncertain when one of the two corner quotients
//    they compute (the extremes, chosen by the operands' signs) has an operand below 2^-900 (found
//    by fuzz/interval_nt).
//  * Decisions are never guessed: sign(), <, <=, ==, ... return the answer that holds for every
//    pair of points of the operands, and throw Uncertain when the operands do not decide it (overlap,
//    division by an interval holding 0, overflow, or results too small for fma to certify).
//  * The caller catches Uncertain and redoes the whole computation exactly (see wellspaced/).
//  * next_up / next_down equal std::nextafter toward ±∞ for every double (±0, subnormals, ±∞, NaN).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <boost/multiprecision/gmp.hpp>

namespace kmr::exact {

// std::nextafter(x, +∞) and std::nextafter(x, −∞), inline (issue 11 §4: the library calls were
// 2.4 % of a 2D wellspaced run). Equal to std::nextafter for every x, NaN and ±∞
// included (test IntervalNT.NextUpDownEqualStdNextafter).
inline double next_up(double x) {
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);
}
inline double next_down(double x) { return -next_up(-x); }

// Thrown when interval arithmetic cannot decide; the caller falls back to exact arithmetic.
struct Uncertain : std::runtime_error {
  Uncertain() : std::runtime_error("interval arithmetic cannot decide; recompute exactly") {}
};
[[noreturn, gnu::noinline, gnu::cold]] inline void throw_uncertain() { throw Uncertain(); }

class IntervalNT {
 public:
  IntervalNT() = default;                                    // [0, 0]
  IntervalNT(double x) : lo_(x), hi_(x) { check(); }         // NOLINT: doubles are exact points
  IntervalNT(int x) : lo_(x), hi_(x) {}                      // NOLINT
  static IntervalNT hull(double lo, double hi) { return IntervalNT(lo, hi); }

  double lo() const { return lo_; }
  double hi() const { return hi_; }
  double approx() const { return lo_ == hi_ ? lo_ : 0.5 * lo_ + 0.5 * hi_; }
  bool is_point() const { return lo_ == hi_; }
  // −1, 0 or 1 when decided; throws Uncertain otherwise.
  int sign() const {
    if (lo_ > 0) return 1;
    if (hi_ < 0) return -1;
    if (lo_ == 0 && hi_ == 0) return 0;
    throw_uncertain();
  }

  friend IntervalNT operator-(const IntervalNT& a) { return IntervalNT(-a.hi_, -a.lo_); }
  friend IntervalNT operator+(const IntervalNT& a, const IntervalNT& b) {
    if (a.is_point() && b.is_point()) {  // one TwoSum for both ends
      double s = a.lo_ + b.lo_, bb = s - a.lo_, e = (a.lo_ - (s - bb)) + (b.lo_ - bb);
      return IntervalNT(e < 0 ? step(s, -1) : s, e > 0 ? step(s, 1) : s);
    }
    return IntervalNT(sum(a.lo_, b.lo_, -1), sum(a.hi_, b.hi_, 1));
  }
  friend IntervalNT operator-(const IntervalNT& a, const IntervalNT& b) { return a + (-b); }
  friend IntervalNT operator*(const IntervalNT& a, const IntervalNT& b) {
    if (a.is_point() && b.is_point()) return IntervalNT(prod(a.lo_, b.lo_, -1), prod(a.lo_, b.lo_, 1));
    // neither operand straddles 0: the extreme products are known from the signs (rounding is
    // monotone, so these are the min and max over the four corner products)
    if (a.lo_ >= 0 && b.lo_ >= 0) return IntervalNT(prod(a.lo_, b.lo_, -1), prod(a.hi_, b.hi_, 1));
    if (a.hi_ <= 0 && b.hi_ <= 0) return IntervalNT(prod(a.hi_, b.hi_, -1), prod(a.lo_, b.lo_, 1));
    if (a.lo_ >= 0 && b.hi_ <= 0) return IntervalNT(prod(a.hi_, b.lo_, -1), prod(a.lo_, b.hi_, 1));
    if (a.hi_ <= 0 && b.lo_ >= 0) return IntervalNT(prod(a.lo_, b.hi_, -1), prod(a.hi_, b.lo_, 1));
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double x : {a.lo_, a.hi_})
      for (double y : {b.lo_, b.hi_}) {
        lo = std::min(lo, prod(x, y, -1));  // operands are finite (check()), so no NaN
        hi = std::max(hi, prod(x, y, 1));
      }
    return IntervalNT(lo, hi);
  }
  friend IntervalNT operator/(const IntervalNT& a, const IntervalNT& b) {
    // b does not straddle 0, so the signs tell which two corner quotients are the extremes
    // (rounding is monotone): for b > 0 the quotient grows with a and, where a ≥ 0, falls with b
    if (b.lo_ > 0) {
      if (a.lo_ >= 0) return IntervalNT(quot(a.lo_, b.hi_, -1), quot(a.hi_, b.lo_, 1));
      if (a.hi_ <= 0) return IntervalNT(quot(a.lo_, b.lo_, -1), quot(a.hi_, b.hi_, 1));
      return IntervalNT(quot(a.lo_, b.lo_, -1), quot(a.hi_, b.lo_, 1));
    }
    if (b.hi_ < 0) {
      if (a.lo_ >= 0) return IntervalNT(quot(a.hi_, b.hi_, -1), quot(a.lo_, b.lo_, 1));
      if (a.hi_ <= 0) return IntervalNT(quot(a.hi_, b.lo_, -1), quot(a.lo_, b.hi_, 1));
      return IntervalNT(quot(a.hi_, b.hi_, -1), quot(a.lo_, b.hi_, 1));
    }
    throw_uncertain();  // b holds 0
  }
  IntervalNT& operator+=(const IntervalNT& b) { return *this = *this + b; }
  IntervalNT& operator-=(const IntervalNT& b) { return *this = *this - b; }
  IntervalNT& operator*=(const IntervalNT& b) { return *this = *this * b; }
  IntervalNT& operator/=(const IntervalNT& b) { return *this = *this / b; }

  friend bool operator<(const IntervalNT& a, const IntervalNT& b) {
    if (a.hi_ < b.lo_) return true;
    if (a.lo_ >= b.hi_) return false;
    throw_uncertain();
  }
  friend bool operator<=(const IntervalNT& a, const IntervalNT& b) {
    if (a.hi_ <= b.lo_) return true;
    if (a.lo_ > b.hi_) return false;
    throw_uncertain();
  }
  friend bool operator>(const IntervalNT& a, const IntervalNT& b) { return b < a; }
  friend bool operator>=(const IntervalNT& a, const IntervalNT& b) { return b <= a; }
  friend bool operator==(const IntervalNT& a, const IntervalNT& b) {
    if (a.is_point() && b.is_point()) return a.lo_ == b.lo_;
    if (a.hi_ < b.lo_ || b.hi_ < a.lo_) return false;
    throw_uncertain();
  }
  friend bool operator!=(const IntervalNT& a, const IntervalNT& b) { return !(a == b); }

 private:
  IntervalNT(double lo, double hi) : lo_(lo), hi_(hi) { check(); }
  void check() const {
    if (!(std::fabs(lo_) <= std::numeric_limits<double>::max() && std::fabs(hi_) <= std::numeric_limits<double>::max()))
      [[unlikely]] throw_uncertain();
  }
  // The neighbouring double of finite x toward +∞ (dir > 0) or −∞ (dir < 0).
  static double step(double x, int dir) {
    if (dir < 0) return -step(-x, 1);
    // x == 0 is not reached today (a zero sum, product or quotient of doubles is exact, or is
    // caught by the underflow guards of prod/quot first); kept so that step is right on its own.
    if (x == 0) return std::numeric_limits<double>::denorm_min();
    auto b = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0 ? b + 1 : b - 1);
  }
  // a + b rounded toward −∞ (dir < 0) or +∞ (dir > 0); TwoSum gives the exact error.
  static double sum(double a, double b, int dir) {
    double s = a + b;
    double bb = s - a;
    double e = (a - (s - bb)) + (b - bb);
    return (dir < 0 ? e < 0 : e > 0) ? step(s, dir) : s;
  }
  // Below this magnitude fma's error term may itself be rounded; such results are refused.
  static constexpr double kTiny = 0x1p-900;
  static double prod(double a, double b, int dir) {
    double p = a * b;
    if ((p != 0 && std::fabs(p) < kTiny) || (p == 0 && a != 0 && b != 0)) {
      // |a·b| < 2·kTiny and its sign is known: a sound (if wide) bound, so that exact-tier
      // filters on tiny coordinates never throw; decisions near 0 then go to the exact tier
      bool positive = (a > 0) == (b > 0);
      if (dir < 0) return positive ? 0.0 : -2 * kTiny;
      return positive ? 2 * kTiny : 0.0;
    }
    double e = std::fma(a, b, -p);
    return (dir < 0 ? e < 0 : e > 0) ? step(p, dir) : p;
  }
  static double quot(double a, double b, int dir) {
    // fma's remainder a − q·b is exact only away from underflow: refuse tiny operands too
    if (std::fabs(b) < kTiny || (a != 0 && std::fabs(a) < kTiny)) throw_uncertain();
    double q = a / b;
    if (q != 0 && std::fabs(q) < kTiny) throw_uncertain();
    if (q == 0 && a != 0) throw_uncertain();
    double r = std::fma(-q, b, a);  // a − q·b, exact; a/b − q has the sign of r/b
    int s = (r > 0) - (r < 0);
    if (b < 0) s = -s;
    return (dir < 0 ? s < 0 : s > 0) ? step(q, dir) : q;
  }
  double lo_ = 0, hi_ = 0;
};

// The tightest interval of doubles known to hold the rational q (GMP's mpq_get_d truncates toward
// zero, so the value lies within one ulp of it; exactly representable values give a point).
inline IntervalNT enclose(const boost::multiprecision::mpq_rational& q) {
  const auto* r = q.backend().data();
  double d = mpq_get_d(r);
  // exactly a double: power-of-two denominator, ≤ 53 significant numerator bits, normal range
  if (mpz_sgn(mpq_numref(r)) == 0) return IntervalNT(0);
  if (mpz_popcount(mpq_denref(r)) == 1 &&
      mpz_sizeinbase(mpq_numref(r), 2) - mpz_scan1(mpq_numref(r), 0) <= 53 &&
      std::fabs(d) >= std::numeric_limits<double>::min())
    return IntervalNT(d);
  return IntervalNT::hull(next_down(d), next_up(d));
}
inline const IntervalNT& enclose(const IntervalNT& x) { return x; }

}  // namespace kmr::exact
