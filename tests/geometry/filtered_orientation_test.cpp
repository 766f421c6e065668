// The orient3d filter never changes an answer: on random, near-degenerate and huge-spread inputs
// filtered_orientation equals the Dyadic orientation, and the filter abstains (falls back) on
// exactly coplanar and nearly coplanar quadruples.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/filtered_orientation.hpp"

using kmr::geometry::filter_safe;
using kmr::geometry::filtered_orientation;
using kmr::geometry::orientation_exact;
using kmr::geometry::orientation_filter;
using kmr::geometry::Point3d;

TEST(FilteredOrientation, NeverChangesAnAnswer) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int abstained = 0, decided = 0;
  for (int rep = 0; rep < 20000; ++rep) {
    Point3d p{u(rng), u(rng), u(rng)}, q{u(rng), u(rng), u(rng)}, r{u(rng), u(rng), u(rng)}, s;
    switch (rep % 4) {
      case 0: s = {u(rng), u(rng), u(rng)}; break;  // generic
      case 1: {  // on the plane pqr up to rounding: s = p + a(q−p) + b(r−p) in doubles
        double a = u(rng), b = u(rng);
        for (int k = 0; k < 3; ++k) s[k] = p[k] + a * (q[k] - p[k]) + b * (r[k] - p[k]);
        break;
      }
      case 2: {  // exactly coplanar small integers (plane z = x + y), then one ulp off
        for (Point3d* x : {&p, &q, &r, &s}) {
          (*x)[0] = std::floor(u(rng) * 8), (*x)[1] = std::floor(u(rng) * 8), (*x)[2] = (*x)[0] + (*x)[1];
        }
        if (rep % 8 == 2) s[2] = std::nextafter(s[2], 100.0);
        break;
      }
      default: {  // near-degenerate at a large offset: coordinates 2^40 + small
        double o = std::ldexp(1, 40);
        for (Point3d* x : {&p, &q, &r}) (*x) = {o + std::floor(u(rng) * 4), o + std::floor(u(rng) * 4), o};
        s = {o + 1, o + 2, std::nextafter(o, rep % 8 == 3 ? 0.0 : 1e300)};
      }
    }
    int want = orientation_exact(p, q, r, s);
    int f = orientation_filter(p, q, r, s);
    if (f == 0) ++abstained; else ++decided;
    if (f != 0) ASSERT_EQ(f, want) << rep;
    ASSERT_EQ(filtered_orientation(p, q, r, s), want) << rep;
    if (want == 0) ASSERT_EQ(f, 0) << "the filter claimed a sign for coplanar points, rep " << rep;
  }
  EXPECT_GT(abstained, 1000);  // the near-degenerate families do reach the fallback
  EXPECT_GT(decided, 5000);
}

TEST(FilteredOrientation, OneUlpFromCoplanarIsDecidedCorrectly) {
  // p, q, r on z = 0 and s one ulp above or below 0 (a subnormal): the true sign is ±1.
  Point3d p{0, 0, 0}, q{1, 0, 0}, r{0, 1, 0};
  for (double z : {std::nextafter(0.0, 1.0), -std::nextafter(0.0, 1.0), 0x1p-300, -0x1p-300}) {
    Point3d s{0.25, 0.25, z};
    EXPECT_EQ(filtered_orientation(p, q, r, s), z > 0 ? 1 : -1);
    EXPECT_EQ(orientation_exact(p, q, r, s), z > 0 ? 1 : -1);
  }
}

TEST(FilteredOrientation, OutsideTheSafeRangeGoesExact) {
  EXPECT_FALSE(filter_safe(0x1p251));
  EXPECT_FALSE(filter_safe(0x1p-251));
  EXPECT_TRUE(filter_safe(0.0));
  EXPECT_TRUE(filter_safe(-0x1p250));
  double big = 0x1p700, tiny = 0x1p-700;
  Point3d p{0, 0, 0}, q{big, 0, 0}, r{0, big, 0}, s{tiny, tiny, tiny};
  EXPECT_EQ(filtered_orientation(p, q, r, s), 1);
  EXPECT_EQ(filtered_orientation(p, r, q, s), -1);
}

TEST(FilteredOrientation, AnyOnePointOutsideTheSafeRangeGoesExact) {
  // p, q, r, s = 0, e_x, e_y, e_z (orientation det I = +1), with one coordinate of one point set to
  // ε = 2^-300 (outside the safe range): det becomes 1 − ε for p and stays 1 otherwise, by hand.
  const double e = 0x1p-300;
  const Point3d base[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Point3d moved[4] = {{e, 0, 0}, {1, e, 0}, {e, 1, 0}, {0, e, 1}};
  for (int i = 0; i < 4; ++i) {
    Point3d u[4] = {base[0], base[1], base[2], base[3]};
    u[i] = moved[i];
    ASSERT_FALSE(filter_safe(u[i]));
    EXPECT_EQ(filtered_orientation(u[0], u[1], u[2], u[3]), 1) << i;
    EXPECT_EQ(filtered_orientation(u[0], u[2], u[1], u[3]), -1) << i;  // a swap flips the sign
  }
}
