// Properties of kinetic sorting on the lattice motion simulator (§2.1), judged independently of the
// poly layer: expected orders come from exact dyadic positions x0 + v·t, with ties at t broken by
// velocity (the order just before t), and crossing times are exact rationals.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "kinetic/kinetic_sort.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::kinetic::KineticSort;
using kmr::kinetic::MotionSimulator;
using kmr::poly::Polynomial;

namespace {

struct Motion {
  long long x0, v;
  bool operator<(const Motion& o) const { return std::tie(x0, v) < std::tie(o.x0, o.v); }
};

struct Scenario {
  std::vector<Motion> points;
  int bits;
  long long until_units;  // simulate until until_units · δ
  bool concurrent = false;
  Dyadic until() const { return Dyadic(Integer(until_units), -bits); }
};

// Uniform points, or many points through a few common meeting places (simultaneous crossings).
rc::Gen<Scenario> scenarios() {
  return rc::gen::exec([] {
    Scenario s;
    s.bits = *rc::gen::inRange(0, 12);
    bool concurrent = *rc::gen::arbitrary<bool>();
    int n = *rc::gen::inRange(1, 24);
    std::set<Motion> seen;
    for (int i = 0; i < n; ++i) {
      Motion m;
      if (concurrent) {  // through the place X at integer time T
        long long X = *rc::gen::inRange(-3, 4), T = *rc::gen::inRange(0, 6);
        m.v = *rc::gen::inRange(-6, 7);
        m.x0 = X - m.v * T;
      } else {
        m.x0 = *rc::gen::inRange(-60, 61);
        m.v = *rc::gen::inRange(-8, 9);
      }
      if (seen.insert(m).second) s.points.push_back(m);
    }
    s.until_units = *rc::gen::inRange(0, 16) << s.bits;
    s.until_units += *rc::gen::inRange(0, 4);
    s.concurrent = concurrent;
    return s;
  });
}

std::vector<Polynomial> positions(const Scenario& s) {
  std::vector<Polynomial> p;
  for (const Motion& m : s.points) p.emplace_back(std::vector<Integer>{Integer(m.x0), Integer(m.v)});
  return p;
}

// Expected order at time t: by exact position, ties by the order just before t (larger v first).
std::vector<std::size_t> expected_order(const Scenario& s, const Dyadic& t) {
  std::vector<std::size_t> idx(s.points.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  auto pos = [&](std::size_t i) { return Dyadic(s.points[i].x0) + Dyadic(s.points[i].v) * t; };
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    auto pa = pos(a), pb = pos(b);
    if (pa != pb) return pa < pb;
    return s.points[a].v > s.points[b].v;
  });
  return idx;
}

// Sign of the linear function a + b·t just before t (independent of poly::sign_before).
int linear_sign_before(const Integer& a, const Integer& b, const Dyadic& t) {
  int s = (Dyadic(a) + Dyadic(b) * t).sign();
  return s != 0 ? s : -b.sign();
}

}  // namespace

RC_GTEST_PROP(KineticSort, A2_1_OrderAfterEveryBatchEqualsExactSort, ()) {
  Scenario s = *scenarios();
  MotionSimulator sim(s.bits, s.until());
  KineticSort sort(positions(s), sim);
  RC_ASSERT(sort.order() == expected_order(s, Dyadic(0)));
  while (auto batch = sim.next_batch(s.until())) {
    // No popped event is spurious: its certificate changes sign across its interval.
    Dyadic end = sim.now(), start = end - Dyadic::pow2(-s.bits);
    for (auto id : *batch) {
      const Polynomial& p = sim.certificate(id).polynomial;
      RC_ASSERT(p.degree() == 1);
      RC_ASSERT(linear_sign_before(p[0], p[1], start) != linear_sign_before(p[0], p[1], end));
    }
    sort.update(*batch);
    RC_ASSERT(sort.order() == expected_order(s, sim.now()));
  }
  RC_ASSERT(sim.now() <= s.until());
  // Nothing left that should have happened before the end.
  if (auto k = sim.next_failure_interval()) RC_ASSERT(Dyadic(*k + 1, -s.bits) > s.until());
  RC_ASSERT(sort.order() == expected_order(s, s.until()));
  RC_CLASSIFY(s.concurrent, "points through common meeting places");
  RC_CLASSIFY(sim.counters().max_batch > 1, "simultaneous failures in one batch");
  RC_CLASSIFY(sort.swaps() > sim.counters().events, "violated certificates repaired in a batch");
}

namespace {

// Crossing intervals of every pair in [0, until), enumerated exactly (rationals, no poly code).
std::vector<Integer> crossing_intervals_of(const Scenario& s) {
  std::vector<Integer> out;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    for (std::size_t j = i + 1; j < s.points.size(); ++j) {
      Integer a(s.points[j].x0 - s.points[i].x0), b(s.points[j].v - s.points[i].v);
      if (linear_sign_before(a, b, Dyadic(0)) == linear_sign_before(a, b, s.until())) continue;
      // Crossing time c = −a/b; its lattice interval is floor(c·2^bits).
      Integer num = -a << static_cast<unsigned>(s.bits), den = b;
      if (den < 0) num = -num, den = -den;
      Integer k = num / den;
      if (k * den > num) k -= 1;
      out.push_back(k);
    }
  std::sort(out.begin(), out.end());
  return out;
}

// Scenarios on a fine lattice whose crossings are forced to be separated (every pair crossing in
// [0, until) does so in its own lattice interval) and at least one: wide positions, distinct
// velocities, resampled until separated.
rc::Gen<Scenario> separated_scenarios() {
  return rc::gen::suchThat(
      rc::gen::exec([] {
        Scenario s;
        s.bits = *rc::gen::inRange(6, 13);
        int n = *rc::gen::inRange(2, 10);
        std::set<long long> velocities;
        for (int i = 0; i < n; ++i) {
          Motion m{*rc::gen::inRange(-1000, 1001), *rc::gen::inRange(-40, 41)};
          if (velocities.insert(m.v).second) s.points.push_back(m);
        }
        s.until_units = (*rc::gen::inRange(8, 64)) << s.bits;
        return s;
      }),
      [](const Scenario& s) {
        auto c = crossing_intervals_of(s);
        return !c.empty() && std::adjacent_find(c.begin(), c.end()) == c.end();
      });
}

}  // namespace

RC_GTEST_PROP(KineticSort, A2_1_EventsEqualCrossingsOnAFineLattice, ()) {
  // Every generated case has ≥ 1 crossing and all crossings separated, so every case asserts: one
  // event per crossing, each in exactly the crossing's lattice interval, in time order.
  Scenario s = *separated_scenarios();
  std::vector<Integer> expected = crossing_intervals_of(s);
  MotionSimulator sim(s.bits, s.until());
  KineticSort sort(positions(s), sim);
  std::vector<Integer> seen;
  while (auto batch = sim.next_batch(s.until())) {
    Integer k = (sim.now().shifted(s.bits)).floor() - 1;  // the batch's interval [kδ, (k+1)δ)
    for (std::size_t e = 0; e < batch->size(); ++e) seen.push_back(k);
    sort.update(*batch);
  }
  RC_ASSERT(seen == expected);
  RC_ASSERT(sim.counters().events == static_cast<long long>(expected.size()));
  RC_ASSERT(sim.counters().max_batch <= 1);
  RC_ASSERT(sort.order() == expected_order(s, s.until()));
  RC_CLASSIFY(expected.size() >= 5, "5 or more crossings");
}
