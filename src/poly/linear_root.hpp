#pragma once
// Linear certificates c0 + c1·t on machine integers: the kinetic hot path of §2.1 (kinetic sorting
// of linear motion), exact without GMP. δ = 2^−bits, 0 ≤ bits ≤ 62; |c0|, |c1| < 2^62; |k| < 2^62.
//
// Guarantees (each a test in tests/poly/linear_root_test.cpp):
//  * linear_sign_before(c0, c1, bits, k) == sign_before(c0 + c1·t, kδ) exactly: 2^b·p(kδ) =
//    c0·2^b + c1·k has |c0·2^b|, |c1·k| < 2^124, so it is evaluated exactly in __int128.
//  * linear_root_interval_exact(c0, c1, bits) = floor(−c0·2^b / c1) exactly (c1 ≠ 0): the lattice
//    interval [kδ, (k+1)δ) that holds the root, by __int128 floor division.
//  * linear_root_interval_filtered(c0, c1, scale = 2^bits) returns the same k, or nothing:
//    for |c0|, |c1| ≤ 2^53 the double q̃ = fl(−c0·2^b / c1) is one correctly rounded division of
//    exact doubles (c0·2^b is exact). With K = floor(q), |K| < 2^52, K and K+1 are doubles and
//    rounding is monotone, so K ≤ q̃ ≤ K + 1; if q̃ is not an integer then floor(q̃) = K. The filter
//    answers only when |q̃| < 2^52 and q̃ ∉ ℤ, so an answer is always exact; a root on a lattice
//    point (q ∈ ℤ) or rounded onto one (within half an ulp of q̃) goes to the exact division.
//    Needs IEEE double with round-to-nearest (SSE2; no -ffast-math).
#include <cmath>
#include <cstdint>
#include <optional>

namespace kmr::poly {

inline int linear_sign_before(std::int64_t c0, std::int64_t c1, int bits, std::int64_t k) {
  __int128 v = (static_cast<__int128>(c0) << bits) + static_cast<__int128>(c1) * k;
  if (v != 0) return v > 0 ? 1 : -1;
  return c1 > 0 ? -1 : (c1 < 0 ? 1 : 0);  // a root at kδ: sign of p' = c1, times (−1)^1 (§2.1)
}

inline __int128 linear_root_interval_exact(std::int64_t c0, std::int64_t c1, int bits) {
  __int128 num = -(static_cast<__int128>(c0) << bits), den = c1;
  if (den < 0) num = -num, den = -den;
  __int128 q = num / den;
  if (q * den > num) q -= 1;  // floor for negative quotients
  return q;
}

inline std::optional<std::int64_t> linear_root_interval_filtered(std::int64_t c0, std::int64_t c1, double scale) {
  constexpr std::int64_t two53 = std::int64_t{1} << 53;
  if (c0 < -two53 || c0 > two53 || c1 < -two53 || c1 > two53 || c1 == 0) return std::nullopt;
  double q = (-static_cast<double>(c0) * scale) / static_cast<double>(c1);
  if (!(std::fabs(q) < 0x1p52)) return std::nullopt;
  double f = std::floor(q);
  if (f == q) return std::nullopt;  // q̃ ∈ ℤ: q may be q̃ or just below it
  return static_cast<std::int64_t>(f);
}

}  // namespace kmr::poly
