// The Chapter 4 construction, and the kinetic KDS's mesh after every batch and update, judged by CGAL
// (kmesh_oracle.hpp); the oracle judged on known-bad triangulations and a set that is not well-spaced.
#include <gtest/gtest.h>

#include <random>

#include "kmesh/construction.hpp"
#include "kmesh/kds.hpp"
#include "kmesh_oracle.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
namespace ko = kmr::oracle::kmesh;

namespace {

std::vector<std::array<Dyadic, 2>> positions(const Mesh& m) {
  std::vector<std::array<Dyadic, 2>> v;
  for (std::size_t i = 0; i < m.size(); ++i) v.push_back(m.spanner.position(static_cast<int>(i)));
  return v;
}

ko::Report judge(const Mesh& m) { return ko::judge_mesh(positions(m), m.n(), m.triangles); }

std::vector<InputPoint> pts(std::initializer_list<std::pair<long long, long long>> l) {
  std::vector<InputPoint> v;
  for (auto [x, y] : l) v.push_back({Integer(x), Integer(y)});
  return v;
}

}  // namespace

TEST(KmeshOracle, SelfTestRejectsBadTriangulations) {
  // A convex quadrilateral that is not cocircular: only one diagonal is Delaunay.
  std::vector<std::array<Dyadic, 2>> q{{Dyadic(0), Dyadic(0)}, {Dyadic(4), Dyadic(0)}, {Dyadic(5), Dyadic(3)}, {Dyadic(0), Dyadic(2)}};
  std::vector<std::array<int, 3>> a{{0, 1, 2}, {0, 2, 3}}, b{{0, 1, 3}, {1, 2, 3}};
  bool oka = ko::judge_mesh(q, 4, a).ok(), okb = ko::judge_mesh(q, 4, b).ok();
  EXPECT_NE(oka, okb);  // exactly one of the two triangulations is Delaunay
  EXPECT_FALSE(ko::judge_mesh(q, 4, {{0, 1, 2}}).ok());              // too few triangles
  EXPECT_FALSE(ko::judge_mesh(q, 4, {{0, 2, 1}, {0, 3, 2}}).ok());   // clockwise
  // Two close points and a far one: the far point's Voronoi vertex is far away → not 9/2-well-spaced.
  std::vector<std::array<Dyadic, 2>> w{{Dyadic(0), Dyadic(0)}, {Dyadic(1), Dyadic(0)}, {Dyadic(0), Dyadic(100)}};
  auto r = ko::judge_mesh(w, 3, {{0, 1, 2}});
  EXPECT_FALSE(r.ok());
  EXPECT_GT(r.max_well_spaced, 4.5);
}

TEST(KmeshOracle, L4_2_3_ConstructionIsDelaunayWellSpacedSizeConforming) {
  RecordProperty("claim", "L4.2.3 L4.2.7 L4.2.8 L4.2.9 T4.2.12");
  std::vector<std::vector<InputPoint>> cases{pts({{0, 0}, {3, 0}}), pts({{0, 0}, {1, 0}, {2, 0}, {5, 0}}),
                                             pts({{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, -3}, {0, -5}, {3, -4}}),
                                             pts({{0, 0}, {1, 0}, {0, 1}, {1LL << 30, 1LL << 29}})};
  std::vector<InputPoint> grid;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) grid.push_back({Integer(2 * i), Integer(2 * j)});
  cases.push_back(grid);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> d(-300, 300);
  std::vector<InputPoint> rnd;
  for (int i = 0; i < 12; ++i) rnd.push_back({Integer(d(rng)), Integer(d(rng))});
  std::sort(rnd.begin(), rnd.end());
  rnd.erase(std::unique(rnd.begin(), rnd.end()), rnd.end());
  cases.push_back(rnd);
  double ws = 0, sz = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    Mesh m = construct(cases[c]);
    auto r = judge(m);
    EXPECT_TRUE(r.ok()) << "case " << c << ": " << (r.ok() ? "" : r.violations[0]);
    ws = std::max(ws, r.max_well_spaced);
    sz = std::max(sz, r.max_size_ratio);
  }
  RecordProperty("max_well_spaced", std::to_string(ws));
  RecordProperty("max_lfs_over_nn", std::to_string(sz));
  std::printf("measured: max |vc|/NN(v) = %.4f (claim <= 4.5), max lfs/NN_M = %.3f (L4.2.8: bounded)\n", ws, sz);
}

