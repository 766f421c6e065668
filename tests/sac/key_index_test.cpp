// KeyIndex (sac/key_index.hpp): the runtime's exact-key index, checked against a reference multiset
// (std::multiset of (hash, node)) under random inserts and erases with crowded homes, equal hashes
// and wrap-around at the table's end. Seeded; the seed is printed on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sac/key_index.hpp"

using kmr::sac::KeyIndex;

namespace {

using Entry = std::pair<std::uint64_t, void*>;

std::vector<void*> visited(const KeyIndex& ix, std::uint64_t h) {
  std::vector<void*> out;
  ix.for_each(h, [&](void* p) { out.push_back(p); });
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<void*> expected(const std::multiset<Entry>& ref, std::uint64_t h) {
  std::vector<void*> out;
  for (auto it = ref.lower_bound({h, nullptr}); it != ref.end() && it->first == h; ++it) out.push_back(it->second);
  std::sort(out.begin(), out.end());
  return out;
}

// Hashes drawn from a few values whose homes coincide in a 16-slot table (low bits equal) or lie at
// its end (wrap-around), plus equal hashes: the cases linear probing and backward shift get wrong.
std::uint64_t crowded_hash(std::mt19937_64& rng) {
  static const std::uint64_t pool[] = {0x0, 0x10, 0x20, 0xf, 0x1f, 0xe, 0x100000000ULL, 0x3,
                                       0xffffffffffffffffULL, 0x7fffffff0000000fULL};
  return pool[rng() % (sizeof pool / sizeof pool[0])] + (rng() % 4 == 0 ? (rng() % 64) : 0);
}

TEST(SacKeyIndex, MatchesAReferenceMultisetUnderRandomInsertsAndErases) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    KeyIndex ix(16);
    std::multiset<Entry> ref;
    std::vector<Entry> live;
    std::uintptr_t next_node = 0x1000;
    for (int step = 0; step < 600; ++step) {
      bool insert = live.empty() || rng() % 3 != 0;
      if (insert) {
        Entry e{crowded_hash(rng), reinterpret_cast<void*>(next_node += 16)};
        ix.insert(e.first, e.second);
        ref.insert(e);
        live.push_back(e);
      } else {
        std::size_t k = rng() % live.size();
        Entry e = live[k];
        live[k] = live.back();
        live.pop_back();
        ASSERT_TRUE(ix.erase(e.first, e.second));
        ref.erase(ref.find(e));
        ASSERT_FALSE(ix.erase(e.first, e.second)) << "an erased entry is gone";
      }
      ASSERT_EQ(ix.size(), ref.size());
      ASSERT_LE(2 * ix.size(), ix.capacity()) << "load stays at most 1/2";
      for (int q = 0; q < 4; ++q) {
        std::uint64_t h = crowded_hash(rng);
        ASSERT_EQ(visited(ix, h), expected(ref, h)) << "step " << step << " hash " << h;
      }
    }
    // Every live entry is found under its own hash, and nothing else is.
    for (const Entry& e : live) ASSERT_EQ(visited(ix, e.first), expected(ref, e.first));
  }
}

TEST(SacKeyIndex, HandCase_BackwardShiftAcrossTheTableEnd) {
  KeyIndex ix(16);  // 16 slots; home = (h ^ h >> 32) & 15
  int a, b, c, d;
  ix.insert(15, &a);  // slot 15
  ix.insert(15, &b);  // wraps to slot 0
  ix.insert(0, &c);   // home 0 taken: slot 1
  ix.insert(14, &d);  // slot 14
  EXPECT_TRUE(ix.erase(15, &a));  // b moves back to 15, then c to 0
  EXPECT_EQ(visited(ix, 15), std::vector<void*>{&b});
  EXPECT_EQ(visited(ix, 0), std::vector<void*>{&c});
  EXPECT_EQ(visited(ix, 14), std::vector<void*>{&d});
  EXPECT_TRUE(ix.erase(15, &b));
  EXPECT_TRUE(visited(ix, 15).empty());
  EXPECT_EQ(visited(ix, 0), std::vector<void*>{&c});
  EXPECT_FALSE(ix.erase(0, &a));
  EXPECT_EQ(ix.size(), 2u);
}

}  // namespace
