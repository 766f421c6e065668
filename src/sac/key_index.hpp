#pragma once
// KeyIndex: the runtime's exact-key index of memo and allocation nodes whose key names no
// modifiable (issue 8 §2: an O(1) index for memo and allocation lookups, as CEAL's runtime keeps).
// Guarantees (tested in tests/sac/key_index_test.cpp):
//  * a multiset of (64-bit key hash, node) entries: insert, erase of one exact entry, and a visit
//    of every entry stored under a hash, each O(1) expected at load ≤ 1/2;
//  * a visit reads only the slots' stored hashes and hands over the nodes whose hash is equal: the
//    caller compares the full key (label and key tuple) in the node, so colliding keys stay
//    distinct; unequal hashes never touch a node (one cache line per lookup, where the chained
//    table it replaces loaded every trace node on the bucket's chain);
//  * the order in which matches are visited is unspecified: callers choose among them by trace time
//    only (the earliest in the window), so no result depends on slot or pointer order.
// Open addressing, linear probing, backward-shift deletion (no tombstones); the table doubles at
// load 1/2.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace kmr::sac {

class KeyIndex {
 public:
  explicit KeyIndex(std::size_t capacity = 1024) : slots_(round_up(capacity)), mask_(slots_.size() - 1) {}

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return slots_.size(); }
  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot); }

  void insert(std::uint64_t h, void* node) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    place(h, node);
    ++size_;
  }
  // Removes the entry (h, node); false if it is not there.
  bool erase(std::uint64_t h, void* node) {
    std::size_t i = home(h);
    for (;; i = (i + 1) & mask_) {
      if (!slots_[i].node) return false;
      if (slots_[i].node == node) break;
    }
    // Backward shift: move later entries of the run into the hole when their home allows it.
    for (std::size_t j = (i + 1) & mask_;; j = (j + 1) & mask_) {
      if (!slots_[j].node) break;
      std::size_t k = home(slots_[j].hash);
      // Entry j may fill hole i iff its home k is not cyclically in (i, j].
      bool stays = i <= j ? (i < k && k <= j) : (i < k || k <= j);
      if (stays) continue;
      slots_[i] = slots_[j];
      i = j;
    }
    slots_[i] = Slot{};
    --size_;
    return true;
  }
  // f(node) for every entry stored under h (f returns nothing; entries are not changed meanwhile).
  template <class F>
  void for_each(std::uint64_t h, F&& f) const {
    for (std::size_t i = home(h);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (!s.node) return;
      if (s.hash == h) f(s.node);
    }
  }

 private:
  struct Slot {
    std::uint64_t hash = 0;
    void* node = nullptr;  // null: empty
  };
  static std::size_t round_up(std::size_t c) {
    std::size_t s = 16;
    while (s < c) s *= 2;
    return s;
  }
  std::size_t home(std::uint64_t h) const { return static_cast<std::size_t>(h ^ (h >> 32)) & mask_; }
  void place(std::uint64_t h, void* node) {
    std::size_t i = home(h);
    while (slots_[i].node) i = (i + 1) & mask_;
    slots_[i] = Slot{h, node};
  }
  void grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    mask_ = slots_.size() - 1;
    for (const Slot& s : old)
      if (s.node) place(s.hash, s.node);
  }

  std::vector<Slot> slots_;
  std::size_t mask_;
  std::size_t size_ = 0;
};

}  // namespace kmr::sac
