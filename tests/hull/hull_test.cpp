// Unit tests of the static hull (§2.2) against hand-derived hulls and the brute-force judge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "brute_hull.hpp"
#include "exact/error.hpp"
#include "hull/hull.hpp"
#include "hull/kernel.hpp"
#include "hull/priorities.hpp"
#include "hull/xyz_file.hpp"

using kmr::hull::Arithmetic;
using kmr::hull::convex_hull;
using kmr::hull::Point3d;
using Facets = std::vector<std::array<int, 3>>;

namespace {

void expect_judged(const std::vector<Point3d>& pts, Arithmetic a = Arithmetic::exact, std::uint64_t seed = 2012) {
  auto h = convex_hull(pts, a, seed);
  EXPECT_EQ(hull_judge::check_hull(hull_judge::judge_hull(pts), h.vertices, h.facets), "");
}

std::vector<Point3d> cube_with_extras() {
  return {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}, {0, 0, 2}, {2, 0, 2}, {0, 2, 2}, {2, 2, 2},
          {1, 1, 1},                                  // interior
          {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {2, 1, 1},  // face centres
          {1, 0, 0}, {0, 1, 0}};                      // edge midpoints
}

}  // namespace

TEST(Hull, C2_2_static_hull_correct_Tetrahedron) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  // Hand-derived: outward normals −z, −y, −x and (1,1,1), counter-clockwise from outside.
  auto h = convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_EQ(h.vertices, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(h.facets, (Facets{{0, 1, 3}, {0, 2, 1}, {0, 3, 2}, {1, 2, 3}}));
}

TEST(Hull, C2_2_static_hull_correct_CubeWithFaceEdgeAndInteriorPoints) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  // Hand-derived: only the 8 corners are vertices; each square is a fan from its lexicographically
  // smallest corner, counter-clockwise from outside (e.g. z = 0, normal −z: [0,2,3], [0,3,1]).
  auto pts = cube_with_extras();
  Facets want{{0, 1, 5}, {0, 2, 3}, {0, 3, 1}, {0, 4, 6}, {0, 5, 4}, {0, 6, 2},
              {1, 3, 7}, {1, 7, 5}, {2, 6, 7}, {2, 7, 3}, {4, 5, 7}, {4, 7, 6}};
  for (std::uint64_t seed : {1, 2, 3, 4, 5, 6, 7, 8, 2012}) {
    auto h = convex_hull(pts, Arithmetic::exact, seed);
    EXPECT_EQ(h.vertices, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7})) << "seed " << seed;
    EXPECT_EQ(h.facets, want) << "seed " << seed;
  }
}

TEST(Hull, C2_2_static_hull_correct_DuplicatesKeepLowestIndex) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  // 3 and 5 repeat 0 and 1; 6 repeats 4 with a higher index; the tetrahedron is 0,1,2,4.
  std::vector<Point3d> pts{{1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 0}, {0, 0, 1}};
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    auto h = convex_hull(pts, Arithmetic::exact, seed);
    EXPECT_EQ(h.vertices, (std::vector<int>{0, 1, 2, 4})) << "seed " << seed;
    EXPECT_EQ(h.facets, (Facets{{0, 1, 2}, {0, 2, 4}, {0, 4, 1}, {1, 4, 2}})) << "seed " << seed;
  }
}

TEST(Hull, C2_2_static_hull_correct_CollinearOnEdgeNeverAVertex) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  // Points 4..9 on the edge 0–1 of a tetrahedron (some beyond the middle, in every order).
  std::vector<Point3d> pts{{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}};
  for (double x : {4.0, 1.0, 7.0, 2.0, 6.0, 3.0}) pts.push_back({x, 0, 0});
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    auto h = convex_hull(pts, Arithmetic::exact, seed);
    EXPECT_EQ(h.vertices, (std::vector<int>{0, 1, 2, 3})) << "seed " << seed;
    expect_judged(pts, Arithmetic::exact, seed);
  }
}

TEST(Hull, C2_2_static_hull_correct_CoplanarGridOnAFace) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  std::vector<Point3d> pts;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y) pts.push_back({double(x), double(y), 0});
  pts.push_back({2, 2, 3});  // apex: a square pyramid, 25 points on its base
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    auto h = convex_hull(pts, Arithmetic::exact, seed);
    EXPECT_EQ(h.vertices, (std::vector<int>{0, 4, 20, 24, 25})) << "seed " << seed;
    EXPECT_EQ(h.facets.size(), 6u);
    expect_judged(pts, Arithmetic::exact, seed);
  }
}

TEST(Hull, C2_2_static_hull_correct_CosphericalIntegerPoints) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  std::vector<Point3d> pts;  // all integer points with x² + y² + z² = 9 (an octahedron-like set)
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z)
        if (x * x + y * y + z * z == 9) pts.push_back({double(x), double(y), double(z)});
  for (std::uint64_t seed = 1; seed <= 3; ++seed) expect_judged(pts, Arithmetic::exact, seed);
}

TEST(Hull, C2_2_static_hull_correct_RandomAgainstBruteForce) {
  RecordProperty("claim", "C2.2-static-hull-correct");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int rep = 0; rep < 10; ++rep) {
    std::vector<Point3d> pts(18);
    for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
    expect_judged(pts);
    expect_judged(pts, Arithmetic::floating);  // generic input: the float baseline agrees
  }
}

