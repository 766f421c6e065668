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
  Q q(d.mantissa());
  const auto e = d.exponent();
  if (e > 0) q *= Q(exact::Integer(1) << static_cast<unsigned>(e));
  if (e < 0) q /= Q(exact::Integer(1) << static_cast<unsigned>(-e));
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
