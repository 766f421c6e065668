// Sign conventions of geometry/predicates.hpp on hand-derived configurations, over Integer and
// Dyadic, and the certificate-polynomial form over Polynomial (evaluated back at sample times).
#include <gtest/gtest.h>

#include "geometry/predicates.hpp"
#include "poly/polynomial.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::geometry::Point;
using kmr::poly::Polynomial;
namespace g = kmr::geometry;

template <std::size_t D>
Point<D, Integer> P(std::array<long, D> c) {
  Point<D, Integer> p;
  for (std::size_t i = 0; i < D; ++i) p[i] = c[i];
  return p;
}

TEST(Predicates, Orientation2DIsPositiveForLeftTurns) {
  EXPECT_EQ(g::orientation(P<2>({0, 0}), P<2>({1, 0}), P<2>({0, 1})), 1);
  EXPECT_EQ(g::orientation(P<2>({0, 0}), P<2>({0, 1}), P<2>({1, 0})), -1);
  EXPECT_EQ(g::orientation(P<2>({0, 0}), P<2>({1, 1}), P<2>({3, 3})), 0);
}

TEST(Predicates, Orientation3DIsPositiveWhenSIsAbovePlanePQR) {
  // det[q−p, r−p, s−p] with p=0, q=e1, r=e2, s=e3 is +1 (CGAL: POSITIVE).
  EXPECT_EQ(g::orientation(P<3>({0, 0, 0}), P<3>({1, 0, 0}), P<3>({0, 1, 0}), P<3>({0, 0, 1})), 1);
  EXPECT_EQ(g::orientation(P<3>({0, 0, 0}), P<3>({0, 1, 0}), P<3>({1, 0, 0}), P<3>({0, 0, 1})), -1);
  EXPECT_EQ(g::orientation(P<3>({0, 0, 0}), P<3>({1, 0, 0}), P<3>({0, 1, 0}), P<3>({5, 7, 0})), 0);
}

TEST(Predicates, SideOfOrientedCircleIsPositiveInside) {
  auto p = P<2>({0, 0}), q = P<2>({4, 0}), r = P<2>({0, 4});  // ccw; circle centre (2,2), r² = 8
  ASSERT_EQ(g::orientation(p, q, r), 1);
  EXPECT_EQ(g::side_of_oriented_circle(p, q, r, P<2>({2, 2})), 1);
  EXPECT_EQ(g::side_of_oriented_circle(p, q, r, P<2>({5, 5})), -1);
  EXPECT_EQ(g::side_of_oriented_circle(p, q, r, P<2>({4, 4})), 0);
  EXPECT_EQ(g::side_of_oriented_circle(q, p, r, P<2>({2, 2})), -1);  // clockwise flips it
}

TEST(Predicates, SideOfOrientedSphereIsPositiveInsideForPositiveOrientation) {
  auto p = P<3>({0, 0, 0}), q = P<3>({4, 0, 0}), r = P<3>({0, 4, 0}), s = P<3>({0, 0, 4});
  ASSERT_EQ(g::orientation(p, q, r, s), 1);
  // Sphere through them: centre (2,2,2), radius² 12.
  EXPECT_EQ(g::side_of_oriented_sphere(p, q, r, s, P<3>({1, 1, 1})), 1);
  EXPECT_EQ(g::side_of_oriented_sphere(p, q, r, s, P<3>({5, 5, 5})), -1);
  EXPECT_EQ(g::side_of_oriented_sphere(p, q, r, s, P<3>({4, 4, 4})), 0);
  EXPECT_EQ(g::side_of_oriented_sphere(q, p, r, s, P<3>({1, 1, 1})), -1);
}

TEST(Predicates, CompareSquaredDistance) {
  EXPECT_EQ(g::compare_squared_distance<2>(P<2>({0, 0}), P<2>({3, 4}), P<2>({5, 0})), 0);
  EXPECT_EQ(g::compare_squared_distance<2>(P<2>({0, 0}), P<2>({3, 3}), P<2>({5, 0})), -1);
  EXPECT_EQ(g::compare_squared_distance<2>(P<2>({0, 0}), P<2>({4, 4}), P<2>({5, 0})), 1);
}

TEST(Predicates, DyadicCoordinatesAreExact) {
  // 0.1 is not dyadic but its double is: three nearly-collinear points decided exactly.
  Point<2, Dyadic> a{Dyadic::from_double(0.1), Dyadic::from_double(0.1)};
  Point<2, Dyadic> b{Dyadic::from_double(0.2), Dyadic::from_double(0.2)};
  Point<2, Dyadic> c{Dyadic::from_double(0.3), Dyadic::from_double(0.3)};
  // Points on y = x stay collinear whatever doubles they are; a 2^-80 nudge is still seen.
  EXPECT_EQ(g::orientation(a, b, c), 0);
  Point<2, Dyadic> d{Dyadic::from_double(0.3), Dyadic::from_double(0.3) + Dyadic::pow2(-80)};
  EXPECT_EQ(g::orientation(a, b, d), 1);
}

TEST(Predicates, CertificatePolynomialOfMovingPointsMatchesStaticPredicateAtEachTime) {
  // Three points moving linearly; orientation_value over Polynomial is a quadratic in t whose value
  // at t equals the static determinant of the positions at t.
  auto lin = [](long x, long v) { return Polynomial(std::vector<Integer>{Integer(x), Integer(v)}); };
  Point<2, Polynomial> a{lin(0, 1), lin(0, 0)}, b{lin(4, -1), lin(0, 1)}, c{lin(1, 0), lin(3, -2)};
  Polynomial cert = g::orientation_value(a, b, c);
  EXPECT_LE(cert.degree(), 2);
  for (long t = -5; t <= 5; ++t) {
    auto at = [&](const Point<2, Polynomial>& p) { return P<2>({p[0].evaluate(Integer(t)).convert_to<long>(), p[1].evaluate(Integer(t)).convert_to<long>()}); };
    EXPECT_EQ(cert.evaluate(Integer(t)), g::orientation_value(at(a), at(b), at(c))) << "t = " << t;
  }
}
