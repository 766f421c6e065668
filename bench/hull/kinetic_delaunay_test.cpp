// Fig. 2.3's kinetic Delaunay baseline judged (claim F2.3-events-vs-kinetic-delaunay): hand-made
// motions whose Delaunay changes are derived by hand (below), and random motions on which CGAL's
// triangulation at a time inside every gap between batches must equal the kept one.
#include <gtest/gtest.h>

#include <random>

#include "hull/kinetic_hull.hpp"
#include "kinetic_delaunay.hpp"
#include "kinetic/trajectory.hpp"

namespace {

using kmr::bench::KineticDelaunay;
using kmr::exact::Dyadic;
using kmr::hull::MovingPoint;
using kmr::poly::Polynomial;

MovingPoint moving(long long x, long long y, long long z, long long vx = 0, long long vy = 0, long long vz = 0) {
  auto c = [](long long a, long long v) { return Polynomial(std::vector<kmr::exact::Integer>{a, v}); };
  return {c(x, vx), c(y, vy), c(z, vz)};
}

struct SimulationRun {
  long long events = 0, flips = 0, batches = 0;
  std::vector<std::string> gap_failures;
  std::vector<long long> flips_per_batch;
};

// Runs to the horizon, checking every gap between batches (and the last one, up to the horizon).
SimulationRun simulate(KineticDelaunay& kd, kmr::kinetic::MotionSimulator& sim, const Dyadic& until) {
  SimulationRun r;
  const Dyadic delta = Dyadic::pow2(-sim.lattice_bits());
  for (;;) {
    const Dyadic before = sim.now();
    auto b = sim.next_batch(until);
    if (!b) break;
    if (auto e = kd.check_gap(before, sim.now() - delta); !e.empty()) r.gap_failures.push_back(e);
    r.flips_per_batch.push_back(kd.update(*b));
  }
  if (auto e = kd.check_gap(sim.now(), until); !e.empty()) r.gap_failures.push_back(e);
  r.events = kd.counters().events, r.flips = kd.counters().flips, r.batches = kd.counters().batches;
  return r;
}

// a, b, c on the circle of radius 5 about the z-axis in z = 0, d = (0, 0, 5): the sphere of abcd is
// |x| = 5. e(t) = (t − 4, 0, −4) stays below z = 0 with segment de through the triangle abc (the five
// points stay in convex position, hull unchanged), and is inside the sphere iff (t − 4)² < 9, i.e.
// for t in (1, 7): two Delaunay flips, 2 → 3 cells at t = 1 (the one inner facet abc fails) and
// 3 → 2 at t = 7 (the three inner facets ade, bde, cde of the same five points fail together).
TEST(KineticDelaunay, F2_3_BipyramidFlipsTwice) {
  RecordProperty("claim", "F2.3-events-vs-kinetic-delaunay");
  std::vector<MovingPoint> pts{moving(5, 0, 0), moving(-3, 4, 0), moving(-3, -4, 0), moving(0, 0, 5), moving(-4, 0, -4, 1, 0, 0)};
  kmr::kinetic::MotionSimulator sim(3, Dyadic(8));
  KineticDelaunay kd(pts, sim);
  EXPECT_EQ(kd.cells().size(), 2u);
  SimulationRun r = simulate(kd, sim, Dyadic(8));
  EXPECT_TRUE(r.gap_failures.empty()) << r.gap_failures.front();
  EXPECT_EQ(r.batches, 2);
  EXPECT_EQ(r.events, 4);
  EXPECT_EQ(r.flips, 2);
  EXPECT_EQ(r.flips_per_batch, (std::vector<long long>{1, 1}));
  EXPECT_EQ(kd.cells().size(), 2u);
  EXPECT_EQ(kd.hull_vertices(), (std::vector<int>{0, 1, 2, 3, 4}));
}

// The tetrahedron a = 0, b = (8,0,0), c = (0,8,0), d = (0,0,8) and e(t) = (1, 1, t − 4) rising into
// it. The sphere of abcd has centre (4,4,4) and radius² 48: e enters it when 18 + (t − 8)² = 48,
// t = 8 − √30 ≈ 2.52 (one flip: the inner facet abc of abcd|abce fails). At t = 4 e reaches the
// hull face abc's plane inside the triangle: the hull faces abe, bce, cae become coplanar and the
// three hull edges ae, be, ce (one 4-set a, b, c, e) fail together: one change, e leaves the hull.
// Afterwards (t ≤ 5) e is interior: its star of four cells is the only triangulation.
TEST(KineticDelaunay, F2_3_PointEntersHull) {
  RecordProperty("claim", "F2.3-events-vs-kinetic-delaunay");
  std::vector<MovingPoint> pts{moving(0, 0, 0), moving(8, 0, 0), moving(0, 8, 0), moving(0, 0, 8), moving(1, 1, -4, 0, 0, 1)};
  kmr::kinetic::MotionSimulator sim(4, Dyadic(5));
  KineticDelaunay kd(pts, sim);
  EXPECT_EQ(kd.hull_vertices(), (std::vector<int>{0, 1, 2, 3, 4}));
  SimulationRun r = simulate(kd, sim, Dyadic(5));
  EXPECT_TRUE(r.gap_failures.empty()) << r.gap_failures.front();
  EXPECT_EQ(r.batches, 2);
  EXPECT_EQ(r.events, 4);
  EXPECT_EQ(r.flips, 2);
  EXPECT_EQ(kd.cells().size(), 4u);
  EXPECT_EQ(kd.hull_vertices(), (std::vector<int>{0, 1, 2, 3}));
}

// The same tetrahedron, e(t) = (1, 1, 1 − t) leaving it through the hull face abc: at t = 1 the cell
// abce flattens (its hull-face certificate fails; e joins the hull, star of 4 cells → 3 cells around
// de, e inside the sphere of abcd); at t = 1 + √30 − 3 ≈ 2.48 e leaves that sphere (z = 4 − √30) and
// the three inner facets ade, bde, cde fail together: 3 → 2 cells.
TEST(KineticDelaunay, F2_3_PointLeavesThroughHullFace) {
  RecordProperty("claim", "F2.3-events-vs-kinetic-delaunay");
  std::vector<MovingPoint> pts{moving(0, 0, 0), moving(8, 0, 0), moving(0, 8, 0), moving(0, 0, 8), moving(1, 1, 1, 0, 0, -1)};
  kmr::kinetic::MotionSimulator sim(4, Dyadic(5));
  KineticDelaunay kd(pts, sim);
  EXPECT_EQ(kd.cells().size(), 4u);
  EXPECT_EQ(kd.hull_vertices(), (std::vector<int>{0, 1, 2, 3}));
  SimulationRun r = simulate(kd, sim, Dyadic(5));
  EXPECT_TRUE(r.gap_failures.empty()) << r.gap_failures.front();
  EXPECT_EQ(r.batches, 2);
  EXPECT_EQ(r.events, 4);
  EXPECT_EQ(r.flips, 2);
  EXPECT_EQ(kd.cells().size(), 2u);
  EXPECT_EQ(kd.hull_vertices(), (std::vector<int>{0, 1, 2, 3, 4}));
}

// Random §2.4-style motions (small, so many events happen early): every gap between batches is
// checked against CGAL; the Delaunay hull vertices equal the kinetic hull's after every batch.
TEST(KineticDelaunay, F2_3_RandomMotionsMatchCgalBetweenBatches) {
  RecordProperty("claim", "F2.3-events-vs-kinetic-delaunay");
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    auto pts = kmr::kinetic::random_linear_trajectories<3>(14, rng, {6, 4});
    const Dyadic until = Dyadic::pow2(5);
    kmr::kinetic::MotionSimulator sim(6, until), hull_sim(6, until);
    KineticDelaunay kd(pts, sim);
    kmr::hull::KineticHull kh(pts, hull_sim);
    EXPECT_EQ(kd.hull_vertices(), kh.vertices());
    SimulationRun r = simulate(kd, sim, until);
    EXPECT_TRUE(r.gap_failures.empty()) << "seed " << seed << ": " << r.gap_failures.front();
    EXPECT_GT(r.flips, 10) << "seed " << seed;
    EXPECT_LE(r.flips, r.events);
    // The hull of the final triangulation is the kinetic hull's at the horizon.
    kh.run_until(until, [] {});
    EXPECT_EQ(kd.hull_vertices(), kh.vertices()) << "seed " << seed;
  }
}

TEST(KineticDelaunay, RefusesIdenticallyCosphericalPoints) {
  // Five points on the sphere |x| = 5 translating together: cospherical for all time, so their
  // sphere certificate is identically zero; refused with an InputError naming them.
  std::vector<MovingPoint> pts{moving(5, 0, 0, 1, 1, 1), moving(-3, 4, 0, 1, 1, 1), moving(-3, -4, 0, 1, 1, 1),
                               moving(0, 0, 5, 1, 1, 1), moving(0, 0, -5, 1, 1, 1)};
  kmr::kinetic::MotionSimulator sim(3, Dyadic(8));
  EXPECT_THROW(KineticDelaunay(pts, sim), kmr::InputError);
}

TEST(KineticDelaunay, RefusesPointsCoplanarForAllTime) {
  std::vector<MovingPoint> pts{moving(0, 0, 0, 1, 0, 0), moving(4, 0, 0), moving(0, 4, 0, 0, 1, 0), moving(3, 3, 0), moving(1, 2, 0, 2, 1, 0)};
  kmr::kinetic::MotionSimulator sim(3, Dyadic(8));
  EXPECT_THROW(KineticDelaunay(pts, sim), kmr::InputError);
}

}  // namespace
