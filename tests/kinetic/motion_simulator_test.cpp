// The lattice motion simulator (§2.1) on hand-derived certificates.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numeric>
#include <set>
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

namespace {
// The judge of the orient3d tests, sharing no code with geometry/ or poly/: the positions of the
// moving points at t = k/2^b, scaled by 2^(Bℓ+b), are X·2^b + V·2^(Bℓ−Bv)·k (written out here from
// the §2.3 definition, not through linear_trajectory), and det[q−p, r−p, s−p] is expanded by hand.
using Motion3 = std::array<std::array<long long, 3>, 2>;  // {X, V}
Integer det3_at(const std::vector<Motion3>& m, const Integer& k, int b, kmr::kinetic::MotionBits bits) {
  std::array<std::array<Integer, 3>, 4> p;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      p[i][c] = (Integer(m[i][0][c]) << b) + (Integer(m[i][1][c]) << (bits.position - bits.velocity)) * k;
  std::array<std::array<Integer, 3>, 3> d;
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) d[i][c] = p[i + 1][c] - p[0][c];
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}
}  // namespace

TEST(MotionSimulator, A2_3_Orient3dCubicOfMovingPointsEqualsStaticOrient3dAtSampleTimes) {
  RecordProperty("claim", "A2.3-trajectories");
  // For random X ∈ [−2^Bℓ, 2^Bℓ]³, V ∈ [−2^Bv, 2^Bv]³ at two bit settings: the certificate built by
  // linear_trajectory + orientation_value is a cubic whose value at t = k/2^b, times 2^(3b), equals
  // the static orient3d determinant of the positions at that time (hand-expanded above), for 64 k.
  for (kmr::kinetic::MotionBits bits : {kmr::kinetic::MotionBits{}, kmr::kinetic::MotionBits{12, 3}}) {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<long long> pos(-(1LL << bits.position), 1LL << bits.position);
    std::uniform_int_distribution<long long> vel(-(1LL << bits.velocity), 1LL << bits.velocity);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<Motion3> m(4);
      std::vector<kmr::kinetic::Trajectory<3>> pts;
      for (auto& mi : m) {
        for (auto& x : mi[0]) x = pos(rng);
        for (auto& v : mi[1]) v = vel(rng);
        std::array<Integer, 3> X{Integer(mi[0][0]), Integer(mi[0][1]), Integer(mi[0][2])};
        std::array<Integer, 3> V{Integer(mi[1][0]), Integer(mi[1][1]), Integer(mi[1][2])};
        pts.push_back(kmr::kinetic::linear_trajectory<3>(X, V, bits));
      }
      Polynomial cert = kmr::geometry::orientation_value(pts[0], pts[1], pts[2], pts[3]);
      ASSERT_EQ(cert.degree(), 3);  // a cubic: det[V differences] ≠ 0 for every seeded draw (this assertion is that check)
      const int b = 10;
      for (long long kk = -32; kk < 32; ++kk) {
        Integer k(kk * 37);
        Integer value(0);  // Σ ci·k^i·2^(b(3−i)) = 2^(3b)·cert(k/2^b)
        for (int i = 3; i >= 0; --i) value = value * k + (cert[i] << (b * (3 - i)));
        ASSERT_EQ(value, det3_at(m, k, b, bits)) << "trial " << trial << " k " << kk;
      }
    }
  }
}

