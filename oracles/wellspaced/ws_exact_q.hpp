#pragma once
// Internal: exact rationals (GMP mpq through Boost.Multiprecision) for the Chapter 3 oracles.
// Guarantees: to_q is exact for every Dyadic; to_text prints the exact value "p/q" or "p".
#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <string>

#include "exact/dyadic.hpp"

namespace kmr::oracle::ws::detail {

using Q = boost::multiprecision::mpq_rational;

inline Q to_q(const exact::Dyadic& d) {
  // Through GMP directly, whatever Boost options exact::Integer uses.
  Q q;
  mpq_set_z(q.backend().data(), d.mantissa().backend().data());
  const auto e = d.exponent();
  if (e > 0) mpq_mul_2exp(q.backend().data(), q.backend().data(), static_cast<mp_bitcnt_t>(e));
  if (e < 0) mpq_div_2exp(q.backend().data(), q.backend().data(), static_cast<mp_bitcnt_t>(-e));
  return q;
}

inline std::string to_text(const Q& q) { return q.str(); }
inline double to_dbl(const Q& q) { return q.convert_to<double>(); }

// True (and sets out) when d is exactly a double.
inline bool exact_double(const exact::Dyadic& d, double& out) {
  out = d.to_double();
  return std::isfinite(out) && exact::Dyadic::from_double(out) == d;
}

}  // namespace kmr::oracle::ws::detail
