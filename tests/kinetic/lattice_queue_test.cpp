// The simulator's bucket queue (kinetic/lattice_queue.hpp) against a std::set of live (k, id):
// random pushes inside and beyond the 1024-interval window, random deaths, whole-interval pops.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "kinetic/lattice_queue.hpp"

TEST(LatticeQueue, A2_1_PopsIntervalsInOrderLikeAnOrderedSet) {
  RecordProperty("claim", "A2.1-batch");
  using kmr::kinetic::LatticeQueue;
  std::mt19937_64 rng(5);
  LatticeQueue q;
  std::set<std::pair<std::int64_t, std::uint64_t>> reference;  // live entries
  std::set<std::uint64_t> dead;
  auto live = [&](const LatticeQueue::Entry& e) { return !dead.count(e.id); };
  std::uint64_t next_id = 0;
  long long popped = 0, far_pushes = 0;
  for (int round = 0; round < 3000; ++round) {
    int pushes = std::uniform_int_distribution<int>(0, 6)(rng);
    for (int i = 0; i < pushes; ++i) {
      bool far = std::uniform_int_distribution<int>(0, 3)(rng) == 0;
      std::int64_t k = q.now() + std::uniform_int_distribution<std::int64_t>(0, far ? 20000 : 40)(rng);
      far_pushes += k >= q.now() + LatticeQueue::kWindow;
      q.push(k, next_id);
      reference.insert({k, next_id++});
    }
    if (!reference.empty() && std::uniform_int_distribution<int>(0, 2)(rng) == 0) {  // a death
      auto it = std::next(reference.begin(), std::uniform_int_distribution<long>(0, long(reference.size()) - 1)(rng));
      dead.insert(it->second);
      reference.erase(it);
    }
    ASSERT_EQ(q.earliest_unchanged(live), reference.empty() ? std::nullopt : std::optional(reference.begin()->first));
    auto k = q.earliest(live);
    ASSERT_EQ(k, reference.empty() ? std::nullopt : std::optional(reference.begin()->first));
    if (!k || std::uniform_int_distribution<int>(0, 1)(rng)) continue;
    std::vector<std::uint64_t> got, want;
    q.pop_interval(*k, live, got);
    while (!reference.empty() && reference.begin()->first == *k) want.push_back(reference.begin()->second), reference.erase(reference.begin());
    ASSERT_EQ(got, want);
    popped += static_cast<long long>(got.size());
    q.advance(*k + 1);
    if (round % 500 == 0) q.compact(live);
  }
  EXPECT_GT(popped, 3000);
  EXPECT_GT(far_pushes, 500);
}
