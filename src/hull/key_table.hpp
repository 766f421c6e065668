#pragma once
// KeyTable: a flat hash table from small fixed-size keys to values (the kinetic hull's live
// certificates and live faces, issue 9: one array instead of one heap node per entry).
//
// Guarantees (tests/hull/key_table_test.cpp, against std::map under random operations):
//  * find / insert / erase / size behave as a map's: find(k) is the value stored under k, or null;
//    insert(k, v) stores v under an absent k (refused with a ContractError if k is present);
//    find(k, probe) then insert(k, v, probe) is find(k) then insert(k, v), hashing and probing once;
//    erase(k) removes k and says whether it was there; clear() empties the table.
//  * Open addressing with linear probing in a power-of-two array, at most half full (grown by
//    doubling; each slot keeps its key's hash, so growth and deletion never rehash a key, and a
//    probe compares keys only when the hashes agree). Deletion is backward-shift: every entry after the erased slot in its
//    probe run moves back when the vacancy lies between its home slot and its slot, so no
//    tombstones exist and every key stays reachable from its home slot with no gap before it.
//  * Pointers and references to values are invalidated by insert (growth) and by erase (shifts):
//    hold keys, not pointers, across them.
//  * Iteration (for_each) visits entries in slot order, i.e. in hash order: a caller must never
//    let that order reach a result (sort what it collects). Lookups are deterministic given the
//    hash; the table never depends on addresses.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "exact/error.hpp"

namespace kmr::hull {

template <class K, class V, class Hash>
class KeyTable {
 public:
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // A key's hash computed by the caller (it must equal Hash{}(k)): find, find with a probe and erase
  // take it instead of hashing again (the kinetic hull's certificates: the runtime's allocation name).
  struct Hashed {
    std::uint64_t value;
  };
  V* find(const K& k) { return find(k, Hashed{Hash{}(k)}); }
  V* find(const K& k, Hashed hk) {
    if (slots_.empty()) return nullptr;
    const auto h = static_cast<std::uint32_t>(hk.value);
    for (std::size_t i = h & mask();; i = next(i)) {
      Slot& s = slots_[i];
      if (!s.full) return nullptr;
      if (s.hash == h && s.key == k) return &s.value;
    }
  }
  const V* find(const K& k) const { return const_cast<KeyTable*>(this)->find(k); }
  // find(k, probe) is find(k), and on a miss remembers where k would go: insert(k, v, probe) right
  // after it (no insert, erase or clear between) stores k there without hashing or probing again.
  struct Probe {
    std::uint32_t hash = 0;
    std::size_t slot = kNoSlot;
  };
  V* find(const K& k, Probe& probe) { return find(k, Hashed{Hash{}(k)}, probe); }
  V* find(const K& k, Hashed hk, Probe& probe) {
    probe = Probe{static_cast<std::uint32_t>(hk.value), kNoSlot};
    if (slots_.empty()) return nullptr;
    for (std::size_t i = probe.hash & mask();; i = next(i)) {
      Slot& s = slots_[i];
      if (!s.full) {
        probe.slot = i;
        return nullptr;
      }
      if (s.hash == probe.hash && s.key == k) return &s.value;
    }
  }
  V& insert(const K& k, V v, const Probe& probe) {
    if (probe.slot == kNoSlot || 2 * (size_ + 1) > slots_.size()) return insert(k, std::move(v));  // grows: probe anew
    KMR_CHECK(!slots_[probe.slot].full, "KeyTable::insert: a stale probe");
    slots_[probe.slot] = Slot{k, probe.hash, true, std::move(v)};
    ++size_;
    return slots_[probe.slot].value;
  }
  bool contains(const K& k) const { return find(k) != nullptr; }
  // Room for n entries without growth (the capacity only grows; no entry moves afterwards until
  // the table holds more than n).
  // One allocation of the final size (not one per doubling); an empty table gets its 16 slots.
  void reserve(std::size_t n) {
    KMR_CHECK(n <= (std::size_t{1} << 31), "KeyTable: more than 2^31 entries");
    std::size_t slots = slots_.empty() ? 16 : slots_.size();
    while (2 * n > slots) slots *= 2;
    if (slots > slots_.size()) rehash(slots);
  }
  std::size_t capacity() const { return slots_.size() / 2; }  // entries that fit without growth

  V& insert(const K& k, V v) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    const std::uint32_t h = hash(k);
    std::size_t i = h & mask();
    for (; slots_[i].full; i = next(i))
      KMR_CHECK(!(slots_[i].hash == h && slots_[i].key == k), "KeyTable::insert: the key is present");
    slots_[i] = Slot{k, h, true, std::move(v)};
    ++size_;
    return slots_[i].value;
  }
  // Stores v under k, replacing a present value.
  V& assign(const K& k, V v) {
    Probe probe;
    if (V* p = find(k, probe)) return *p = std::move(v);
    return insert(k, std::move(v), probe);
  }

  bool erase(const K& k) { return erase(k, Hashed{Hash{}(k)}); }
  bool erase(const K& k, Hashed hashed) {
    if (slots_.empty()) return false;
    const auto hk = static_cast<std::uint32_t>(hashed.value);
    std::size_t i = hk & mask();
    for (;; i = next(i)) {
      if (!slots_[i].full) return false;
      if (slots_[i].hash == hk && slots_[i].key == k) break;
    }
    // Backward shift: walk the run after the hole; an entry whose home is not cyclically in
    // (hole, j] would become unreachable behind the hole, so it moves into it.
    std::size_t hole = i;
    for (std::size_t j = next(hole); slots_[j].full; j = next(j)) {
      const std::size_t h = slots_[j].hash & mask();
      const bool stays = hole < j ? (hole < h && h <= j) : (hole < h || h <= j);
      if (stays) continue;
      slots_[hole] = std::move(slots_[j]);
      hole = j;
    }
    slots_[hole] = Slot{};
    --size_;
    return true;
  }

  void clear() {
    slots_.clear();
    size_ = 0;
  }

  // Visits (key, value) in slot order (hash order: see the header).
  template <class F>
  void for_each(F&& f) const {
    for (const Slot& s : slots_)
      if (s.full) f(s.key, s.value);
  }

 private:
  struct Slot {
    K key{};
    std::uint32_t hash = 0;  // the low 32 bits of Hash{}(key): the home is hash & mask()
    bool full = false;
    V value{};
  };
  static constexpr std::size_t kNoSlot = ~std::size_t{0};
  static std::uint32_t hash(const K& k) { return static_cast<std::uint32_t>(Hash{}(k)); }
  std::size_t mask() const { return slots_.size() - 1; }
  std::size_t next(std::size_t i) const { return (i + 1) & mask(); }
  void grow() { rehash(slots_.empty() ? 16 : 2 * slots_.size()); }
  void rehash(std::size_t size) {  // size: a power of two ≤ 2^32 (the stored hash's bits)
    KMR_CHECK(size <= (std::size_t{1} << 32), "KeyTable: more than 2^31 entries");
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(size, Slot{});
    for (Slot& s : old) {
      if (!s.full) continue;
      std::size_t i = s.hash & mask();
      while (slots_[i].full) i = next(i);
      slots_[i] = std::move(s);
    }
  }
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace kmr::hull
