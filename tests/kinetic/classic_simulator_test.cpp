// The classic event-at-a-time baseline (kinetic/classic_simulator.hpp) against the exact sort of
// x0 + v·t computed here and against the lattice simulator, with and without simultaneous events.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "exact/error.hpp"
#include "kinetic/classic_simulator.hpp"
#include "kinetic/kinetic_sort.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::poly::Polynomial;
using Motion = std::pair<long long, long long>;  // (x0, v)

// §2.4-style motions (velocities scaled by 2^12); with `meet`, every 5th point passes through the
// place of point 0 at t = 1/4 (exactly on a lattice point of δ = 2^-10).
std::vector<Motion> motions(int n, bool meet, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 8), 1LL << 8);
  std::vector<Motion> m;
  for (int i = 0; i < n; ++i) m.emplace_back(pos(rng), vel(rng) << 12);
  if (meet)
    for (int i = 5; i < n; i += 5) {
      long long v = m[0].second + 4 * 4096 * i;
      m[i] = {m[0].first + (m[0].second - v) / 4, v};  // x_i(1/4) = x_0(1/4); v − v0 divisible by 4
    }
  std::sort(m.begin(), m.end());
  m.erase(std::unique(m.begin(), m.end()), m.end());
  return m;
}

std::vector<std::size_t> exact_sort_just_before(const std::vector<Motion>& m, const Dyadic& t) {
  std::vector<std::size_t> idx(m.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    Dyadic pa = Dyadic(m[a].first) + Dyadic(m[a].second) * t, pb = Dyadic(m[b].first) + Dyadic(m[b].second) * t;
    return pa != pb ? pa < pb : m[a].second > m[b].second;
  });
  return idx;
}

TEST(ClassicSimulator, A2_1_EventAtATimeEqualsLatticeBatchesAndTheExactSort) {
  RecordProperty("claim", "A2.1-batching-avoids-separation");
  for (bool meet : {false, true}) {
    SCOPED_TRACE(meet ? "with a meeting point" : "generic");
    auto m = motions(150, meet, meet ? 3 : 4);
    std::vector<Polynomial> x;
    for (auto& [x0, v] : m) x.emplace_back(std::vector<Integer>{Integer(x0), Integer(v)});
    const int bits = 10;
    Dyadic horizon(Integer(1), -1);
    kmr::kinetic::ClassicKineticSort classic(x, bits, horizon);
    kmr::kinetic::MotionSimulator sim(bits, horizon);
    kmr::kinetic::KineticSort lattice(x, sim);
    long long checked = 0;
    for (long long k : {1, 2, 100, 255, 256, 257, 300, 512}) {  // 256δ = 1/4, the meeting time
      Dyadic t(Integer(k), -bits);
      classic.run_until(t);
      lattice.run_until(t);
      auto want = exact_sort_just_before(m, t);
      EXPECT_EQ(classic.order(), want) << "t = " << t.to_decimal();
      EXPECT_EQ(lattice.order(), want) << "t = " << t.to_decimal();
      EXPECT_EQ(classic.swaps(), lattice.swaps()) << "t = " << t.to_decimal();
      ++checked;
    }
    const auto& c = classic.counters();
    EXPECT_GT(c.events, 100);
    EXPECT_GT(c.bisection_steps, 0);
    if (meet) {
      EXPECT_GT(c.ties, 0);  // the simultaneous crossings at t = 1/4 needed equality
    }
    EXPECT_EQ(checked, 8);
  }
}

TEST(ClassicSimulator, RefusesNonlinearOrIdenticalMotions) {
  Polynomial t2(std::vector<Integer>{0, 0, 1}), a(std::vector<Integer>{1, 2});
  EXPECT_THROW((kmr::kinetic::ClassicKineticSort({a, t2}, 10, Dyadic(1))), kmr::InputError);
  EXPECT_THROW((kmr::kinetic::ClassicKineticSort({a, a}, 10, Dyadic(1))), kmr::InputError);
}

}  // namespace
