// Fig. 2.4's first ratio as the audit measures it (`timings()` in src/audit/hull_checks.cpp), outside
// the audit, for profiles: n moving points with §2.4's motions (Bℓ = 20, Bv = 8, seed 20121 + 7n),
// the exact static hull of their starting positions and the initial kinetic run (a MotionSimulator
// at δ = 2^-10 until 2^27 and a KineticHull), R times each, alternately. The two runs are the
// function `static_run` and the KineticHull constructor (callgrind's --toggle-collect). Prints one
// line per size: best wall times and their ratio.
// Usage: initial_run_probe [--n 20,40] [--reps R] [--seed S]
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hull/hull.hpp"
#include "hull/kinetic_hull.hpp"
#include "kinetic/trajectory.hpp"

namespace {
using namespace kmr;
[[gnu::noinline]] std::size_t static_run(const std::vector<hull::Point3d>& pts) { return hull::convex_hull(pts).facets.size(); }
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
// The audit times the KineticHull constructor only (not the simulator's construction nor the
// hull's destruction); so does this, and callgrind can toggle on the constructor's symbol.
[[gnu::noinline]] std::size_t initial_kinetic_run(const std::vector<hull::MovingPoint>& moving, std::uint64_t seed,
                                                  double& seconds) {
  kinetic::MotionSimulator sim(10, exact::Dyadic::pow2(27));
  auto t0 = std::chrono::steady_clock::now();
  hull::KineticHull kh(moving, sim, seed);
  seconds = since(t0);
  return kh.live_certificates();
}
}  // namespace

int main(int argc, char** argv) {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // as kmr's main (src/cli/main.cpp)
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  std::vector<int> sizes{20, 40};
  int reps = 5;
  std::uint64_t seed = 20121;  // the audit's default seed
  for (int i = 1; i < argc; i += 2) {
    std::string a = argv[i];
    if ((a != "--n" && a != "--reps" && a != "--seed") || i + 1 >= argc) {
      std::fprintf(stderr, "usage: initial_run_probe [--n 20,40] [--reps R] [--seed S] (bad or incomplete option '%s')\n", a.c_str());
      return 2;
    }
    std::string v = argv[i + 1];
    if (a == "--n") {
      sizes.clear();
      std::stringstream ss(v);
      for (std::string s; std::getline(ss, s, ',');) sizes.push_back(std::stoi(s));
    } else if (a == "--reps") {
      reps = std::stoi(v);
    } else if (a == "--seed") {
      seed = std::stoull(v);
    }
  }
  for (int n : sizes) {
    std::mt19937_64 rng(seed + 7 * n);
    const auto moving = kinetic::random_linear_trajectories<3>(static_cast<std::size_t>(n), rng, {20, 8});
    std::vector<hull::Point3d> pts;
    for (const auto& q : moving)
      pts.push_back({q[0].is_zero() ? 0.0 : q[0][0].convert_to<double>(), q[1].is_zero() ? 0.0 : q[1][0].convert_to<double>(),
                     q[2].is_zero() ? 0.0 : q[2][0].convert_to<double>()});
    double best_static = 1e300, best_initial = 1e300;
    std::size_t certificates = 0;
    for (int k = 0; k < reps; ++k) {
      auto t0 = std::chrono::steady_clock::now();
      static_run(pts);
      best_static = std::min(best_static, since(t0));
      double seconds = 0;
      certificates = initial_kinetic_run(moving, seed + 7 * n, seconds);
      best_initial = std::min(best_initial, seconds);
    }
    std::printf("n = %d: certificates %zu, static %.2f us, initial %.2f us, initial / static %.2f\n", n, certificates,
                best_static * 1e6, best_initial * 1e6, best_initial / best_static);
  }
}
