#pragma once
// Trajectories of moving points (§2.3): each coordinate is an integer polynomial of time t, all
// coordinates of all points sharing one positive scale factor (which no predicate's sign depends on,
// since kmr's predicates are homogeneous in the coordinates).
// Guarantees:
//  * linear_trajectory(X, V, bits) is the point X/2^Bℓ + (V/2^Bv)·t scaled by 2^Bℓ, i.e. the
//    integer polynomial X + V·2^(Bℓ−Bv)·t, exactly.
//  * random_linear_trajectories draws X uniformly from [−2^Bℓ, 2^Bℓ] and V from [−2^Bv, 2^Bv] per
//    coordinate (the §2.4 input: positions and velocities uniform in [−1, 1]^D), deterministically
//    from the seeded generator.
#include <array>
#include <cstddef>
#include <random>
#include <vector>

#include "geometry/point.hpp"
#include "poly/polynomial.hpp"

namespace kmr::kinetic {

using exact::Integer;
using poly::Polynomial;

template <std::size_t D>
using Trajectory = geometry::Point<D, Polynomial>;

struct MotionBits {
  int position = 20;  // Bℓ (§2.3, §2.4)
  int velocity = 8;   // Bv
};

inline Polynomial linear_coordinate(const Integer& x, const Integer& v, MotionBits bits) {
  Integer scaled_v = v << static_cast<unsigned>(bits.position - bits.velocity);
  return Polynomial(std::vector<Integer>{x, scaled_v});
}

template <std::size_t D>
Trajectory<D> linear_trajectory(const std::array<Integer, D>& x, const std::array<Integer, D>& v, MotionBits bits) {
  Trajectory<D> t;
  for (std::size_t i = 0; i < D; ++i) t[i] = linear_coordinate(x[i], v[i], bits);
  return t;
}

template <std::size_t D>
std::vector<Trajectory<D>> random_linear_trajectories(std::size_t n, std::mt19937_64& rng, MotionBits bits = {}) {
  std::uniform_int_distribution<long long> pos(-(1LL << bits.position), 1LL << bits.position);
  std::uniform_int_distribution<long long> vel(-(1LL << bits.velocity), 1LL << bits.velocity);
  std::vector<Trajectory<D>> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::array<Integer, D> x, v;
    for (std::size_t i = 0; i < D; ++i) x[i] = pos(rng);
    for (std::size_t i = 0; i < D; ++i) v[i] = vel(rng);
    out.push_back(linear_trajectory<D>(x, v, bits));
  }
  return out;
}

}  // namespace kmr::kinetic