TEST(Trajectory, A2_3_LinearTrajectoryScalesPositionsBy2PowBlAndVelocitiesBy2PowBlMinusBv) {
  RecordProperty("claim", "A2.3-trajectories");
  // Hand-derived: the point X/2^Bℓ + (V/2^Bv)·t scaled by 2^Bℓ is X + V·2^(Bℓ−Bv)·t.
  kmr::kinetic::MotionBits bits{20, 8};
  auto c = kmr::kinetic::linear_coordinate(Integer(3), Integer(-5), bits);
  EXPECT_EQ(c, Polynomial(std::vector<Integer>{Integer(3), Integer(-5 * 4096)}));
  auto t = kmr::kinetic::linear_trajectory<2>({Integer(-7), Integer(1 << 20)}, {Integer(1), Integer(0)}, {10, 10});
  EXPECT_EQ(t[0], Polynomial(std::vector<Integer>{Integer(-7), Integer(1)}));
  EXPECT_EQ(t[1], Polynomial(std::vector<Integer>{Integer(1 << 20)}));
  // random_linear_trajectories: X in [−2^Bℓ, 2^Bℓ], V·2^(Bℓ−Bv) with V in [−2^Bv, 2^Bv], both ends
  // nearly reached, deterministic from the seed.
  for (kmr::kinetic::MotionBits mb : {kmr::kinetic::MotionBits{}, kmr::kinetic::MotionBits{6, 2}}) {
    std::mt19937_64 rng(5), rng2(5);
    auto pts = kmr::kinetic::random_linear_trajectories<3>(2000, rng, mb);
    auto again = kmr::kinetic::random_linear_trajectories<3>(2000, rng2, mb);
    EXPECT_TRUE(pts == again);
    Integer lim_x = Integer(1) << mb.position, step = Integer(1) << (mb.position - mb.velocity);
    Integer max_x(0), max_v(0), min_x(0), min_v(0);
    for (const auto& p : pts)
      for (std::size_t i = 0; i < 3; ++i) {
        Integer x = p[i].degree() >= 0 ? p[i][0] : Integer(0), v = p[i].degree() >= 1 ? p[i][1] : Integer(0);
        ASSERT_LE(p[i].degree(), 1);
        ASSERT_LE(abs(x), lim_x);
        ASSERT_EQ(v % step, 0);
        ASSERT_LE(abs(v), lim_x);  // |V|·2^(Bℓ−Bv) ≤ 2^Bℓ
        max_x = std::max(max_x, x), min_x = std::min(min_x, x), max_v = std::max(max_v, v), min_v = std::min(min_v, v);
      }
    EXPECT_GT(max_x * 100, lim_x * 99);
    EXPECT_LT(min_x * 100, -lim_x * 99);
    EXPECT_GT(max_v * 100, lim_x * 74);  // V = 2^Bv is drawn (Bv = 2: 1 in 9; 8: within 1 %)
    EXPECT_LT(min_v * 100, -lim_x * 74);
  }
}

TEST(MotionSimulator, A2_1_Orient3dFailuresAreExactlyTheSignChangesOfStaticOrient3d) {
  RecordProperty("claim", "A2.1-no-spurious");
  // Four linearly moving points, δ = 2^−10, horizon 2, 30 seeds: the simulator's failures of the orient3d
  // cubic must be exactly the lattice intervals [kδ, (k+1)δ) where the static determinant (hand-
  // expanded, det3_at) has different signs at kδ and (k+1)δ — none missed, none spurious — and the
  // outcome after each batch is the static sign at now(). No sample time is a root (asserted), so
  // sign_before equals the sign there. Across the seeds at least 20 failures must occur.
  kmr::kinetic::MotionBits bits;
  const int b = 10;
  const long long horizon_units = 2LL << b;
  long long total = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<long long> pos(-(1LL << bits.position), 1LL << bits.position);
    std::uniform_int_distribution<long long> vel(-(1LL << bits.velocity), 1LL << bits.velocity);
    std::vector<Motion3> m(4);
    std::vector<kmr::kinetic::Trajectory<3>> pts;
    for (auto& mi : m) {
      for (auto& x : mi[0]) x = pos(rng) / 64;  // start near each other so that orientations flip soon
      for (auto& v : mi[1]) v = vel(rng);
      pts.push_back(kmr::kinetic::linear_trajectory<3>({Integer(mi[0][0]), Integer(mi[0][1]), Integer(mi[0][2])},
                                                      {Integer(mi[1][0]), Integer(mi[1][1]), Integer(mi[1][2])}, bits));
    }
    Polynomial cert = kmr::geometry::orientation_value(pts[0], pts[1], pts[2], pts[3]);
    std::vector<long long> expected;
    int prev = det3_at(m, Integer(0), b, bits).sign();
    ASSERT_NE(prev, 0);
    for (long long k = 0; k < horizon_units; ++k) {
      int next = det3_at(m, Integer(k + 1), b, bits).sign();
      ASSERT_NE(next, 0) << "seed " << seed << ": a root on the lattice; pick another seed";
      if (next != prev) expected.push_back(k);
      prev = next;
    }
    MotionSimulator sim(b, Dyadic(Integer(horizon_units), -b));
    auto id = sim.add(cert);
    EXPECT_EQ(sim.outcome(id), det3_at(m, Integer(0), b, bits).sign());
    std::vector<long long> seen;
    while (auto batch = sim.next_batch(sim.horizon())) {
      Integer end = sim.now().shifted(b).floor();
      seen.push_back(static_cast<long long>(end) - 1);
      EXPECT_EQ(sim.outcome(id), det3_at(m, end, b, bits).sign());
    }
    EXPECT_EQ(seen, expected) << "seed " << seed;
    total += static_cast<long long>(expected.size());
  }
  EXPECT_GE(total, 20);
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

