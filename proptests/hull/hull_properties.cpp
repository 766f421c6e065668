// Properties of the static hull (§2.2) on random and degenerate inputs, judged by the brute-force
// exact hull of tests/hull/brute_hull.hpp (no code shared with src/hull).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "brute_hull.hpp"
#include "exact/error.hpp"
#include "hull/hull.hpp"

using kmr::hull::Arithmetic;
using kmr::hull::convex_hull;
using kmr::hull::Point3d;

namespace {

// Point sets of 4..16 points from one of several degenerate families; every family mixes in a
// few generic points so that most sets span 3D.
rc::Gen<std::vector<Point3d>> point_sets() {
  return rc::gen::exec([] {
    int family = *rc::gen::inRange(0, 8);
    int n = *rc::gen::inRange(4, 17);
    std::vector<Point3d> pts;
    auto small = [] { return double(*rc::gen::inRange(-3, 4)); };
    for (int i = 0; i < n; ++i) {
      switch (family) {
        case 0:  // a small grid: many coplanar, collinear, duplicate points
          pts.push_back({small(), small(), small()});
          break;
        case 1:  // mostly on the plane z = 0, a few off it
          pts.push_back({small(), small(), i % 5 == 4 ? small() : 0.0});
          break;
        case 2:  // mostly on two lines
          if (i % 4 == 3) pts.push_back({small(), small(), small()});
          else if (i % 2) pts.push_back({small(), 0, 0});
          else pts.push_back({0, small(), 2});
          break;
        case 3: {  // cospherical: integer points on x² + y² + z² = 9 or 25
          static const std::vector<Point3d> sphere = [] {
            std::vector<Point3d> s;
            for (int x = -5; x <= 5; ++x)
              for (int y = -5; y <= 5; ++y)
                for (int z = -5; z <= 5; ++z)
                  if (x * x + y * y + z * z == 25) s.push_back({double(x), double(y), double(z)});
            return s;
          }();
          pts.push_back(sphere[*rc::gen::inRange<std::size_t>(0, sphere.size())]);
          break;
        }
        case 4: {  // near-duplicates: a point and its neighbours one ulp away
          Point3d p{small(), small(), small()};
          if (i > 0 && *rc::gen::inRange(0, 2)) {
            p = pts[*rc::gen::inRange<std::size_t>(0, pts.size())];
            int k = *rc::gen::inRange(0, 3);
            p[k] = std::nextafter(p[k], *rc::gen::arbitrary<bool>() ? 10.0 : -10.0);
          }
          pts.push_back(p);
          break;
        }
        case 5: {  // huge spread: scales from 2^-700 to 2^700 (in and beyond the filter's range)
          int e = *rc::gen::element(-700, -300, -200, 0, 0, 0, 200, 300, 700);
          pts.push_back({std::ldexp(small(), e), std::ldexp(small(), e), std::ldexp(small(), e)});
          break;
        }
        case 6:  // duplicates of a few points
          if (i >= 4 && *rc::gen::inRange(0, 2)) pts.push_back(pts[*rc::gen::inRange(0, i)]);
          else pts.push_back({small(), small(), small()});
          break;
        default:  // generic doubles
          pts.push_back({*rc::gen::inRange(-1000000, 1000000) * 1e-6, *rc::gen::inRange(-1000000, 1000000) * 1e-6,
                         *rc::gen::inRange(-1000000, 1000000) * 1e-6});
      }
    }
    return pts;
  });
}

// The output as coordinates: facets as triples of points, rotated to their smallest point.
std::vector<std::array<Point3d, 3>> geometric(const std::vector<Point3d>& pts, const kmr::hull::Hull& h) {
  std::vector<std::array<Point3d, 3>> out;
  for (auto t : h.facets) {
    std::array<Point3d, 3> f{pts[t[0]], pts[t[1]], pts[t[2]]};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

RC_GTEST_PROP(HullProperties, C2_2_static_hull_correct_MatchesBruteForce, ()) {
  auto pts = *point_sets();
  auto judge = hull_judge::judge_hull(pts);
  RC_CLASSIFY(judge.degenerate, "degenerate");
  RC_CLASSIFY(judge.extreme.size() < pts.size(), "some points not extreme");
  if (judge.degenerate) {
    RC_ASSERT_THROWS_AS(convex_hull(pts), kmr::InputError);
    return;
  }
  auto seed = *rc::gen::arbitrary<std::uint64_t>();
  auto h = convex_hull(pts, Arithmetic::exact, seed);
  RC_ASSERT(hull_judge::check_hull(judge, h.vertices, h.facets) == std::string());
}

RC_GTEST_PROP(HullProperties, C2_2_static_hull_correct_IndependentOfInputOrderAndSeed, ()) {
  auto pts = *point_sets();
  if (hull_judge::judge_hull(pts).degenerate) return;
  std::vector<int> order(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[*rc::gen::inRange<std::size_t>(0, i)]);
  std::vector<Point3d> shuffled;
  for (int i : order) shuffled.push_back(pts[i]);
  auto a = convex_hull(pts, Arithmetic::exact, *rc::gen::arbitrary<std::uint64_t>());
  auto b = convex_hull(shuffled, Arithmetic::exact, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(geometric(pts, a) == geometric(shuffled, b));
}
