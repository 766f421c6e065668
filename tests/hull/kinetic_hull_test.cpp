// The kinetic hull (kinetic_hull.hpp) against its judges after every batch: the static algorithm
// run from scratch just before now (C2.2-hull-correct), the independent hull certificate, and a
// from-scratch self-adjusting run (C2.2-stability: trace signature; F2.8: live certificates).
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <sstream>

#include "exact/error.hpp"
#include "hull/hull_at_time.hpp"
#include "hull/kinetic_hull.hpp"

namespace kmr::hull {
namespace {

using exact::Dyadic;
using exact::Integer;

std::vector<MovingPoint> random_motions(int n, std::uint64_t seed, int pos_bits = 10, int vel_bits = 6) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> pos(-(1LL << pos_bits), 1LL << pos_bits), vel(-(1LL << vel_bits), 1LL << vel_bits);
  std::vector<MovingPoint> pts;
  for (int i = 0; i < n; ++i) pts.push_back(linear(pos(rng), pos(rng), pos(rng), vel(rng), vel(rng), vel(rng)));
  return pts;
}

struct Judged {
  long long batches = 0, events = 0, max_batch = 0;
};

// Simulates to `until`, judging after every batch (and after the initial run).
Judged simulate_and_judge(const std::vector<MovingPoint>& pts, int bits, const Dyadic& until, std::uint64_t seed = 2012) {
  kinetic::MotionSimulator sim(bits, until);
  KineticHull kh(pts, sim, seed);
  Judged j;
  auto judge = [&] {
    SCOPED_TRACE("time " + sim.now().to_decimal());
    const auto facets = kh.facets();
    EXPECT_EQ(facets, static_hull_before(pts, sim.now(), seed));
    EXPECT_EQ(hull_certificate_failure(pts, sim.now(), facets), "");
    KineticHull scratch(pts, sim.now(), seed);
    EXPECT_EQ(kh.signature(), scratch.signature());
    EXPECT_EQ(kh.certificate_keys(), scratch.certificate_keys());
    EXPECT_EQ(kh.live_certificates(), static_cast<std::size_t>(sim.counters().live()));
    EXPECT_EQ(kh.counters().certificates_created, sim.counters().created);
  };
  judge();
  while (auto batch = sim.next_batch(until)) {
    kh.update(*batch);
    ++j.batches;
    judge();
    if (::testing::Test::HasFailure()) break;
  }
  j.events = sim.counters().events;
  j.max_batch = sim.counters().max_batch;
  return j;
}

TEST(KineticHull, C2_2_RandomMotionsMatchStaticAndScratchAfterEveryBatch) {
  ::testing::Test::RecordProperty("claim", "C2.2-hull-correct C2.2-stability F2.8-compactness");
  long long batches = 0, events = 0;
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    auto pts = random_motions(10 + 4 * static_cast<int>(seed), seed);
    Judged j = simulate_and_judge(pts, 4, Dyadic(16), seed);
    batches += j.batches, events += j.events;
  }
  std::cout << "batches " << batches << ", events " << events << "\n";
  EXPECT_GT(batches, 20);  // the motions do change the hull
}

// check_simulator_counts (run by `kmr simulate hull --check-every`) holds on the hull's own
// simulator and names the difference when the simulator holds a certificate the hull did not create
// (a leak or a double count on either side), and again after that certificate is removed.
TEST(KineticHull, CheckSimulatorCountsNamesACertificateTheHullDidNotCreate) {
  const auto pts = random_motions(12, 7);
  kinetic::MotionSimulator sim(4, Dyadic(16));
  KineticHull kh(pts, sim, 2012);
  EXPECT_NO_THROW(kh.check_simulator_counts());
  const auto foreign = sim.add(poly::Polynomial(std::vector<Integer>{Integer(1), Integer(1)}));  // 1 + t, never fails
  try {
    kh.check_simulator_counts();
    ADD_FAILURE() << "a certificate created outside the hull was not noticed";
  } catch (const ContractError& e) {
    EXPECT_NE(std::string(e.what()).find("certificates created, the simulator created"), std::string::npos) << e.what();
  }
  sim.remove(foreign);  // created counts still differ by one; live counts agree again
  EXPECT_THROW(kh.check_simulator_counts(), ContractError);
}

