// The motion simulator (§2.1) on many linear certificates c0 + c1·t, most of them removed (enough
// that the lazy queue compacts itself), some removed right after they fail (while their rescheduling
// is still deferred), judged batch by batch against brute force written here: a line's one failure
// is in lattice interval k = floor(−c0·2^b / c1) (exact integer floor division), reported iff
// now ≤ kδ and (k+1)δ ≤ horizon; outcomes are the sign just before now, from exact integers. The
// same certificates run on the machine path, the exact path, and a lattice past the machine range.
// Claim A2.1-batch (spec/claims.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include "kinetic/motion_simulator.hpp"

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::kinetic::CertificateId;
using kmr::kinetic::MotionSimulator;
using kmr::kinetic::SimulatorOptions;

namespace {

using i128 = __int128;

i128 floor_div(i128 a, i128 b) {  // b ≠ 0
  i128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

struct Line {
  std::int64_t c0, c1;
};

// The sign of c0 + c1·t just before t = n·2^-bits (n ≥ 0): the value's sign, or at a root the sign
// on its left, −sign(c1); a constant keeps its sign.
int sign_before(const Line& l, std::int64_t n, int bits) {
  i128 v = static_cast<i128>(l.c0) * (i128{1} << bits) + static_cast<i128>(l.c1) * n;
  if (v != 0) return v > 0 ? 1 : -1;
  return l.c1 > 0 ? -1 : 1;
}

// The one failure interval of a line, if it lies in [from, last).
std::optional<std::int64_t> failure(const Line& l, std::int64_t from, std::int64_t last, int bits) {
  if (l.c1 == 0) return std::nullopt;
  i128 k = floor_div(-static_cast<i128>(l.c0) * (i128{1} << bits), l.c1);
  if (k < from || k >= last) return std::nullopt;
  return static_cast<std::int64_t>(k);
}

// Runs the whole scenario on `sim` (bits, horizon index last) and checks every step by brute force.
void run_and_judge(MotionSimulator& sim, const std::vector<Line>& lines, int bits, std::int64_t last) {
  std::map<CertificateId, Line> live;
  std::vector<CertificateId> ids;
  for (const Line& l : lines) {
    CertificateId id = sim.add_linear(l.c0, l.c1);
    ids.push_back(id);
    live[id] = l;
    ASSERT_EQ(sim.outcome(id), sign_before(l, 0, bits)) << l.c0 << " + " << l.c1 << "t";
  }
  // Remove two thirds of them before any batch (their queue entries go stale; the queue compacts).
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (i % 3 != 0) {
      sim.remove(ids[i]);
      live.erase(ids[i]);
    }
  ASSERT_EQ(sim.counters().live(), static_cast<long long>(live.size()));
  std::int64_t now = 0;
  std::set<CertificateId> failed;  // a line fails at most once
  long long batches = 0, events = 0;
  for (int round = 0;; ++round) {
    // The expected next batch: the smallest interval among live unfailed lines, all its lines.
    std::optional<std::int64_t> want_k;
    std::vector<CertificateId> want;
    for (auto& [id, l] : live) {
      if (failed.count(id)) continue;
      auto k = failure(l, now, last, bits);
      if (!k) continue;
      if (!want_k || *k < *want_k) want_k = k, want.clear();
      if (*k == *want_k) want.push_back(id);
    }
    auto next = sim.next_failure_interval();
    ASSERT_EQ(next.has_value(), want_k.has_value()) << "round " << round;
    if (next) {
      ASSERT_EQ(*next, Integer(*want_k));
    }
    auto batch = sim.next_batch(sim.horizon());
    ASSERT_EQ(batch.has_value(), want_k.has_value()) << "round " << round;
    if (!batch) break;
    ASSERT_EQ(*batch, want) << "round " << round;  // ids in increasing order
    now = *want_k + 1;
    ASSERT_EQ(sim.now(), Dyadic(Integer(now), -bits));
    ++batches, events += static_cast<long long>(want.size());
    for (CertificateId id : want) failed.insert(id);
    for (auto& [id, l] : live) ASSERT_EQ(sim.outcome(id), sign_before(l, now, bits)) << "round " << round;
    // A popped certificate viewed before the next batch: flipped, no later failure (a line fails once).
    const auto& view = sim.certificate(want.front());
    EXPECT_EQ(view.outcome, sign_before(live[want.front()], now, bits));
    EXPECT_FALSE(view.failure);
    // Every fourth batch, remove the last certificate of the batch just popped (its rescheduling is
    // still deferred) and one live certificate that has not failed yet.
    if (round % 4 == 0) {
      sim.remove(want.back());
      live.erase(want.back());
      for (auto it = live.rbegin(); it != live.rend(); ++it)  // the newest: the edge lines stay
        if (!failed.count(it->first) && failure(it->second, now, last, bits)) {
          CertificateId id = it->first;
          sim.remove(id);
          live.erase(id);
          break;
        }
    }
  }
  EXPECT_GT(batches, 50);
  EXPECT_EQ(sim.counters().events, events);
  EXPECT_EQ(sim.counters().batches, batches);
  EXPECT_EQ(sim.counters().live(), static_cast<long long>(live.size()));
}

// Lines c0 + (c1·2^b)·t with roots near lattice points r·2^-b in [−8, 72]: on the point itself for
// every fifth line (c0 = −c1·r), else up to 3/(|c1|·2^b) away; c1 = 0 gives a constant (never fails).
std::vector<Line> random_lines(std::size_t n, std::uint64_t seed, int bits) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> slope(-40, 40), root(-8 << bits, 72 << bits), off(-3, 3);
  std::vector<Line> lines;
  while (lines.size() < n) {
    std::int64_t c1 = slope(rng), r = root(rng), e = lines.size() % 5 == 0 ? 0 : off(rng);
    std::int64_t c0 = -c1 * r + e;
    if (c1 == 0 && c0 == 0) continue;
    lines.push_back({c0, c1 * (std::int64_t{1} << bits)});
  }
  // Edge lines at kept positions (multiples of 3), for horizon 64 and δ = 2^-4 (last index 1024):
  const std::int64_t one = std::int64_t{1} << bits;
  lines[0] = {-64 * one, one};            // root 64 = the horizon: k = 1024, never reported
  lines[3] = {-(64 * 2 * one - 1), 2 * one};  // root 63 + 31/32: k = 1023, the last interval reported
  lines[6] = {0, 5};                      // root 0: k = 0, the first interval (outcome −1 at 0)
  lines[9] = {1, one};                    // root −1/16: k = −1, before the start, never reported
  lines[12] = {-(64 * one + 1), one};     // root 64 + 1/16: k = 1025, past the horizon
  lines[15] = {7, 0};                     // a constant: never fails
  return lines;
}

TEST(LinearBruteForce, A2_1_BatchesAndOutcomesEqualBruteForceWithRemovalsOnAllPaths) {
  RecordProperty("claim", "A2.1-batch");
  const int bits = 4;
  const auto lines = random_lines(2400, 20121, bits);
  const std::int64_t last = 64 << bits;  // horizon 64
  {
    MotionSimulator machine(bits, Dyadic(64));
    run_and_judge(machine, lines, bits, last);
    EXPECT_GT(machine.counters().filter_decided + machine.counters().filter_fallbacks, 0);
    EXPECT_EQ(machine.counters().exact_certificates, 0);
  }
  {
    SimulatorOptions exact;
    exact.machine_fast_path = false;
    MotionSimulator sim(bits, Dyadic(64), exact);
    run_and_judge(sim, lines, bits, last);
    EXPECT_EQ(sim.counters().exact_certificates, 2400);
  }
}

// A lattice past the machine range (horizon index 2^66): the exact (interval, id) set, the same answers.
TEST(LinearBruteForce, A2_1_TheSameOnALatticePastTheMachineRange) {
  RecordProperty("claim", "A2.1-batch");
  const int bits = 4;
  const auto lines = random_lines(600, 7, bits);
  MotionSimulator sim(bits, Dyadic::pow2(62));
  ASSERT_FALSE(sim.now_index());
  // Every interval the lines can fail in is far below the horizon index: use the int64 bound 2^62.
  run_and_judge(sim, lines, bits, std::int64_t{1} << 62);
}

}  // namespace
