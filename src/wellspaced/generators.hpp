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

enum class Kind { uniform, clustered, line, plane, sphere, grid, close_pair, boundary,
                  // degenerate families with non-dyadic spacing (issue 11): a regular grid of
                  // ⌈n^{1/D}⌉^D points i/(m−1); n evenly spaced points i/(n−1) on the diagonal, on
                  // the axis line x_2 = .. = x_D = 1/2; the integer points of a circle (in the first
                  // two axes, the rest 1/2) and of a sphere of radius 25 (2D), 9 (3D), 5 (4D) scaled by
                  // 1/64 (exactly cocircular / cospherical), a seeded subset of n of them
                  grid_fine, collinear, axis_line, cocircular, cospherical };
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
    case Kind::grid_fine: return "grid_fine";
    case Kind::collinear: return "collinear";
    case Kind::axis_line: return "axis_line";
    case Kind::cocircular: return "cocircular";
    case Kind::cospherical: return "cospherical";
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
std::vector<Point<D>> degenerate_points(Kind kind, std::size_t n, std::uint64_t seed);

template <std::size_t D>
std::vector<Point<D>> points(Kind kind, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(kind) + 1);
  std::set<Point<D>> out;
  auto add = [&](Point<D> p) {
    for (auto& x : p) x = std::clamp(x, 0.0, 1.0);
    out.insert(p);
  };
  if (kind >= Kind::grid_fine) return degenerate_points<D>(kind, n, seed);
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
      default:
        break;
    }
    add(p);
  }
  return {out.begin(), out.end()};
}

// The degenerate families (Kind::grid_fine .. Kind::cospherical): n points, deterministic in seed.
template <std::size_t D>
std::vector<Point<D>> degenerate_points(Kind kind, std::size_t n, std::uint64_t seed) {
  std::vector<Point<D>> pts;
  if (kind == Kind::grid_fine) {
    std::size_t m = 2;
    while (std::pow(double(m), double(D)) < double(n)) ++m;
    std::array<std::size_t, D> idx{};
    for (;;) {
      Point<D> p;
      for (std::size_t i = 0; i < D; ++i) p[i] = double(idx[i]) / double(m - 1);
      pts.push_back(p);
      std::size_t i = 0;
      while (i < D && ++idx[i] == m) idx[i++] = 0;
      if (i == D) break;
    }
    std::sort(pts.begin(), pts.end());
    return pts;
  }
  if (kind == Kind::collinear || kind == Kind::axis_line) {
    for (std::size_t j = 0; j < n; ++j) {
      Point<D> p;
      for (std::size_t i = 0; i < D; ++i) p[i] = kind == Kind::collinear || i == 0 ? double(j) / double(n - 1) : 0.5;
      pts.push_back(p);
    }
    return pts;
  }
  // integer points of Σ x_i² = R² over the first k axes (k = 2 for a circle, D for a sphere)
  const std::size_t k = kind == Kind::cocircular ? 2 : D;
  const int R = k == 2 ? 25 : k == 3 ? 9 : 5;
  std::array<int, D> x{};
  for (std::size_t i = 0; i < k; ++i) x[i] = -R;
  for (;;) {
    int s = 0;
    for (std::size_t i = 0; i < k; ++i) s += x[i] * x[i];
    if (s == R * R) {
      Point<D> p;
      for (std::size_t i = 0; i < D; ++i) p[i] = 0.5 + (i < k ? x[i] / 64.0 : 0.0);
      pts.push_back(p);
    }
    std::size_t i = 0;
    while (i < k && ++x[i] > R) x[i++] = -R;
    if (i == k) break;
  }
  std::mt19937_64 rng(seed);
  std::shuffle(pts.begin(), pts.end(), rng);
  if (pts.size() > n) pts.resize(n);
  std::sort(pts.begin(), pts.end());
  return pts;
}
inline constexpr Kind kDegenerateKinds[] = {Kind::grid_fine, Kind::collinear, Kind::axis_line, Kind::cocircular,
                                            Kind::cospherical};

// Theorem 3.4.5's lower-bound input (§3.4.2, Fig. 3.10): [0,1]^D tiled by 2^{tiles_log2·D} gadget
// boxes of side h = 2^-tiles_log2. Each gadget has an input vertex at its centre and a grid of
// spacing h/face_grid on its faces (every lattice point of (h/face_grid)Z^D in [0,1]^D lying on a
// box face, shared by neighbouring boxes) — our stand-in for Hudson's face grids [43, p.79], which
// the thesis does not spell out. The dynamic vertex of a gadget is its centre + 2^-delta_log2 · e_1.
// Needs tiles_log2 + 1 < delta_log2 ≤ 50 (x inside its box, exact). All coordinates are dyadic; `input` is
// sorted, `dynamic` lists the gadgets in lexicographic order.
template <std::size_t D>
struct GadgetTiling {
  std::vector<Point<D>> input;
  std::vector<Point<D>> dynamic;
};
template <std::size_t D>
GadgetTiling<D> gadget_tiling(int tiles_log2, int delta_log2, int face_grid = 4) {
  const long per_axis = 1L << tiles_log2, g = face_grid, lattice = per_axis * g;
  const double h = std::ldexp(1.0, -tiles_log2);
  std::set<Point<D>> input;
  std::vector<Point<D>> dynamic;
  std::array<long, D> k{};
  for (;;) {  // lattice points on box faces
    bool on_face = false;
    Point<D> p;
    for (std::size_t i = 0; i < D; ++i) {
      on_face = on_face || k[i] % g == 0;
      p[i] = static_cast<double>(k[i]) * h / static_cast<double>(g);
    }
    if (on_face) input.insert(p);
    std::size_t i = 0;
    while (i < D && ++k[i] > lattice) k[i++] = 0;
    if (i == D) break;
  }
  std::array<long, D> b{};
  for (;;) {  // gadget centres and dynamic vertices
    Point<D> c;
    for (std::size_t i = 0; i < D; ++i) c[i] = (static_cast<double>(b[i]) + 0.5) * h;
    input.insert(c);
    c[0] += std::ldexp(1.0, -delta_log2);
    dynamic.push_back(c);
    std::size_t i = 0;
    while (i < D && ++b[i] == per_axis) b[i++] = 0;
    if (i == D) break;
  }
  std::sort(dynamic.begin(), dynamic.end());
  return {{input.begin(), input.end()}, dynamic};
}

// Near-duplicate pairs (issue 11): ⌈n/2⌉ seeded points (so n or n + 1 points) with 20-bit dyadic coordinates, each with a
// partner `sep` away along axis (index mod D), toward the domain's centre (the partner's coordinate
// is the double nearest to x ± sep; sep = 2^-k with k ≤ 33 keeps it exact). Pairs whose partner
// would collide with another point are skipped; sorted, no duplicates.
template <std::size_t D>
std::vector<Point<D>> near_duplicate_pairs(std::size_t n, double sep, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::set<Point<D>> out;
  for (std::size_t j = 0; out.size() < n && j < 100 * n + 10; ++j) {
    Point<D> p;
    for (auto& x : p) x = dyadic01(rng);
    Point<D> q = p;
    const std::size_t a = j % D;
    q[a] = p[a] < 0.5 ? p[a] + sep : p[a] - sep;
    if (out.count(p) || out.count(q)) continue;
    out.insert(p);
    out.insert(q);
  }
  return {out.begin(), out.end()};
}

}  // namespace kmr::wellspaced::gen
