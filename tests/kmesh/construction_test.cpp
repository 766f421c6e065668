// Fig. 4.2: the whole construction, every lemma checked by brute force (kmesh/invariants.hpp), on
// random, grid (cocircular and collinear), collinear, clustered (spread 2^30) inputs.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "exact/error.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/delaunay.hpp"
#include "kmesh/invariants.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

namespace {

std::vector<InputPoint> pts(std::initializer_list<std::pair<long long, long long>> l) {
  std::vector<InputPoint> v;
  for (auto [x, y] : l) v.push_back({Integer(x), Integer(y)});
  return v;
}

void expect_all_hold(const Mesh& m, const std::string& what) {
  for (auto& r : check_all(m)) EXPECT_TRUE(r.ok()) << what << " " << r.claim << ": " << (r.ok() ? "" : r.violations[0]);
}

}  // namespace

TEST(Construction, SinglePointIsItsOwnMesh) {
  Mesh m = construct(pts({{3, 4}}));
  EXPECT_EQ(m.size(), 1u);
  EXPECT_TRUE(m.triangles.empty());
}

TEST(Construction, DuplicatesRefused) {
  EXPECT_THROW(construct(pts({{1, 2}, {3, 4}, {1, 2}})), kmr::InputError);
}

TEST(Construction, PerturbedInCircleOnASquare) {
  // Four cocircular points: the largest id is outside the circle of the other three.
  std::vector<Point2> p{{Dyadic(0), Dyadic(0)}, {Dyadic(1), Dyadic(0)}, {Dyadic(1), Dyadic(1)}, {Dyadic(0), Dyadic(1)}};
  EXPECT_LT(perturbed_side_of_circle(p[0], 0, p[1], 1, p[2], 2, p[3], 3), 0);
  EXPECT_GT(perturbed_side_of_circle(p[0], 0, p[1], 1, p[3], 3, p[2], 2), 0);  // 3 is outside (0,1,2): 2 inside (0,1,3)
  EXPECT_GT(perturbed_side_of_circle(p[0], 3, p[1], 1, p[2], 2, p[3], 0), 0);  // id 3 at p[0]
}

TEST(Construction, L4_2_AllLemmasOnSmallInputs) {
  RecordProperty("claim", "L4.2.4 L4.2.5 L4.2.6 L4.2.9 L4.2.10 T4.2.12");
  expect_all_hold(construct(pts({{0, 0}, {1, 0}})), "two points");
  expect_all_hold(construct(pts({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {7, 0}})), "collinear");
  std::vector<InputPoint> grid;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) grid.push_back({Integer(i), Integer(j)});
  expect_all_hold(construct(grid), "grid 4x4");
  // Cocircular start: 8 points on a circle of radius 5 (Pythagorean).
  expect_all_hold(construct(pts({{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, -3}, {0, -5}, {3, -4}})), "cocircular");
}

TEST(Construction, L4_2_AllLemmasOnRandomAndClustered) {
  RecordProperty("claim", "L4.2.4 L4.2.5 L4.2.6 L4.2.9 L4.2.10 T4.2.12");
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> d(0, 1000);
  std::vector<InputPoint> in;
  for (int i = 0; i < 14; ++i) in.push_back({Integer(d(rng)), Integer(d(rng))});
  std::sort(in.begin(), in.end());
  in.erase(std::unique(in.begin(), in.end()), in.end());
  expect_all_hold(construct(in), "random 14");
  // Spread 2^30: a tight cluster and a far point.
  expect_all_hold(construct(pts({{0, 0}, {1, 0}, {0, 1}, {1LL << 30, 1LL << 29}})), "spread 2^30");
}

TEST(Construction, IndependentOfInputOrder) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> d(-50, 50);
  std::vector<InputPoint> in;
  for (int i = 0; i < 15; ++i) in.push_back({Integer(d(rng)), Integer(d(rng))});
  std::sort(in.begin(), in.end());
  in.erase(std::unique(in.begin(), in.end()), in.end());
  std::vector<InputPoint> rev(in.rbegin(), in.rend());
  std::shuffle(rev.begin(), rev.end(), rng);
  Mesh a = construct(in), b = construct(rev);
  ASSERT_EQ(a.size(), b.size());
  // Compare positions and triangles as coordinates (not ids).
  auto tri_coords = [](const Mesh& m) {
    std::set<std::vector<Dyadic>> s;
    for (auto& t : m.triangles) {
      std::vector<Dyadic> v;
      for (int i : t) v.push_back(m.spanner.position(i)[0]), v.push_back(m.spanner.position(i)[1]);
      s.insert(v);
    }
    return s;
  };
  EXPECT_EQ(tri_coords(a), tri_coords(b));
}