// Issue 9's machine certificates: orient3d and centre tests are translation invariant, so
// translating every point by an offset gives the same polynomials. With offset 0 every certificate
// is built in __int128 (machine form); with 2^36 − 2^9 some points are beyond the machine bound
// (mixed); with 2^45 none has a machine form (GMP throughout). Batches, outcomes, trace and live
// certificates must be identical.
TEST(KineticHull, MachineCertificatesEqualTheExactOnes) {
  const auto base = random_motions(24, 99);
  struct Run {
    std::vector<std::vector<kinetic::CertificateId>> batches;
    std::string signature;
    std::vector<KineticHull::CertificateKey> keys;
    std::vector<std::array<int, 3>> facets;
    long long machine = 0;
  };
  auto run = [&](long long offset) {
    auto shift = [offset](MovingPoint q) {
      q[0] = q[0] + Polynomial(Integer(offset));
      return q;
    };
    std::vector<MovingPoint> pts;
    for (const auto& p : base) pts.push_back(shift(p));
    kinetic::MotionSimulator sim(4, Dyadic(8));
    KineticHull kh(pts, sim, 7);
    Run r;
    while (auto b = sim.next_batch(Dyadic(8))) {
      kh.update(*b);
      r.batches.push_back(*b);
      if (r.batches.size() == 40) {  // an integrated change mid-run: new polynomials of one point
        kh.change_motion(3, shift(three_quarters(base[3])));
      }
    }
    r.signature = kh.signature();
    r.keys = kh.certificate_keys();
    r.facets = kh.facets();
    r.machine = sim.counters().machine_polynomials;
    return r;
  };
  const Run a = run(0), mixed = run((1LL << 36) - (1LL << 9)), big = run(1LL << 45);
  EXPECT_GT(a.batches.size(), 50u);
  EXPECT_GT(a.machine, 1000);
  EXPECT_GT(mixed.machine, 0);
  EXPECT_LT(mixed.machine, a.machine);
  EXPECT_EQ(big.machine, 0);
  for (const Run* r : {&mixed, &big}) {
    EXPECT_TRUE(r->batches == a.batches);
    EXPECT_TRUE(r->signature == a.signature);
    EXPECT_TRUE(r->keys == a.keys);
    EXPECT_TRUE(r->facets == a.facets);
  }
  // The machine form itself: at the bound and beyond it.
  EXPECT_TRUE(machine_point(linear((1LL << 36) - 1, 0, 0, -(1LL << 36) + 1, 0, 0)).has_value());
  EXPECT_FALSE(machine_point(linear(1LL << 36, 0, 0, 0, 0, 0)).has_value());
}

// The machine certificate cubics (moving_points.hpp) against the Polynomial ones, which share no
// arithmetic with them, coefficient by coefficient: entries on both sides of the int64 cross-product
// fast path's 2^31 bound (rows of differences of points up to 2^29 … 2^36); in the second half
// position and velocity bits are drawn apart (slow points far out, fast points near the origin).
TEST(KineticHull, MachineCertificatesArePolynomialOnes) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 8000; ++i) {
    const int bits = 4 + static_cast<int>(rng() % 33);  // |coordinate| ≤ 2^bits, bits ≤ 36
    const int vbits = i < 4000 ? bits : static_cast<int>(rng() % 37);  // |velocity| ≤ 2^vbits
    const long long lim = (1LL << bits) - 1, vlim = (1LL << vbits) - 1;
    std::uniform_int_distribution<long long> c(-lim, lim), cv(-vlim, vlim);
    std::array<MovingPoint, 5> p;
    std::array<MachinePoint, 5> m;
    for (int k = 0; k < 5; ++k) {
      p[k] = linear(c(rng), c(rng), c(rng), cv(rng), cv(rng), cv(rng));
      m[k] = *machine_point(p[k]);
    }
    SCOPED_TRACE("case " + std::to_string(i) + ", bits " + std::to_string(bits) + ", velocity bits " + std::to_string(vbits));
    ASSERT_EQ(orientation_polynomial(m[0], m[1], m[2], m[3]).to_polynomial(), orientation_polynomial(p[0], p[1], p[2], p[3]));
    const MovingPoint sum = trajectory_sum(p[0], p[1], p[2], p[4]);
    const MachinePoint msum = m[0] + m[1] + m[2] + m[4];
    ASSERT_EQ(centre_side_polynomial(m[3], m[1], m[2], msum).to_polynomial(), centre_side_polynomial(p[3], p[1], p[2], sum));
  }
}

