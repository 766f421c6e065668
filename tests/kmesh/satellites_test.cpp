// §4.1.1 satellites: hand-derived offsets, exact unit length, angles within 0.05° of kπ/12.
#include <gtest/gtest.h>

#include <cmath>

#include "kmesh/satellites.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

TEST(Satellites, HandDerivedRayVectors) {
  RayVector r1 = ray_vector(1);
  EXPECT_EQ(r1.a, 1419);
  EXPECT_EQ(r1.b, 380);
  EXPECT_EQ(r1.c, 1469);
  RayVector r7 = ray_vector(7);  // ray 1 turned by 90°
  EXPECT_EQ(r7.a, -380);
  EXPECT_EQ(r7.b, 1419);
  RayVector r12 = ray_vector(12);  // 180°
  EXPECT_EQ(r12.a, -1);
  EXPECT_EQ(r12.b, 0);
  RayVector r9 = ray_vector(9);  // 135° = 45° + 90°: (−696, 697)/985
  EXPECT_EQ(r9.a, -696);
  EXPECT_EQ(r9.b, 697);
  EXPECT_EQ(r9.c, 985);
  // kScale·2^0·u_0 = (kScale, 0); kScale·2^3·u_6 = (0, 8·kScale); kScale·2^−1·u_3 = (697/985·kScale/2, ...).
  EXPECT_EQ(satellite_offset(0, 0)[0], Dyadic(Integer(4863249365LL)));
  EXPECT_EQ(satellite_offset(0, 0)[1], Dyadic(0));
  EXPECT_EQ(satellite_offset(6, 3)[1], Dyadic(Integer(8) * 4863249365LL));
  EXPECT_EQ(satellite_offset(3, -1)[0], Dyadic(Integer(697) * (4863249365LL / 985), -1));
}

TEST(Satellites, UnitLengthAndAngles) {
  RecordProperty("claim", "L4.2.3");
  for (int k = 0; k < kRays; ++k) {
    RayVector r = ray_vector(k);
    EXPECT_EQ(Integer(r.a) * r.a + Integer(r.b) * r.b, Integer(r.c) * r.c) << k;
    double ang = std::atan2(double(r.b), double(r.a));
    double want = k * M_PI / 12;
    double diff = std::remainder(ang - want, 2 * M_PI);
    EXPECT_LT(std::abs(diff), 0.05 * M_PI / 180) << k;
    // |offset|² = (kScale·2^ℓ)² exactly, for a negative and a positive rank.
    for (std::int64_t l : {-5, 0, 7}) {
      Point2 o = satellite_offset(k, l);
      EXPECT_EQ(o[0] * o[0] + o[1] * o[1], Dyadic(Integer(4863249365LL) * 4863249365LL, 2 * l));
    }
  }
}

TEST(Satellites, ParityRule) {
  auto odd = rays_of_rank(-3), even = rays_of_rank(4);
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(odd[i], 2 * i + 1);
    EXPECT_EQ(even[i], 2 * i);
  }
  Point2 v{Dyadic(10), Dyadic(-4)};
  Point2 s = satellite_position(v, 6, 2);
  EXPECT_EQ(s[0], Dyadic(10));
  EXPECT_EQ(s[1], Dyadic(Integer(4) * 4863249365LL - 4));
}
