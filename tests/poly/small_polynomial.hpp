#pragma once
// Test helper: P({c0, c1, ..., cn}) is the Polynomial c0 + c1·t + ... + cn·tⁿ with small coefficients.
#include <initializer_list>
#include <vector>

#include "poly/polynomial.hpp"

namespace kmr::poly::testing {

inline Polynomial P(std::initializer_list<long long> c) {
  std::vector<exact::Integer> v;
  for (long long x : c) v.emplace_back(x);
  return Polynomial(v);
}

}  // namespace kmr::poly::testing
