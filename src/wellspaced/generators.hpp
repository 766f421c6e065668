#pragma once
// Seeded input generators for Chapter 3 tests, property tests, benchmarks and the audit
// (verification doctrine 4: degenerate inputs on purpose). Every generator returns distinct points
// in [0,1]^D with dyadic (exact double) coordinates, depending only on (kind, n, seed).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "wellspaced/well_spaced_set.hpp"

namespace kmr::wellspaced::gen {

enum class Kind { uniform, clustered, line, plane, sphere, grid, close_pair, boundary };
inline const char* name(Kind k) {
  switch (k) {
    case Kind::uniform: return "uniform";
    case Kind::clustered: return "clustered";
    case Kind::line: return "line";
    case Kind::plane: return "plane";
    case Kind::sphere: return "sphere";
    case Kind::grid: return "grid";
    case Kind::close_pair: return "close_pair";
    case Kind::boundary: return "boundary";
  }
  return "?";
}
inline constexpr Kind kAllKinds[] = {Kind::uniform, Kind::clustered, Kind::line, Kind::plane,
                                     Kind::sphere, Kind::grid, Kind::close_pair, Kind::boundary};

// A dyadic number in [0,1] with `bits` bits.
inline double dyadic01(std::mt19937_64& rng, int bits = 20) {
  std::uint64_t m = rng() >> (64 - bits);
  return std::ldexp(static_cast<double>(m), -bits);
}

template <std::size_t D>
std::vector<Point<D>> points(Kind kind, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(kind) + 1);
  std::set<Point<D>> out;
  auto add = [&](Point<D> p) {
    for (auto& x : p) x = std::clamp(x, 0.0, 1.0);
    out.insert(p);
  };
  std::size_t guard = 0;
  while (out.size() < n && guard++ < 100 * n + 1000) {
    Point<D> p;
    switch (kind) {
      case Kind::uniform:
        for (auto& x : p) x = dyadic01(rng);
        break;
      case Kind::clustered: {  // 3 clusters of radius 2^-12 around fixed centres
        int c = static_cast<int>(rng() % 3);
        for (std::size_t i = 0; i < D; ++i) {
          double centre = 0.25 + 0.25 * ((c + i) % 3);
          p[i] = centre + std::ldexp(dyadic01(rng, 12) - 0.5, -11);
        }
        break;
      }
      case Kind::line: {  // the main diagonal: exactly collinear
        double t = dyadic01(rng);
        for (auto& x : p) x = t;
        break;
      }
      case Kind::plane:  // x_D = 1/2: exactly co-(hyper)planar
        for (auto& x : p) x = dyadic01(rng);
        p[D - 1] = 0.5;
        break;
      case Kind::sphere: {  // permutations of (±3, ±4, 0, ..)/16 and ±5 e_i/16 around the centre
        for (auto& x : p) x = 0.5;
        std::size_t i = rng() % D, j = rng() % D;
        if (i == j || rng() % 4 == 0) {
          p[i] += (rng() % 2 ? 5.0 : -5.0) / 16;
        } else {
          p[i] += (rng() % 2 ? 3.0 : -3.0) / 16;
          p[j] += (rng() % 2 ? 4.0 : -4.0) / 16;
        }
        if (out.size() >= 2 * D + 4 * D * (D - 1)) {  // sphere exhausted: add uniform points
          for (auto& x : p) x = dyadic01(rng);
        }
        break;
      }
      case Kind::grid: {  // a dyadic grid with spacing 1/8: cocircular / cospherical everywhere
        for (auto& x : p) x = static_cast<double>(rng() % 9) / 8;
        break;
      }
      case Kind::close_pair:
        for (auto& x : p) x = dyadic01(rng);
        if (out.size() == 1) {
          p = *out.begin();
          p[0] = p[0] + (p[0] < 0.5 ? 1 : -1) * std::ldexp(1.0, -30);
        }
        break;
      case Kind::boundary: {  // corners and faces of the domain
        for (auto& x : p) x = dyadic01(rng, 6);
        std::size_t k = rng() % (D + 1);
        for (std::size_t i = 0; i < k; ++i) p[rng() % D] = static_cast<double>(rng() % 2);
        break;
      }
    }
    add(p);
  }
  return {out.begin(), out.end()};
}

}  // namespace kmr::wellspaced::gen
