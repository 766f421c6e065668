#pragma once
// Satellites (§4.1.1): a discrete polar template around every input vertex (its nucleus).
//
// Ray k (k = 0..23) leaves the nucleus at angle ≈ k·π/12; the orbit of rank ℓ has radius 2^ℓ. The
// ℓ-satellites of a nucleus v are v + 2^ℓ·u_k for the 12 rays k with k ≡ ℓ (mod 2) (odd rays on odd
// ranks, even rays on even ranks). A satellite moves with its nucleus (same motion plus a fixed
// translation).
//
// Exactness (deviation from the thesis, spec/kmesh.md): cos(kπ/12), sin(kπ/12) are irrational, so
// u_k is an exact *rational* unit vector (a/c, b/c) with a² + b² = c² (a Pythagorean triple) within
// 0.05° of angle kπ/12. All coordinates are scaled by kScale = lcm of the three hypotenuses, so a
// satellite offset kScale·2^ℓ·u_k is an exact Dyadic and every position is a dyadic (for moving
// points: a polynomial of time with dyadic coefficients).
// Guarantees (tests/kmesh/satellites_test.cpp):
//  * |u_k| = 1 exactly, so |s − v| = kScale·2^ℓ exactly for every ℓ-satellite s of v;
//  * the angle of u_k differs from kπ/12 by less than 0.05° (0.00087 rad);
//  * the template is symmetric under rotation by 90° (u_{k+6} = rot90(u_k)) and u_0 = (1, 0);
//  * rays_of_rank(ℓ) lists the 12 rays of ℓ's parity in increasing order.
#include <array>
#include <cstdint>

#include "exact/dyadic.hpp"
#include "geometry/point.hpp"

namespace kmr::kmesh {

using exact::Dyadic;
using Point2 = geometry::Point<2, Dyadic>;

inline constexpr int kRays = 24;

// A Pythagorean triple (a, b, c): the unit vector (a/c, b/c).
struct RayVector {
  std::int64_t a, b, c;
};

// The exact unit vector of ray k (0 ≤ k < 24).
RayVector ray_vector(int k);

// kScale = lcm(1469, 3361, 985): input coordinates are multiplied by it so that offsets are dyadic.
inline constexpr std::int64_t kScale = 4863249365LL;

// kScale·2^ℓ·u_k, exact.
Point2 satellite_offset(int ray, std::int64_t rank);

// The satellite of `nucleus` (already scaled) at (ray, rank): nucleus + satellite_offset(ray, rank).
Point2 satellite_position(const Point2& nucleus, int ray, std::int64_t rank);

// The 12 rays whose parity is that of the rank, in increasing order.
std::array<int, 12> rays_of_rank(std::int64_t rank);

}  // namespace kmr::kmesh