// The initial tetrahedron's tests in machine form (issue 9) choose what the Polynomial tests
// choose, or refuse with the same message: on moving lines and planes (identically collinear /
// coplanar prefixes), on points coplanar or collinear only at t = 0, and on small grids; unscaled,
// scaled by 2^30 (every point in machine form, products beyond int64), and scaled by 2^32 (some
// points beyond machine_point's 36 bits: mixed forms). Scaling keeps every identity.
TEST(KineticHull, InitialSimplexInMachineFormEqualsTheExactChoice) {
  std::mt19937_64 rng(44);
  auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  long long chosen = 0, refused = 0, wide = 0, mixed = 0;
  auto judge = [&](const std::vector<MovingPoint>& pts, std::vector<int> order, const std::string& what) {
    try {
      refuse_identical_trajectories(pts);  // initial_simplex_of's precondition
    } catch (const InputError&) {
      return;
    }
    std::vector<std::optional<MachinePoint>> machine;
    for (const auto& p : pts) machine.push_back(machine_point(p));
    const auto in_form = std::count_if(machine.begin(), machine.end(), [](const auto& m) { return m.has_value(); });
    auto choose = [&](const std::vector<std::optional<MachinePoint>>* m) -> std::string {
      try {
        const auto s = m ? initial_simplex_of(pts, order, *m) : initial_simplex_of(pts, order);
        return std::to_string(s[0]) + " " + std::to_string(s[1]) + " " + std::to_string(s[2]) + " " + std::to_string(s[3]);
      } catch (const InputError& e) {
        return e.what();
      }
    };
    const std::string exact = choose(nullptr), fast = choose(&machine);
    EXPECT_EQ(fast, exact) << what;
    (exact.find("points") == std::string::npos ? chosen : refused) += 1;
    mixed += in_form > 0 && in_form < static_cast<long>(pts.size());
    for (const auto& m : machine)
      if (m)
        for (int k = 0; k < 3; ++k) wide += std::max(std::llabs(m->x[k]), std::llabs(m->v[k])) >= (1LL << 33);
  };
  for (int trial = 0; trial < 400; ++trial) {
    const int family = trial % 4, n = pick(4, 9);
    const long long scale = trial % 8 < 4 ? 1 : trial % 2 == 0 ? (1LL << 30) : (1LL << 32);
    // A moving frame o + w·t, e1 + g1·t, e2 + g2·t; points o + s·e1 + r·e2 (+ their velocities).
    auto vec = [&] { return std::array<long long, 3>{pick(-3, 3), pick(-3, 3), pick(-3, 3)}; };
    const auto o = vec(), w = vec(), e1 = vec(), g1 = vec(), e2 = vec(), g2 = vec();
    std::vector<MovingPoint> pts;
    for (int i = 0; i < n; ++i) {
      const long long s = pick(-4, 4), r = family == 0 ? 0 : pick(-4, 4);  // 0: a moving line
      std::array<long long, 6> c{};
      for (int k = 0; k < 3; ++k) c[k] = o[k] + s * e1[k] + r * e2[k], c[3 + k] = w[k] + s * g1[k] + r * g2[k];
      if (family == 2 && i % 3 == 2) c[3 + pick(0, 2)] += pick(1, 2);  // leaves the plane after t = 0
      if (family == 3) c = {pick(-1, 1), pick(-1, 1), pick(-1, 1), pick(-1, 1), pick(-1, 1), pick(-1, 1)};  // a grid
      for (auto& x : c) x *= scale;
      pts.push_back(linear(c[0], c[1], c[2], c[3], c[4], c[5]));
    }
    std::vector<int> order(pts.size());
    for (int i = 0; i < n; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    judge(pts, order, "trial " + std::to_string(trial));
  }
  // At machine_point's edge: ±(2^36 − 1) on a moving line and off it (in form), then 2^36 (not).
  const long long m = (1LL << 36) - 1;
  for (long long top : {m, m + 1}) {
    std::vector<MovingPoint> line{linear(0, 0, 0, 0, 0, 0), linear(top, top, -top, -top, top, top),
                                  linear(-top, -top, top, top, -top, -top), linear(top, -top, top, -top, top, -top),
                                  linear(-top, top, -top, top, -top, top)};
    judge(line, {0, 1, 2, 3, 4}, "edge " + std::to_string(top));
  }
  EXPECT_GT(chosen, 50);  // both outcomes occur
  EXPECT_GT(refused, 50);
  EXPECT_GT(wide, 100);   // the machine path ran on entries where int64 products overflow
  EXPECT_GT(mixed, 10);   // and on inputs where only some points have a machine form
}

TEST(KineticHull, StartsCoplanar) {
  // All points on z = 0 at t = 0 (a degenerate start), distinct vertical speeds.
  std::vector<MovingPoint> pts;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> pos(-100, 100), vel(-8, 8);
  for (int i = 0; i < 14; ++i) pts.push_back(linear(pos(rng), pos(rng), 0, vel(rng), vel(rng), vel(rng) + 20 * (i % 3 - 1)));
  simulate_and_judge(pts, 3, Dyadic(16));
}

TEST(KineticHull, SeveralPointsCrossOnePlaneInOneInterval) {
  // A big tetrahedron, and points on a plane z = 10 moving together through z = 0 at t = 1 + tiny
  // offsets (within one lattice interval), with small distinct horizontal drifts.
  std::vector<MovingPoint> pts{linear(-1000, -1000, -1000, 0, 0, 0), linear(1000, -1000, -1000, 0, 0, 0),
                               linear(0, 1000, -1000, 0, 0, 0), linear(0, 0, 1000, 0, 0, 1)};
  const long long xs[8] = {-310, -170, -60, 30, 140, 250, -220, 90}, ys[8] = {13, -170, 210, -40, 95, -260, 170, -5};
  for (int i = 0; i < 8; ++i) pts.push_back(linear(xs[i], ys[i], 2000 + 3 * i * i, 7 * i - 25, 11 - 5 * i, -2000));
  EXPECT_GE(simulate_and_judge(pts, 2, Dyadic(4)).max_batch, 2);
}

TEST(KineticHull, FourPointsCoplanarAtALatticePoint) {
  // Points 0..3 on the plane x = 0 exactly at t = 1 (a lattice point), apart before and after.
  std::vector<MovingPoint> pts{linear(-5, 0, 0, 5, 0, 0),    linear(5, 40, 0, -5, 0, 0),  linear(-10, 0, 40, 10, 1, 0),
                               linear(10, 30, 30, -10, 0, 1), linear(100, -100, -100, 0, 0, 0), linear(-100, 100, -100, 0, 0, 0),
                               linear(-100, -100, 100, 0, 1, 0), linear(100, 100, 100, 1, 0, 0), linear(0, 200, 0, 0, -3, 2)};
  EXPECT_GE(simulate_and_judge(pts, 3, Dyadic(4)).events, 1);
}

TEST(KineticHull, RefusesIdenticalTrajectories) {
  std::vector<MovingPoint> pts = random_motions(8, 3);
  pts.push_back(pts[2]);
  kinetic::MotionSimulator sim(10, Dyadic(4));
  try {
    KineticHull kh(pts, sim);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("points 2 and 8 have identical trajectories"), std::string::npos) << e.what();
  }
}

