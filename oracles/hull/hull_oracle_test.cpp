// kmr::hull's static hull (§2.2) judged by CGAL convex_hull_3 (exact predicates) on real
// (uniform cube, ball, sphere) and degenerate inputs (grids, coplanar, collinear, cospherical,
// duplicates, near-duplicates).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cgal_hull.hpp"
#include "hull/hull.hpp"

using kmr::hull::Point3d;

namespace {

void judge(const std::vector<Point3d>& pts, const std::string& what) {
  for (auto a : {kmr::hull::Arithmetic::exact}) {
    auto h = kmr::hull::convex_hull(pts, a, 77);
    EXPECT_EQ(kmr_oracle::compare_with_cgal(pts, h.vertices, h.facets), "") << what;
  }
}

}  // namespace

TEST(HullOracle, C2_2_static_hull_correct_RealInputs) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n : {100, 2000}) {
    std::vector<Point3d> cube, ball, sphere;
    while (static_cast<int>(ball.size()) < n) {
      Point3d p{u(rng), u(rng), u(rng)};
      if (static_cast<int>(cube.size()) < n) cube.push_back(p);
      double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      if (r <= 1 && r > 0) {
        ball.push_back(p);
        sphere.push_back({p[0] / r, p[1] / r, p[2] / r});
      }
    }
    judge(cube, "cube n=" + std::to_string(n));
    judge(ball, "ball n=" + std::to_string(n));
    judge(sphere, "sphere n=" + std::to_string(n));
  }
}

TEST(HullOracle, C2_2_static_hull_correct_DegenerateInputs) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  std::vector<Point3d> grid, coplanar, collinear, cosph, dups, near;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 6; ++z) grid.push_back({double(x), double(y), double(z)});
  judge(grid, "grid 6^3");
  for (int x = -4; x <= 4; ++x)
    for (int y = -4; y <= 4; ++y) coplanar.push_back({double(x), double(y), 0});
  coplanar.push_back({0, 0, 5});
  coplanar.push_back({1, 1, -5});
  judge(coplanar, "coplanar bipyramid");
  for (int i = 0; i <= 20; ++i) collinear.push_back({double(i), 0, 0}), collinear.push_back({0, double(i), 0});
  collinear.push_back({0, 0, 20});
  collinear.push_back({7, 7, 7});
  judge(collinear, "collinear edges");
  for (int x = -7; x <= 7; ++x)
    for (int y = -7; y <= 7; ++y)
      for (int z = -7; z <= 7; ++z)
        if (x * x + y * y + z * z == 49) cosph.push_back({double(x), double(y), double(z)});
  judge(cosph, "cospherical r=7");
  std::mt19937_64 rng(3);
  for (int i = 0; i < 300; ++i) dups.push_back(grid[rng() % 40]);
  judge(dups, "duplicates");
  for (int i = 0; i < 200; ++i) {
    Point3d p = grid[rng() % grid.size()];
    p[rng() % 3] = std::nextafter(p[rng() % 3], (rng() & 1) ? 100.0 : -100.0);
    near.push_back(p);
    near.push_back(grid[rng() % grid.size()]);
  }
  judge(near, "near-duplicates");
}
