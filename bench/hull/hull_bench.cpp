// Fig. 2.2 (static algorithms compared) and the static ratio of Fig. 2.4 (exact ÷ float):
// kmr::hull exact vs CGAL convex_hull_3 (Epick: exact predicates) vs qhull (libqhull_r, "Qt"), and
// kmr::hull float, on the same points, uniform in a cube, in a ball, on a sphere. Side by side in
// one run: the four contenders interleaved, best of R repetitions (at least 15 at n ≤ 10^4, 5 at
// n ≤ 10^5); the answers (number of hull
// vertices) are checked to agree before any timing is reported.
// Usage: hull_bench [--n N,N,...] [--reps R] [--dist cube|ball|sphere|all]   (default: n = 10000)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hull/hull.hpp"

using kmr::hull::Point3d;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

std::vector<Point3d> generate(const std::string& dist, int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3d> pts;
  while (static_cast<int>(pts.size()) < n) {
    Point3d p{u(rng), u(rng), u(rng)};
    double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (dist == "cube") pts.push_back(p);
    else if (r <= 1 && r > 1e-3) pts.push_back(dist == "ball" ? p : Point3d{p[0] / r, p[1] / r, p[2] / r});
  }
  return pts;
}

std::size_t run_cgal(const std::vector<Point3d>& pts) {
  std::vector<K::Point_3> cp;
  cp.reserve(pts.size());
  for (auto& p : pts) cp.emplace_back(p[0], p[1], p[2]);
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::convex_hull_3(cp.begin(), cp.end(), mesh);
  return mesh.number_of_vertices();
}

std::size_t run_qhull(const std::vector<Point3d>& pts) {
  std::vector<coordT> c;
  c.reserve(3 * pts.size());
  for (auto& p : pts) c.insert(c.end(), p.begin(), p.end());
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, stderr);
  char options[] = "qhull Qt";
  int code = qh_new_qhull(qh, 3, static_cast<int>(pts.size()), c.data(), False, options, nullptr, stderr);
  std::size_t v = code == 0 ? static_cast<std::size_t>(qh->num_vertices) : 0;
  qh_freeqhull(qh, !qh_ALL);
  int curlong, totlong;
  qh_memfreeshort(qh, &curlong, &totlong);
  return v;
}

template <class F>
double seconds(F&& f) {
  auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{10000};
  int reps = 3;
  std::vector<std::string> dists{"cube", "ball", "sphere"};
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string a = argv[i], v = argv[i + 1];
    if (a == "--n") {
      sizes.clear();
      std::stringstream ss(v);
      for (std::string t; std::getline(ss, t, ',');) sizes.push_back(std::stoi(t));
    } else if (a == "--reps") {
      reps = std::stoi(v);
    } else if (a == "--dist") {
      if (v != "all") dists = {v};
    } else {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  std::printf("%-7s %8s %8s %10s %10s %10s %10s %9s %9s %9s %9s\n", "dist", "n", "hull_v", "exact_s", "cgal_s",
              "qhull_s", "float_s", "ex/cgal", "ex/qhull", "ex/float", "fallbk%");
  int failures = 0;
  for (const auto& dist : dists)
    for (int n : sizes) {
      auto pts = generate(dist, n, 1000 + n);
      // answers first
      auto ex = kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::exact);
      std::size_t ours = ex.vertices.size(), cg = run_cgal(pts), qh = run_qhull(pts);
      std::size_t fl = kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::floating).vertices.size();
      if (ours != cg || ours != qh || ours != fl) {
        std::printf("%-7s %8d MISMATCH: exact %zu, CGAL %zu, qhull %zu, float %zu\n", dist.c_str(), n, ours, cg, qh, fl);
        ++failures;
        continue;
      }
      double best[4] = {1e300, 1e300, 1e300, 1e300};
      // at least R repetitions; more for millisecond-scale runs, where a loaded machine is noisiest
      const int runs = std::max(reps, n <= 10000 ? 15 : n <= 100000 ? 5 : reps);
      for (int r = 0; r < runs; ++r) {  // interleaved
        best[0] = std::min(best[0], seconds([&] { kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::exact); }));
        best[1] = std::min(best[1], seconds([&] { run_cgal(pts); }));
        best[2] = std::min(best[2], seconds([&] { run_qhull(pts); }));
        best[3] = std::min(best[3], seconds([&] { kmr::hull::convex_hull(pts, kmr::hull::Arithmetic::floating); }));
      }
      std::printf("%-7s %8d %8zu %10.4f %10.4f %10.4f %10.4f %9.2f %9.2f %9.2f %9.4f\n", dist.c_str(), n, ours, best[0],
                  best[1], best[2], best[3], best[0] / best[1], best[0] / best[2], best[0] / best[3],
                  100.0 * double(ex.stats.exact_fallbacks) / double(ex.stats.orientation_tests));
    }
  return failures ? 1 : 0;
}