TEST(KineticHull, RefusesIdenticallyCoplanarPoints) {
  // Four points of the plane z = 0 that stay in it (vz = 0), plus points off it: some certificate
  // on the four is identically zero.
  std::vector<MovingPoint> pts{linear(0, 0, 0, 1, 0, 0),   linear(50, 0, 0, 0, 1, 0),   linear(0, 50, 0, 1, 1, 0),
                               linear(20, 20, 0, -1, 0, 0), linear(10, 10, 80, 0, 0, 1), linear(10, 10, -80, 0, 0, -1)};
  kinetic::MotionSimulator sim(10, Dyadic(4));
  bool refused = false;
  for (std::uint64_t seed = 1; seed <= 8 && !refused; ++seed) {
    try {
      kinetic::MotionSimulator s(10, Dyadic(4));
      KineticHull kh(pts, s, seed);
    } catch (const InputError& e) {
      refused = std::string(e.what()).find("stay coplanar for all time") != std::string::npos;
      EXPECT_TRUE(refused) << e.what();
    }
  }
  EXPECT_TRUE(refused);
}

TEST(HullJudge, CertificateCatchesAWrongFacet) {
  auto pts = random_motions(12, 5);
  auto facets = static_hull_before(pts, Dyadic(0));
  EXPECT_EQ(hull_certificate_failure(pts, Dyadic(0), facets), "");
  auto flipped = facets;
  std::swap(flipped[0][1], flipped[0][2]);
  EXPECT_NE(hull_certificate_failure(pts, Dyadic(0), flipped), "");
  EXPECT_NE(hull_certificate_failure(pts, Dyadic(1000), facets), "");  // the points moved
}

TEST(HullMotions, ParsesAndRefuses) {
  std::istringstream ok("# x y z vx vy vz\n1 2 3 4 5 6\n\n-7 8 9 0 0 123456789012345678901234567890\n");
  auto pts = parse_hull_motions(ok, "f");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1][2], Polynomial(std::vector<Integer>{Integer(9), exact::parse_integer("123456789012345678901234567890")}));
  std::istringstream bad("1 2 3 4 5\n");
  EXPECT_THROW(parse_hull_motions(bad, "f"), InputError);
  std::istringstream bad2("1 2 3 4 5 x\n");
  try {
    parse_hull_motions(bad2, "g");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g:1"), std::string::npos);
  }
}

}  // namespace
}  // namespace kmr::hull
