// Generators of ws_generators.hpp.
#include "ws_generators.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

namespace kmr::oracle::ws::gen {

std::string name(Kind k) {
  switch (k) {
    case Kind::Uniform: return "uniform";
    case Kind::Clustered: return "clustered";
    case Kind::Line: return "line";
    case Kind::Grid: return "grid";
    case Kind::ClosePairs: return "closepairs";
    case Kind::Boundary: return "boundary";
  }
  return "?";
}

namespace {
// Dyadic grid of 2^-20 so that sums stay exact and points are well inside double precision.
double snap(double x) { return std::clamp(std::ldexp(std::round(std::ldexp(x, 20)), -20), 0.0, 1.0); }
}  // namespace

template <std::size_t D>
std::vector<DPoint<D>> make(Kind kind, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(kind) + 1);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<DPoint<D>> pts;
  auto uniform_pt = [&] {
    DPoint<D> p;
    for (auto& x : p) x = snap(U(rng));
    return p;
  };
  switch (kind) {
    case Kind::Uniform:
      for (std::size_t i = 0; i < n; ++i) pts.push_back(uniform_pt());
      break;
    case Kind::Clustered: {  // a few tight clusters (radius 2^-12) plus sparse background
      std::size_t clusters = std::max<std::size_t>(1, n / 20);
      std::vector<DPoint<D>> centers;
      for (std::size_t c = 0; c < clusters; ++c) centers.push_back(uniform_pt());
      std::normal_distribution<double> N(0.0, std::ldexp(1.0, -12));
      for (std::size_t i = 0; i < n; ++i) {
        if (i % 5 == 0) { pts.push_back(uniform_pt()); continue; }
        DPoint<D> p = centers[i % clusters];
        for (auto& x : p) x = snap(x + N(rng));
        pts.push_back(p);
      }
      break;
    }
    case Kind::Line:  // on the segment x_0 = x_1 = ... (diagonal), collinear
      for (std::size_t i = 0; i < n; ++i) {
        double t = snap(U(rng));
        DPoint<D> p;
        p.fill(t);
        pts.push_back(p);
      }
      break;
    case Kind::Grid: {  // k^D grid with dyadic spacing, interior and boundary
      std::size_t k = 2;
      while (std::pow(double(k + 1), double(D)) <= double(n)) ++k;
      std::size_t total = 1;
      for (std::size_t d = 0; d < D; ++d) total *= k;
      for (std::size_t i = 0; i < total; ++i) {
        DPoint<D> p;
        std::size_t r = i;
        for (std::size_t d = 0; d < D; ++d) { p[d] = snap(double(r % k) / double(k - 1)); r /= k; }
        pts.push_back(p);
      }
      break;
    }
    case Kind::ClosePairs: {  // a few pairs 2^-30 apart (spread Δ ≈ 2^30) among uniform points
      const std::size_t pairs = std::max<std::size_t>(1, n / 40);
      for (std::size_t i = 0; i < pairs; ++i) {
        DPoint<D> p = uniform_pt();
        for (auto& x : p) x = std::min(x, 0.5);
        DPoint<D> q = p;
        q[0] += std::ldexp(1.0, -30);
        pts.push_back(p);
        pts.push_back(q);
      }
      while (pts.size() < n) pts.push_back(uniform_pt());
      break;
    }
    case Kind::Boundary: {  // all 2^D corners plus points on faces of the domain
      for (std::size_t m = 0; m < (std::size_t(1) << D); ++m) {
        DPoint<D> p;
        for (std::size_t d = 0; d < D; ++d) p[d] = double((m >> d) & 1);
        pts.push_back(p);
      }
      for (std::size_t i = pts.size(); i < n; ++i) {
        DPoint<D> p = uniform_pt();
        p[i % D] = (i / D) % 2 ? 1.0 : 0.0;
        pts.push_back(p);
      }
      break;
    }
  }
  // Remove duplicates, keep the generated order otherwise.
  std::set<DPoint<D>> seen;
  std::vector<DPoint<D>> out;
  for (const auto& p : pts)
    if (seen.insert(p).second) out.push_back(p);
  return out;
}

template std::vector<DPoint<2>> make<2>(Kind, std::size_t, std::uint64_t);
template std::vector<DPoint<3>> make<3>(Kind, std::size_t, std::uint64_t);
template std::vector<DPoint<4>> make<4>(Kind, std::size_t, std::uint64_t);

}  // namespace kmr::oracle::ws::gen
