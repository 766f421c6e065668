// kmr_bench_kmesh [n ...]: the Chapter 4 construction (Fig. 4.2) on n distinct uniform integer points
// in [0, 2^16]^2 (seeded): wall time, |M|/n, operations ÷ (n log2 Δ) (T4.2.12), and the output size
// of Chapter 3's StableWS (ρ = √2, default β) and CGAL Mesh_2 (radius-edge bound √2, the box
// [0, 2^16]^2 as constraints) on the same points, scaled to [0,1]^2. The Chapter 4 mesh covers a
// region about 32× the input's diameter (its outermost satellites are at rank Λ+4), so its count
// inside the input box is printed too. Qualities differ (9/2-well-spaced vs ρ = √2), so the sizes
// are a report, not a like-for-like ratio. ins_diff: Steiner vertices that differ between the mesh
// and the from-scratch mesh after inserting one more random point (stability of the construction). The machine may be loaded: times are best of `reps`.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>
#include <vector>

#include "kmesh/construction.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace {

using K = CGAL::Epick;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
using Clock = std::chrono::steady_clock;
constexpr int kBits = 16;

std::size_t mesh2(const std::vector<std::array<double, 2>>& in) {
  CDT cdt;
  const CDT::Point c[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) cdt.insert_constraint(c[i], c[(i + 1) % 4]);
  for (auto& p : in) cdt.insert(CDT::Point(p[0], p[1]));
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, 0));
  return cdt.number_of_vertices();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> ns;
  for (int i = 1; i < argc; ++i) ns.push_back(std::strtoull(argv[i], nullptr, 10));
  if (ns.empty()) ns = {8, 16, 32, 64};
  std::printf("%6s %9s %8s %8s %10s %14s %10s %10s %9s %11s\n", "n", "kmesh_s", "|M|", "|M|/n", "in_box", "ops/(n lgD)",
              "stablews", "mesh2", "ins_diff", "diff/lgD");
  for (std::size_t n : ns) {
    std::mt19937_64 rng(20121 + n);
    std::uniform_int_distribution<int> d(0, 1 << kBits);
    std::vector<kmr::kmesh::InputPoint> in;
    while (in.size() < n) {
      kmr::kmesh::InputPoint p{kmr::exact::Integer(d(rng)), kmr::exact::Integer(d(rng))};
      if (std::find(in.begin(), in.end(), p) == in.end()) in.push_back(p);
    }
    double dmax = 0, dmin = INFINITY;
    std::vector<std::array<double, 2>> unit;
    for (auto& p : in) unit.push_back({std::ldexp(p.x.convert_to<double>(), -kBits), std::ldexp(p.y.convert_to<double>(), -kBits)});
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        double e = std::hypot(unit[i][0] - unit[j][0], unit[i][1] - unit[j][1]);
        dmax = std::max(dmax, e), dmin = std::min(dmin, e);
      }
    auto t0 = Clock::now();
    kmr::kmesh::Mesh m = kmr::kmesh::construct(in);
    double secs = std::chrono::duration<double>(Clock::now() - t0).count();
    std::size_t inbox = 0;
    for (std::size_t v = 0; v < m.size(); ++v) {
      double x = m.spanner.position(int(v))[0].to_double() / double(kmr::kmesh::kScale);
      double y = m.spanner.position(int(v))[1].to_double() / double(kmr::kmesh::kScale);
      inbox += x >= 0 && y >= 0 && x <= (1 << kBits) && y <= (1 << kBits);
    }
    double ops = double(m.ops_spanner + m.ops_convert + m.ops_delaunay) / (n * std::log2(dmax / dmin));
    std::vector<kmr::wellspaced::Point<2>> wp;
    for (auto& p : unit) wp.push_back({p[0], p[1]});
    kmr::wellspaced::Params params;
    params.rho = std::sqrt(2.0);
    kmr::wellspaced::WellSpacedSet<2> ws(wp, params);
    std::size_t wsn = ws.vertices().size();
    std::size_t cg = mesh2(unit);
    // Stability of the construction itself: insert one more point and rebuild from scratch; the
    // Steiner vertices that differ (by position) are the least an update must change (T4.3.7's
    // premise; the update of Fig. 4.5 is not implemented).
    kmr::kmesh::InputPoint extra{kmr::exact::Integer(d(rng)), kmr::exact::Integer(d(rng))};
    while (std::find(in.begin(), in.end(), extra) != in.end()) extra.x += 1;
    auto in2 = in;
    in2.push_back(extra);
    kmr::kmesh::Mesh m2 = kmr::kmesh::construct(in2);
    auto steiner = [](const kmr::kmesh::Mesh& x) {
      std::set<std::pair<kmr::exact::Dyadic, kmr::exact::Dyadic>> s;
      for (std::size_t v = 0; v < x.size(); ++v)
        if (x.info[v].steiner) s.insert({x.spanner.position(int(v))[0], x.spanner.position(int(v))[1]});
      return s;
    };
    auto a = steiner(m), b = steiner(m2);
    std::size_t common = 0;
    for (auto& p : a) common += b.count(p);
    std::size_t changed = a.size() + b.size() - 2 * common;
    std::printf("%6zu %9.3f %8zu %8.1f %10zu %14.4g %10zu %10zu %9zu %11.3g\n", n, secs, m.size(), double(m.size()) / n, inbox, ops,
                wsn, cg, changed, changed / std::log2(dmax / dmin));
    std::fflush(stdout);
  }
  return 0;
}
