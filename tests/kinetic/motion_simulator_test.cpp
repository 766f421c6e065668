// The lattice motion simulator (§2.1) on hand-derived certificates.
#include <gtest/gtest.h>

#include <sstream>

#include "exact/error.hpp"
#include "kinetic/kinetic_sort.hpp"
#include "kinetic/point_file.hpp"
#include "kinetic/trajectory.hpp"
#include "geometry/predicates.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::kinetic::MotionSimulator;
using kmr::poly::Polynomial;

namespace {
Polynomial poly(std::vector<long> c) {
  std::vector<Integer> v(c.begin(), c.end());
  return Polynomial(v);
}
}  // namespace

TEST(MotionSimulator, A2_1_BatchesAllFailuresOfOneLatticeInterval) {
  RecordProperty("claim", "A2.1-batch");
  // δ = 1/4. Roots: p1 at 1/8 and 3/16 (both in interval k = 0, an even count: no failure),
  // p2 at 1/3 (k = 1), p3 at 3/10 (k = 1), p4 at 5/4 (k = 5, exactly on a lattice point).
  MotionSimulator sim(2, Dyadic(2));
  auto p1 = sim.add(poly({3, -40, 128}));  // (8t−1)(16t−3) = 128t² − 40t + 3
  auto p2 = sim.add(poly({1, -3}));
  auto p3 = sim.add(poly({3, -10}));
  auto p4 = sim.add(poly({-5, 4}));
  EXPECT_EQ(sim.outcome(p1), 1);
  EXPECT_EQ(sim.outcome(p2), 1);
  EXPECT_EQ(sim.outcome(p4), -1);
  auto b1 = sim.next_batch(Dyadic(2));
  ASSERT_TRUE(b1);
  EXPECT_EQ(*b1, (std::vector<kmr::kinetic::CertificateId>{p2, p3}));
  EXPECT_EQ(sim.now(), Dyadic(Integer(1), -1));  // (1+1)·δ = 1/2
  EXPECT_EQ(sim.outcome(p2), -1);
  EXPECT_EQ(sim.outcome(p3), -1);
  auto b2 = sim.next_batch(Dyadic(2));
  ASSERT_TRUE(b2);
  EXPECT_EQ(*b2, (std::vector<kmr::kinetic::CertificateId>{p4}));
  EXPECT_EQ(sim.now(), Dyadic(Integer(3), -1));  // 6δ = 3/2
  EXPECT_FALSE(sim.next_batch(Dyadic(2)));
  EXPECT_EQ(sim.counters().events, 3);
  EXPECT_EQ(sim.counters().batches, 2);
  EXPECT_EQ(sim.counters().max_batch, 2);
  EXPECT_EQ(sim.counters().live(), 4);
  sim.remove(p1);
  EXPECT_EQ(sim.counters().live(), 3);
}

TEST(MotionSimulator, A2_1_TangencyIsNoFailureAndZeroAtLatticePointTakesSignBefore) {
  RecordProperty("claim", "A2.1-sign-before-after");
  MotionSimulator sim(0, Dyadic(10));
  auto tangent = sim.add(poly({9, -6, 1}));  // (t−3)²: touches zero at t = 3, never changes sign
  EXPECT_FALSE(sim.certificate(tangent).failure);
  // (t−0)·(t−5): zero at the start time 0; the outcome is the sign just before 0, which is +.
  auto at_start = sim.add(poly({0, -5, 1}));
  EXPECT_EQ(sim.outcome(at_start), 1);
  auto b = sim.next_batch(Dyadic(10));
  ASSERT_TRUE(b);
  EXPECT_EQ(*b, std::vector<kmr::kinetic::CertificateId>{at_start});  // interval [0, 1)
  EXPECT_EQ(sim.now(), Dyadic(1));
  b = sim.next_batch(Dyadic(10));
  ASSERT_TRUE(b);  // the root at 5 is in [5, 6)
  EXPECT_EQ(sim.now(), Dyadic(6));
  EXPECT_EQ(sim.outcome(at_start), 1);
}

TEST(MotionSimulator, HorizonBoundsTheScheduleAndUntilBoundsTheBatches) {
  MotionSimulator sim(0, Dyadic(5));
  auto late = sim.add(poly({-5, 1}));  // root at 5: interval [5, 6) ends after the horizon
  EXPECT_FALSE(sim.certificate(late).failure);
  auto early = sim.add(poly({-4, 1}));  // interval [4, 5) ends exactly at the horizon
  ASSERT_TRUE(sim.certificate(early).failure);
  EXPECT_FALSE(sim.next_batch(Dyadic(4)));  // processing it would pass 4
  EXPECT_TRUE(sim.next_batch(Dyadic(5)));
}

TEST(MotionSimulator, RefusesIdenticallyZeroCertificates) {
  MotionSimulator sim(10, Dyadic(1));
  EXPECT_THROW(sim.add(Polynomial()), kmr::InputError);
  EXPECT_THROW(MotionSimulator(-1, Dyadic(1)), kmr::InputError);
}

TEST(MotionSimulator, A2_1_Orient3dCertificateOfLinearMotionIsACubicWhoseFailuresAreReal) {
  RecordProperty("claim", "A2.1-batch");
  std::mt19937_64 rng(7);
  auto pts = kmr::kinetic::random_linear_trajectories<3>(4, rng);
  Polynomial cert = kmr::geometry::orientation_value(pts[0], pts[1], pts[2], pts[3]);
  EXPECT_LE(cert.degree(), 3);
  MotionSimulator sim(10, Dyadic::pow2(27));
  auto id = sim.add(cert);
  int flips = 0;
  while (auto b = sim.next_batch(Dyadic::pow2(27))) {
    Dyadic end = sim.now(), start = end - Dyadic::pow2(-10);
    EXPECT_NE(kmr::poly::sign_before(cert, start), kmr::poly::sign_before(cert, end));
    EXPECT_EQ(sim.outcome(id), kmr::poly::sign_before(cert, end));
    ++flips;
  }
  EXPECT_LE(flips, 3);
}

TEST(KineticSort, RefusesIdenticalTrajectoriesNamingBoth) {
  MotionSimulator sim(10, Dyadic(1));
  try {
    kmr::kinetic::KineticSort sort({poly({1, 2}), poly({0, 1}), poly({1, 2})}, sim);
    FAIL() << "identical trajectories accepted";
  } catch (const kmr::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("points 0 and 2"), std::string::npos) << e.what();
  }
}

TEST(PointFile, ParsesCommentsAndBlankLinesAndRefusesBadLinesWithFileAndLine) {
  std::istringstream good("# header\n1 2\n\n-3 +4  # trailing\n123456789012345678901234567890 0\n");
  auto pts = kmr::kinetic::parse_sort_points(good, "f.txt");
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[1].x0, -3);
  EXPECT_EQ(pts[1].v, 4);
  EXPECT_EQ(pts[2].x0, Integer("123456789012345678901234567890"));
  auto error_of = [](const std::string& text) {
    std::istringstream in(text);
    try {
      kmr::kinetic::parse_sort_points(in, "f.txt");
    } catch (const kmr::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("1 2\n3\n").find("f.txt:2"), std::string::npos);
  EXPECT_NE(error_of("1 2\n3 4 5\n").find("f.txt:2"), std::string::npos);
  EXPECT_NE(error_of("1 2.5\n").find("f.txt:1"), std::string::npos);
  EXPECT_NE(error_of("1 nan\n").find("'nan'"), std::string::npos);
  EXPECT_NE(error_of("# nothing\n").find("no points"), std::string::npos);
}
