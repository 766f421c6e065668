#pragma once
// Polynomial: dense univariate polynomials over Integer, p(t) = c0 + c1·t + ... + cn·tⁿ.
// Guarantees:
//  * Canonical form: no zero leading coefficient; the zero polynomial has no coefficients and
//    degree −1. Arithmetic (+, −, ×, derivative, composition with t → −t) is exact.
//  * sign_at(t) is the exact sign of p at a dyadic t (evaluated homogeneously in integers).
//  * pseudo_remainder(a, b) = lc(b)^(deg a − deg b + 1)·a mod b, exactly (Knuth's prem; note the
//    factor's sign: it may flip the sign of the true remainder, see sturm.hpp).
//  * gcd(a, b) is primitive with a positive leading coefficient; square_free_part(p) has the same
//    distinct real (and complex) roots as p, each simple.
#include <string>
#include <vector>

#include "exact/dyadic.hpp"
#include "exact/integer.hpp"

namespace kmr::poly {

using exact::Dyadic;
using exact::Integer;

class Polynomial {
 public:
  Polynomial() = default;
  Polynomial(int c) : Polynomial(Integer(c)) {}
  Polynomial(Integer c);
  explicit Polynomial(std::vector<Integer> coefficients);  // c0, c1, ..., cn

  // The polynomial t (the identity), and c·t^k.
  static Polynomial identity() { return monomial(Integer(1), 1); }
  static Polynomial monomial(Integer c, int k);
  // A positive multiple of (t − x) for a dyadic x: 2^s·t − m for x = m·2^(−s).
  static Polynomial linear_with_root(const Dyadic& x);

  int degree() const { return static_cast<int>(c_.size()) - 1; }
  bool is_zero() const { return c_.empty(); }
  const std::vector<Integer>& coefficients() const { return c_; }
  const Integer& operator[](int i) const { return c_[static_cast<std::size_t>(i)]; }
  const Integer& leading() const { return c_.back(); }
  int sign() const { return is_zero() ? 0 : leading().sign(); }  // the sign as t → +∞

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  Polynomial operator-() const;
  friend Polynomial operator*(const Integer& k, const Polynomial& p);
  friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.c_ == b.c_; }

  Polynomial derivative() const;
  Polynomial mirrored() const;          // p(−t)
  Polynomial shifted_by(const Integer& a) const;  // p(t + a)
  Integer content() const;              // positive gcd of the coefficients (0 for zero)
  Polynomial primitive_part() const;    // p / content(p); keeps the sign of the leading coefficient

  Integer evaluate(const Integer& t) const;
  // Exact sign of p(m / 2^s) for s ≥ 0.
  int sign_at(const Integer& m, long long s) const;
  int sign_at(const Dyadic& t) const;

  std::string to_string() const;

 private:
  void trim();
  std::vector<Integer> c_;
};

Polynomial pseudo_remainder(const Polynomial& a, const Polynomial& b);
// a / b when b divides a exactly over the rationals and the quotient has integer coefficients
// (e.g. b primitive and dividing a); throws ContractError otherwise.
Polynomial exact_quotient(const Polynomial& a, const Polynomial& b);
Polynomial gcd(const Polynomial& a, const Polynomial& b);
Polynomial square_free_part(const Polynomial& p);

// The sign of p just before and just after t (§2.1 degeneracy rule): the sign of the first
// non-vanishing derivative p^(k)(t), times (−1)^k before t. Throws InputError for p ≡ 0.
int sign_before(const Polynomial& p, const Dyadic& t);
int sign_after(const Polynomial& p, const Dyadic& t);

}  // namespace kmr::poly