// §4.3 (L4.3.1 with L4.2.3, L4.2.7, L4.2.8): the kinetic KDS's mesh after the construction, every
// batch and every update, judged by CGAL at the repair time (a lattice time: the mesh is certified
// at lattice times; judge_mesh accepts either triangulation of a cocircular quadruple), over nine
// intervals of the lattices 2^-3 and the CLI's default 2^-10. Inputs: a close pass (two points one
// unit per interval each, 1 apart at 4δ), three points collinear at every time, four points
// cocircular at every time (on circles about the origin), a cluster 2^12 away; an insertion and a
// deletion in the middle of each run.
TEST(KmeshOracle, L4_3_1_KineticAndUpdatedMeshesAreDelaunayWellSpacedSizeConforming) {
  RecordProperty("claim", "L4.3.1 L4.2.3 L4.2.7 L4.2.8");
  auto mv = [](long long x, long long y, long long vx, long long vy) {
    return InputPoint{Integer(x), Integer(y), Integer(vx), Integer(vy)};
  };
  const long long far = 1LL << 12;
  const InputPoint added = mv(7, -6, 0, 1);
  double ws = 0, sz = 0;
  std::size_t judged = 0;
  for (int bits : {3, 10}) {
    const long long v = 1LL << bits;  // one unit per lattice interval
    std::vector<std::vector<InputPoint>> cases{
        {mv(-4, 0, v, 0), mv(4, 1, -v, 0), mv(0, 9, 0, 0)},                   // 1 apart at the 4th interval's end
        {mv(0, 0, 0, 1), mv(2, 0, 0, 0), mv(4, 0, 0, -1)},                     // collinear at every t
        {mv(5, 0, 0, 1), mv(0, 5, -1, 0), mv(-5, 0, 0, -1), mv(0, -5, 1, 0)},  // cocircular at every t
        {mv(0, 0, 0, 0), mv(1, 1, 0, 0), mv(far, 0, -2, 1), mv(far + 3, 2, 0, 0)}};
    for (std::size_t c = 0; c < cases.size(); ++c) {
      KineticMesh kds(cases[c], bits);
      auto judge_now = [&](const std::string& when) {
        auto r = judge(kds.mesh());
        ++judged;
        EXPECT_TRUE(r.ok()) << "case " << c << ", lattice 2^-" << bits << ", " << when << " at "
                            << kds.now().to_decimal() << ": " << (r.ok() ? "" : r.violations[0]);
        ws = std::max(ws, r.max_well_spaced);
        sz = std::max(sz, r.max_size_ratio);
      };
      judge_now("construction");
      auto after = [&](const Batch&) { judge_now("batch"); };
      const Dyadic step(1, -bits);  // three lattice intervals, an insertion, three, a deletion, three
      kds.run_until(step * Dyadic(3), after);
      kds.insert(added);
      judge_now("insertion");
      kds.run_until(step * Dyadic(6), after);
      kds.erase(added);
      judge_now("deletion");
      kds.run_until(step * Dyadic(9), after);
      EXPECT_GT(kds.batches().size(), 3u) << "case " << c << ": the run must have kinetic batches";
    }
  }
  RecordProperty("meshes_judged", std::to_string(judged));
  std::printf("kinetic: %zu meshes judged; max |vc|/NN(v) = %.4f (claim <= 4.5), max lfs/NN_M = %.3f\n", judged, ws,
              sz);
}
