// Fuzz harness (h): kinetic sorting on the lattice motion simulator (§2.1), judged after every
// batch by an exact sort written here. Input bytes give δ = 2^−b (b ≤ 8), a horizon of ≤ 64 time
// units, and ≤ 16 distinct linear motions x0 + v·t (x0, v small integers, or clustered through a few
// meeting places so that many points cross at one place and time). Checks:
//  * the initial order and the order after every batch equal the points sorted by their exact
//    position at now() (Dyadic arithmetic), ties by the order just before now() (larger v first);
//  * now() only increases and never passes the horizon; afterwards no failure is left before it;
//  * the number of events never exceeds the pairs that cross in [0, horizon) (linear motion: each
//    pair crosses at most once).
#include <algorithm>
#include <numeric>
#include <set>
#include <utility>

#include "fuzz_common.hpp"
#include "kinetic/kinetic_sort.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kmr_fuzz::ByteReader in(data, size);
  int bits = in.byte() % 9;
  bool meet = in.byte() & 1;
  long long until_units = (1 + in.byte() % 64) << bits;
  int n = 1 + in.byte() % 16;
  std::vector<std::pair<long long, long long>> pts;  // (x0, v)
  std::set<std::pair<long long, long long>> seen;
  for (int i = 0; i < n && !in.empty(); ++i) {
    long long x0, v;
    if (meet) {  // through place X at time T: x0 = X − v·T
      long long X = in.byte() % 7 - 3, T = in.byte() % 8;
      v = in.byte() % 13 - 6;
      x0 = X - v * T;
    } else {
      x0 = static_cast<long long>(in.byte()) - 128;
      v = static_cast<long long>(in.byte() % 33) - 16;
    }
    if (seen.insert({x0, v}).second) pts.push_back({x0, v});
  }
  if (pts.empty()) return 0;
  Dyadic until(Integer(until_units), -bits);
  std::vector<kmr::poly::Polynomial> positions;
  for (auto [x0, v] : pts) positions.emplace_back(std::vector<Integer>{Integer(x0), Integer(v)});
  auto expected = [&](const Dyadic& t) {
    std::vector<std::size_t> idx(pts.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
      Dyadic pa = Dyadic(pts[a].first) + Dyadic(pts[a].second) * t, pb = Dyadic(pts[b].first) + Dyadic(pts[b].second) * t;
      if (pa != pb) return pa < pb;
      return pts[a].second > pts[b].second;
    });
    return idx;
  };
  long long crossing_pairs = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      // order just before 0 vs just before `until` (position, then −v)
      auto before = [&](const Dyadic& t) {
        Dyadic d = Dyadic(pts[j].first - pts[i].first) + Dyadic(pts[j].second - pts[i].second) * t;
        return d.sign() != 0 ? d.sign() : -(pts[j].second > pts[i].second ? 1 : (pts[j].second < pts[i].second ? -1 : 0));
      };
      if (before(Dyadic(0)) != before(until)) ++crossing_pairs;
    }
  kmr::kinetic::MotionSimulator sim(bits, until);
  kmr::kinetic::KineticSort sort(positions, sim);
  FUZZ_CHECK(sort.order() == expected(Dyadic(0)), "initial order");
  Dyadic last(0);
  while (auto batch = sim.next_batch(until)) {
    FUZZ_CHECK(last < sim.now() && sim.now() <= until, "time went backwards or past the horizon");
    last = sim.now();
    sort.update(*batch);
    FUZZ_CHECK(sort.order() == expected(sim.now()), "order after the batch ending at " + sim.now().to_decimal());
  }
  if (auto k = sim.next_failure_interval()) FUZZ_CHECK(Dyadic(*k + 1, -bits) > until, "a failure left before the horizon");
  FUZZ_CHECK(sim.counters().events <= crossing_pairs, "more events than crossing pairs");
  return 0;
}