// §5 of issue 13: kinetic sorting against exact enumeration of crossing times, at any scale. Default
// (ctest): n = 200 points, ~10^4 events. Campaign: KMR_KINETIC_POINTS=2020 (1 013 391 events), see README.
// n random linear motions (x0 ∈ ±2^20, distinct v ∈ ±2^12), δ = 2^−10, horizon 2^22 (after every
// crossing). The crossing interval of every pair, floor(−Δx/Δv·2^10), is enumerated exactly (integer
// division, no poly code). Judged: the batch intervals are exactly the intervals holding ≥ 1 crossing
// (none missed, none spurious, in time order); a batch never has more events than its interval has
// crossings, and exactly 1 when it has 1 (that pair is adjacent just before: any point between would
// cross one of them in the same interval); the order equals the exact sort at now() after the first
// 64 batches, every 4096th and the last. Figures: events, batches, multi-crossing intervals.
TEST(KineticSortCampaign, A2_1_EventsMatchExactCrossingIntervals) {
  RecordProperty("claim", "A2.1-events-equal-crossings");
  std::size_t n = 200;
  if (const char* e = std::getenv("KMR_KINETIC_POINTS")) n = std::stoul(e);
  std::mt19937_64 rng(2012);
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 12), 1LL << 12);
  std::vector<std::pair<long long, long long>> pts;
  std::set<long long> vs;
  while (pts.size() < n) {
    long long v = vel(rng);
    if (vs.insert(v).second) pts.push_back({pos(rng), v});
  }
  const int bits = 10;
  const Dyadic horizon = Dyadic::pow2(22);
  std::map<long long, long long> crossings;  // interval k → pairs crossing in it
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      long long dx = pts[j].first - pts[i].first, dv = pts[j].second - pts[i].second;
      // i, j cross at c = −dx/dv; c = 0 counts too (the order just before 0 is the start order).
      if (dv == 0) continue;
      long long num = -dx << bits, den = dv;
      if (den < 0) num = -num, den = -den;
      if (num < 0) continue;  // crossed before 0
      long long k = num / den;  // floor (num ≥ 0)
      ++crossings[k];
    }
  std::vector<Polynomial> positions;
  for (auto [x0, v] : pts) positions.emplace_back(std::vector<Integer>{Integer(x0), Integer(v)});
  MotionSimulator sim(bits, horizon);
  kmr::kinetic::KineticSort sort(positions, sim);
  auto exact_order = [&](const Dyadic& t) {
    std::vector<std::size_t> idx(n);
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
      Dyadic pa = Dyadic(pts[a].first) + Dyadic(pts[a].second) * t, pb = Dyadic(pts[b].first) + Dyadic(pts[b].second) * t;
      if (pa != pb) return pa < pb;
      return pts[a].second > pts[b].second;
    });
    return idx;
  };
  ASSERT_EQ(sort.order(), exact_order(Dyadic(0)));
  auto expected = crossings.begin();
  long long batches = 0, multi = 0;
  while (auto batch = sim.next_batch(horizon)) {
    long long k = static_cast<long long>(sim.now().shifted(bits).floor()) - 1;
    ASSERT_TRUE(expected != crossings.end()) << "spurious batch at k = " << k;
    ASSERT_EQ(k, expected->first) << "batch interval differs from the next crossing interval (missed or spurious)";
    auto size = static_cast<long long>(batch->size());
    ASSERT_LE(size, expected->second) << "k = " << k;
    if (expected->second == 1) ASSERT_EQ(size, 1) << "k = " << k;
    if (expected->second > 1) ++multi;
    ++expected;
    sort.update(*batch);
    ++batches;
    if (batches <= 64 || batches % 4096 == 0) ASSERT_EQ(sort.order(), exact_order(sim.now())) << "after batch " << batches;
  }
  EXPECT_TRUE(expected == crossings.end()) << "crossing interval " << expected->first << " never processed";
  EXPECT_EQ(sort.order(), exact_order(sim.now()));
  EXPECT_EQ(sort.order(), exact_order(horizon));
  RecordProperty("events", std::to_string(sim.counters().events));
  std::printf("kinetic campaign: n = %zu, events = %lld, batches = %lld, intervals with > 1 crossing = %lld\n", n,
              sim.counters().events, batches, multi);
  EXPECT_GE(sim.counters().events, static_cast<long long>(n * n / 8));
}
