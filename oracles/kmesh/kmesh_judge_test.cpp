// The Chapter 4 construction judged by CGAL (kmesh_oracle.hpp), and the oracle judged on known-bad
// triangulations and a set that is not well-spaced.
#include <gtest/gtest.h>

#include <random>

#include "kmesh/construction.hpp"
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
