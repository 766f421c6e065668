// KeyTable (hull/key_table.hpp) against std::map under random insert / erase / find / assign
// (and find-with-probe then insert-through-the-probe) sequences, every other lookup and erase given
// the key's hash by the caller (KeyTable::Hashed, as the kinetic hull passes its traceables' names): after every operation the answers agree, and periodically the whole contents (listed
// by for_each, then sorted) equal the map's. A weak hash forces long probe runs and wrap-around,
// where backward-shift deletion is exercised; the seed is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <random>

#include "exact/error.hpp"
#include "hull/key_table.hpp"

namespace kmr::hull {
namespace {

using Key = std::array<int, 5>;
struct GoodHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (int v : k) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ULL;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
struct WeakHash {  // 37 homes, the last slots of any power-of-two array: long runs that wrap
  std::size_t operator()(const Key& k) const { return ~static_cast<std::size_t>(k[1] % 37); }
};

template <class Hash>
void random_against_map(std::uint64_t seed, int ops, int key_range) {
  std::cout << "key_table_test seed " << seed << " ops " << ops << " keys " << key_range << std::endl;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> pick(0, key_range - 1), op(0, 9);
  KeyTable<Key, long long, Hash> t;
  std::map<Key, long long> m;
  auto key = [&] {
    const int x = pick(rng);
    return Key{x % 3, x, x / 7, -1, x % 11};
  };
  using Table = KeyTable<Key, long long, Hash>;
  for (int i = 0; i < ops; ++i) {
    SCOPED_TRACE("seed " + std::to_string(seed) + ", operation " + std::to_string(i));
    const Key k = key();
    const int o = op(rng);
    const bool hashed = i % 2 == 1;  // the caller's hash (Hashed) instead of the table's own
    const typename Table::Hashed h{Hash{}(k)};
    if (o < 2) {  // find with a probe, then insert through the probe when absent (else overwrite)
      typename Table::Probe probe;
      long long* v = hashed ? t.find(k, h, probe) : t.find(k, probe);
      auto it = m.find(k);
      ASSERT_EQ(v != nullptr, it != m.end());
      if (v) {
        ASSERT_EQ(*v, it->second);
        *v = i;
      } else {
        EXPECT_EQ(t.insert(k, i, probe), i);
      }
      m[k] = i;
    } else if (o < 4) {  // insert when absent, else assign
      if (m.count(k)) {
        t.assign(k, i);
      } else {
        EXPECT_EQ(t.insert(k, i), i);
      }
      m[k] = i;
    } else if (o < 8) {
      ASSERT_EQ(hashed ? t.erase(k, h) : t.erase(k), m.erase(k) == 1);
    } else {
      const long long* v = hashed ? t.find(k, h) : t.find(k);
      auto it = m.find(k);
      ASSERT_EQ(v != nullptr, it != m.end());
      if (v) {
        ASSERT_EQ(*v, it->second);
      }
    }
    ASSERT_EQ(t.size(), m.size());
    if (i % 97 == 0 || i + 1 == ops) {
      std::vector<std::pair<Key, long long>> listed;
      t.for_each([&](const Key& a, long long b) { listed.emplace_back(a, b); });
      std::sort(listed.begin(), listed.end());
      const std::vector<std::pair<Key, long long>> expected(m.begin(), m.end());
      ASSERT_EQ(listed, expected);
      for (const auto& [a, b] : m) {
        const long long* v = t.find(a);
        ASSERT_TRUE(v != nullptr);
        ASSERT_EQ(*v, b);
      }
    }
  }
}

TEST(KeyTable, RandomOperationsAgreeWithMap) {
  for (std::uint64_t seed : {1ULL, 2ULL, 2012ULL}) random_against_map<GoodHash>(seed, 20000, 3000);
}

TEST(KeyTable, CollidingHashAgreesWithMap) {  // every probe run long; erasures shift across the wrap
  for (std::uint64_t seed : {3ULL, 4ULL, 77ULL}) random_against_map<WeakHash>(seed, 6000, 400);
}

TEST(KeyTable, InsertOfPresentKeyRefusedAndClearEmpties) {
  KeyTable<Key, int, GoodHash> t;
  t.insert(Key{0, 1, 2, 3, 4}, 5);
  EXPECT_THROW(t.insert(Key{0, 1, 2, 3, 4}, 6), ContractError);
  EXPECT_FALSE(t.erase(Key{0, 1, 2, 3, 5}));
  t.clear();
  EXPECT_EQ(t.size(), 0u);
  EXPECT_EQ(t.find(Key{0, 1, 2, 3, 4}), nullptr);
  t.insert(Key{0, 1, 2, 3, 4}, 7);
  EXPECT_EQ(*t.find(Key{0, 1, 2, 3, 4}), 7);
}

// reserve(n) (issue 9: the kinetic hull reserves its initial run's certificates): the entries present
// stay, and n entries then fit without growth, so a value's address taken after the reserve holds
// while the table fills up to n (growth would move it). Hand-derived: 16 slots hold 8 entries.
TEST(KeyTable, ReserveKeepsEntriesAndMakesRoomWithoutGrowth) {
  KeyTable<Key, int, GoodHash> t;
  EXPECT_EQ(t.capacity(), 0u);
  t.insert(Key{0, 0, 0, 0, 0}, 10);
  EXPECT_EQ(t.capacity(), 8u);
  t.reserve(1000);
  EXPECT_EQ(t.capacity(), 1024u);
  const int* first = t.find(Key{0, 0, 0, 0, 0});
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(*first, 10);
  for (int i = 1; i < 1000; ++i) t.insert(Key{1, i, 0, 0, 0}, i);
  EXPECT_EQ(t.capacity(), 1024u);
  EXPECT_EQ(t.find(Key{0, 0, 0, 0, 0}), first);  // never moved
  for (int i = 1; i < 1000; ++i) ASSERT_EQ(*t.find(Key{1, i, 0, 0, 0}), i);
  t.reserve(10);  // never shrinks
  EXPECT_EQ(t.capacity(), 1024u);
}

}  // namespace
}  // namespace kmr::hull
