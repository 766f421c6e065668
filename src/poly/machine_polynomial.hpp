#pragma once
// MachinePolynomial: a polynomial of degree ≤ 3 with __int128 coefficients, the machine form of a
// certificate polynomial (issue 9: the kinetic hull's orient3d cubics of linearly moving points
// built without GMP).
//
// Guarantees (tests/poly/machine_polynomial_test.cpp):
//  * +, −, × are exact integer polynomial arithmetic, or refused with a ContractError (never a
//    wrapped value) when an intermediate overflows __int128 or a product's degree exceeds 3; the
//    caller avoids that by a bound on its inputs (moving_points.hpp: linear coordinates with
//    |c| ≤ 2^36 keep every hull certificate below 2^123).
//  * to_polynomial() is the same Polynomial that the same operations over Polynomial give
//    (canonical: no zero leading coefficient), so every decision taken on either is the same.
//  * approximations(): each coefficient rounded to nearest double (|error| ≤ 2^−53·|c|, inside
//    the one-ulp allowance of DoubleCoefficients).
#include <array>
#include <bit>
#include <cstdint>

#include "poly/polynomial.hpp"

namespace kmr::poly {

class MachinePolynomial {
 public:
  static constexpr int kMaxDegree = 3;
  MachinePolynomial() = default;
  MachinePolynomial(__int128 c) { set(0, c); }  // NOLINT: a constant
  static MachinePolynomial linear(__int128 c0, __int128 c1) {
    MachinePolynomial p(c0);
    p.set(1, c1);
    return p;
  }

  // c0 + c1·t + c2·t² + c3·t³ stored directly: the same polynomial as linear(c0, c1) +
  // cubic_terms(c2, c3) (the kinetic hull's orient3d cubics, moving_points.cpp), without the
  // generic sum's overflow checks (adding zeros cannot overflow) and its second trim.
  static MachinePolynomial cubic(__int128 c0, __int128 c1, __int128 c2, __int128 c3) {
    MachinePolynomial p;
    p.c_ = {c0, c1, c2, c3};
    p.trim();
    return p;
  }
  static MachinePolynomial cubic_terms(__int128 c2, __int128 c3) {  // c2·t² + c3·t³
    MachinePolynomial p;
    p.c_[2] = c2;
    p.set(3, c3);
    return p;
  }

  int degree() const { return degree_; }  // −1 for zero
  bool is_zero() const { return degree_ < 0; }
  __int128 operator[](int i) const { return c_[static_cast<std::size_t>(i)]; }

  friend MachinePolynomial operator+(const MachinePolynomial& a, const MachinePolynomial& b) {
    MachinePolynomial r;
    for (std::size_t i = 0; i <= kMaxDegree; ++i) check(!__builtin_add_overflow(a.c_[i], b.c_[i], &r.c_[i]));
    r.trim();
    return r;
  }
  friend MachinePolynomial operator-(const MachinePolynomial& a, const MachinePolynomial& b) {
    MachinePolynomial r;
    for (std::size_t i = 0; i <= kMaxDegree; ++i) check(!__builtin_sub_overflow(a.c_[i], b.c_[i], &r.c_[i]));
    r.trim();
    return r;
  }
  friend MachinePolynomial operator*(const MachinePolynomial& a, const MachinePolynomial& b) {
    MachinePolynomial r;
    if (a.is_zero() || b.is_zero()) return r;
    check(a.degree_ + b.degree_ <= kMaxDegree);
    for (int i = 0; i <= a.degree_; ++i)
      for (int j = 0; j <= b.degree_; ++j) {
        __int128 t;
        check(!__builtin_mul_overflow(a[i], b[j], &t));
        check(!__builtin_add_overflow(r.c_[static_cast<std::size_t>(i + j)], t, &r.c_[static_cast<std::size_t>(i + j)]));
      }
    r.trim();
    return r;
  }
  friend bool operator==(const MachinePolynomial& a, const MachinePolynomial& b) { return a.c_ == b.c_; }

  Polynomial to_polynomial() const;
  std::array<double, kMaxDegree + 1> approximations() const {
    std::array<double, kMaxDegree + 1> d{};
    for (int i = 0; i <= degree_; ++i) d[static_cast<std::size_t>(i)] = to_double(c_[static_cast<std::size_t>(i)]);
    return d;
  }
  // c rounded to nearest (ties to even), as the 128-bit library conversion rounds it, without its
  // call: a 64-bit conversion when c fits; else the top 64 bits of |c| with a sticky bit for the
  // rest (below the rounding position, so the one rounding of the 64-bit conversion is c's),
  // scaled by an exact power of two.
  static double to_double(__int128 c) {
    const auto s = static_cast<std::int64_t>(c);
    if (s == c) return static_cast<double>(s);
    const bool neg = c < 0;
    const unsigned __int128 u = neg ? -static_cast<unsigned __int128>(c) : static_cast<unsigned __int128>(c);
    const auto hi = static_cast<std::uint64_t>(u >> 64), lo = static_cast<std::uint64_t>(u);
    double r;
    if (hi == 0) {
      r = static_cast<double>(lo);
    } else {
      const int sh = 64 - __builtin_clzll(hi);  // 1..63: u >> sh has 64 bits
      const std::uint64_t m = static_cast<std::uint64_t>(u >> sh) | static_cast<std::uint64_t>((lo << (64 - sh)) != 0);
      r = static_cast<double>(m) * std::bit_cast<double>(static_cast<std::uint64_t>(1023 + sh) << 52);  // ·2^sh, exact
    }
    return neg ? -r : r;
  }

  // |c| < 2^bits
  static bool fits(__int128 c, int bits) {
    const __int128 lim = static_cast<__int128>(1) << bits;
    return c > -lim && c < lim;
  }

 private:
  static void check(bool ok) {
    if (!ok) overflow();
  }
  [[noreturn]] static void overflow();  // ContractError
  void set(int i, __int128 c) {
    c_[static_cast<std::size_t>(i)] = c;
    trim();
  }
  void trim() {
    degree_ = -1;
    for (int k = kMaxDegree; k >= 0; --k)
      if (c_[static_cast<std::size_t>(k)] != 0) {
        degree_ = k;
        break;
      }
  }
  std::array<__int128, kMaxDegree + 1> c_{};
  int degree_ = -1;
};

// The exact Integer of a machine integer.
Integer to_integer(__int128 c);

}  // namespace kmr::poly
