// CGAL judges the kinetic hull (C2.2-hull-correct) at sampled batches: the kinetic hull after a
// batch is the hull just before now, i.e. the hull at every time of (now − ε, now) for some ε > 0;
// CGAL's convex_hull_3 (exact predicates) of the positions at the dyadic times now − δ·2^-j,
// j = 1, 2, …, 40, must agree with it for some j (a wrong kinetic hull agrees with none, since
// for small enough ε the hull on (now − ε, now) is constant). Coordinates are small integers, so
// the positions at these times are exact doubles (checked).
#include <gtest/gtest.h>

#include <random>

#include "cgal_hull.hpp"
#include "hull/kinetic_hull.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::hull::KineticHull;
using kmr::hull::MovingPoint;
using kmr::hull::linear;
using kmr::poly::Polynomial;

// "" if CGAL's hull at some now − δ·2^-j equals the kinetic hull; else the last difference.
std::string judge(const KineticHull& kh, const Dyadic& now, int bits) {
  std::string last;
  for (int j = 1; j <= 40; ++j) {
    const Dyadic t = now - Dyadic::pow2(-(bits + j));
    std::vector<kmr_oracle::Pt> pos;
    for (const MovingPoint& p : kh.points()) {
      auto q = kmr::hull::position_at(p, t);
      kmr_oracle::Pt d{q[0].to_double(), q[1].to_double(), q[2].to_double()};
      for (int k = 0; k < 3; ++k)
        if (!(Dyadic::from_double(d[k]) == q[k])) return "a position is not an exact double (test set-up)";
      pos.push_back(d);
    }
    last = kmr_oracle::compare_with_cgal(pos, kh.vertices(), kh.facets());
    if (last.empty()) return "";
  }
  return last;
}

TEST(KineticHullOracle, C2_2_hull_correct_CgalAtSampledBatches) {
  ::testing::Test::RecordProperty("claim", "C2.2-hull-correct");
  long long judged = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<long long> pos(-512, 512), vel(-32, 32);
    std::vector<MovingPoint> pts;
    for (int i = 0; i < 30; ++i) pts.push_back(linear(pos(rng), pos(rng), pos(rng), vel(rng), vel(rng), vel(rng)));
    // A degenerate start too: seed 3 puts every point on z = 0 at t = 0.
    if (seed == 3)
      for (auto& p : pts) p[2] = Polynomial(std::vector<Integer>{Integer(0), p[2].degree() >= 1 ? p[2][1] : Integer(1)});
    const int bits = 4;
    const Dyadic until(32);
    kmr::kinetic::MotionSimulator sim(bits, until);
    KineticHull kh(pts, sim, seed);
    EXPECT_EQ(judge(kh, sim.now(), bits), "") << "initial run";
    long long batch = 0;
    while (auto b = sim.next_batch(until)) {
      kh.update(*b);
      if (++batch % 5 == 0) {
        EXPECT_EQ(judge(kh, sim.now(), bits), "") << "seed " << seed << ", batch " << batch << ", t = " << sim.now().to_decimal();
        ++judged;
      }
    }
  }
  EXPECT_GT(judged, 10);
}

}  // namespace