TEST(Hull, HugeSpreadBeyondTheFilterRange) {
  // Coordinates of 2^600 and 2^-600 are outside the filter's safe range: all decisions exact.
  std::vector<Point3d> pts{{0, 0, 0}, {std::ldexp(1, 600), 0, 0}, {0, std::ldexp(1, 600), 0}, {0, 0, std::ldexp(1, 600)},
                           {std::ldexp(1, -600), std::ldexp(1, -600), std::ldexp(1, -600)},
                           {std::ldexp(1, 599), std::ldexp(1, 599), 0}, {-std::ldexp(1, -600), 0, 0}};
  auto h = convex_hull(pts);
  EXPECT_GT(h.stats.exact_fallbacks, 0u);
  expect_judged(pts);
}

TEST(Hull, FewerThanFourAffinelyIndependentPointsIsAnInputError) {
  EXPECT_THROW(convex_hull({}), kmr::InputError);
  EXPECT_THROW(convex_hull({{1, 2, 3}, {1, 2, 3}}), kmr::InputError);
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}}), kmr::InputError);
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 7, 0}, {3, 3, 0}}), kmr::InputError);
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}}), kmr::InputError);
}

TEST(Hull, ReadXyzFile) {
  std::istringstream in("# comment\n1 2 3\n\n  -0.5 1e2 +7  # trailing\n0.1 0 0\n");
  auto pts = kmr::hull::read_xyz(in, "f.xyz");
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[1], (Point3d{-0.5, 100, 7}));
  EXPECT_EQ(pts[2][0], 0.1);  // the nearest double
  auto refuse = [](const std::string& text, const std::string& what) {
    std::istringstream in(text);
    try {
      kmr::hull::read_xyz(in, "f.xyz");
      ADD_FAILURE() << "accepted " << text;
    } catch (const kmr::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refuse("1 2 3\n1 2\n", "f.xyz:2");
  refuse("1 2 3 4\n", "f.xyz:1");
  refuse("1 2 inf\n", "'inf'");
  refuse("1 2 nan\n", "'nan'");
  refuse("1 2 1e400\n", "not a finite double: '1e400'");
  refuse("0x10 2 3\n", "'0x10'");
}

// The centre tests (filtered, with the centre rounded to a double) equal the exact orientation
// with the Dyadic centroid, on generic doubles and on grids where many tests are exactly zero.
TEST(HullKernel, CentreTestsAreExact) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int family = 0; family < 3; ++family) {
    std::vector<Point3d> pts;
    for (int i = 0; i < 40; ++i) {
      if (family == 0) pts.push_back({u(rng), u(rng), u(rng)});
      else if (family == 1) pts.push_back({double(rng() % 5), double(rng() % 5), double(rng() % 5)});
      else pts.push_back({0.1 * double(rng() % 5), 0.1 * double(rng() % 5), 1e-3 * double(rng() % 5)});
    }
    pts[0] = {0, 0, 0}, pts[1] = {1, 0, 0}, pts[2] = {0, 1, 0}, pts[3] = {0.3, 0.7, 0.9};
    kmr::hull::ExactKernel k(pts);
    k.set_centre(0, 1, 2, 3);
    using kmr::exact::Dyadic;
    kmr::geometry::Point<3, Dyadic> c;
    for (int j = 0; j < 3; ++j)
      c[j] = (Dyadic::from_double(pts[0][j]) + Dyadic::from_double(pts[1][j]) + Dyadic::from_double(pts[2][j]) +
              Dyadic::from_double(pts[3][j])) * Dyadic(kmr::exact::Integer(1), -2);
    int zeros = 0;
    for (int rep = 0; rep < 3000; ++rep) {
      int a = int(rng() % 40), x = int(rng() % 40), y = int(rng() % 40);
      auto d = [&](int i) { return kmr::geometry::to_dyadic(pts[i]); };
      int want_before = kmr::geometry::orientation(d(y), d(a), c, d(x));
      int want_after = kmr::geometry::orientation(d(a), d(y), c, d(x));
      zeros += want_before == 0;
      auto frame = k.apex_frame(a, x);
      ASSERT_EQ(frame.side_before(y), want_before) << family << " " << rep;
      ASSERT_EQ(frame.side_after(y), want_after) << family << " " << rep;
      ASSERT_EQ(k.centre_side(y, a, x), want_before) << family << " " << rep;
    }
    if (family == 1) {
      EXPECT_GT(zeros, 100);
    }
  }
}

// The radix-sorted priority order equals std::sort by (priority decreasing, index increasing),
// ties included.
TEST(HullPriorities, OrderIsDecreasingPriorityThenIndex) {
  std::mt19937_64 rng(3);
  for (int n : {0, 1, 7, 1000, 5000}) {
    auto pr = kmr::hull::random_priorities(n, 42 + n);
    for (int i = 0; i < n; i += 3) pr[i] = pr[(i * 7) % n] & (rng() % 2 ? ~0ULL : 0xffff0000ffffULL);  // ties, shared bytes
    std::vector<int> want(n);
    for (int i = 0; i < n; ++i) want[i] = i;
    std::sort(want.begin(), want.end(), [&](int a, int b) { return pr[a] != pr[b] ? pr[a] > pr[b] : a < b; });
    EXPECT_EQ(kmr::hull::priority_order(pr), want) << n;
  }
}
