#pragma once
// The motion simulator's event queue (§2.1: "the queue maintains nonempty intervals"), keyed by
// int64 lattice index: one bucket per index of the window [now, now + W) and a binary heap of the
// entries beyond it. Deletion is lazy: the caller's `live` predicate says which entries still count.
//
// Guarantees:
//  * earliest(live) is the smallest k of a live entry (nothing if none); it may drop dead entries.
//  * pop_interval(k, live, out) appends the ids of all live entries with index k, in increasing id
//    order, and removes every entry with index k; k must be earliest(live).
//  * push(k, id) needs k ≥ now; advance(now') needs now' > every index popped so far.
//  * A bucket holds one index only: its entries have k ∈ [now, now + W), and buckets below now are
//    empty (pop_interval and earliest empty them), so index k mod W names one k.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace kmr::kinetic {

class LatticeQueue {
 public:
  struct Entry {
    std::int64_t k;
    std::uint64_t id;
    friend bool operator>(const Entry& a, const Entry& b) { return a.k != b.k ? a.k > b.k : a.id > b.id; }
  };
  static constexpr std::int64_t kWindow = 1024;

  LatticeQueue() : buckets_(kWindow) {}

  std::int64_t now() const { return now_; }
  std::size_t size() const { return size_; }

  void push(std::int64_t k, std::uint64_t id) {
    ++size_;
    if (k < now_ + kWindow) {
      auto b = static_cast<std::size_t>(k & (kWindow - 1));
      buckets_[b].push_back({k, id});
      nonempty_[b >> 6] |= std::uint64_t{1} << (b & 63);
    } else {
      far_.push_back({k, id});
      std::push_heap(far_.begin(), far_.end(), std::greater<>{});
    }
  }

  template <class Live>
  std::optional<std::int64_t> earliest(Live&& live) {
    for (std::int64_t off = 0; off < kWindow;) {
      auto b = static_cast<std::size_t>((now_ + off) & (kWindow - 1));
      std::uint64_t word = nonempty_[b >> 6] >> (b & 63);
      if (word == 0) {
        off += 64 - static_cast<std::int64_t>(b & 63);
        continue;
      }
      off += std::countr_zero(word);
      if (off >= kWindow) break;
      b = static_cast<std::size_t>((now_ + off) & (kWindow - 1));
      auto& bucket = buckets_[b];
      if (std::any_of(bucket.begin(), bucket.end(), live)) return bucket.front().k;
      clear(b);  // only dead entries
      ++off;
    }
    while (!far_.empty() && !live(far_.front())) pop_far();
    if (far_.empty()) return std::nullopt;
    return far_.front().k;
  }

  // Without dropping anything (for const queries).
  template <class Live>
  std::optional<std::int64_t> earliest_unchanged(Live&& live) const {
    std::optional<std::int64_t> best;
    for (const auto& bucket : buckets_)
      for (const Entry& e : bucket)
        if (live(e) && (!best || e.k < *best)) best = e.k;
    if (best) return best;
    for (const Entry& e : far_)
      if (live(e) && (!best || e.k < *best)) best = e.k;
    return best;
  }

  template <class Live>
  void pop_interval(std::int64_t k, Live&& live, std::vector<std::uint64_t>& out) {
    std::size_t first = out.size();
    if (k < now_ + kWindow) {
      auto b = static_cast<std::size_t>(k & (kWindow - 1));
      for (const Entry& e : buckets_[b])
        if (live(e)) out.push_back(e.id);
      clear(b);
    } else {
      while (!far_.empty() && far_.front().k == k) {
        if (live(far_.front())) out.push_back(far_.front().id);
        pop_far();
      }
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  }

  void advance(std::int64_t now) {
    now_ = now;
    while (!far_.empty() && far_.front().k < now_ + kWindow) {
      Entry e = far_.front();
      pop_far();
      push(e.k, e.id);
    }
  }

  template <class Live>
  void compact(Live&& live) {
    size_ = 0;
    for (std::size_t b = 0; b < buckets_.size(); ++b) {
      std::erase_if(buckets_[b], [&](const Entry& e) { return !live(e); });
      if (buckets_[b].empty()) nonempty_[b >> 6] &= ~(std::uint64_t{1} << (b & 63));
      size_ += buckets_[b].size();
    }
    std::erase_if(far_, [&](const Entry& e) { return !live(e); });
    std::make_heap(far_.begin(), far_.end(), std::greater<>{});
    size_ += far_.size();
  }

 private:
  void clear(std::size_t b) {
    size_ -= buckets_[b].size();
    buckets_[b].clear();
    nonempty_[b >> 6] &= ~(std::uint64_t{1} << (b & 63));
  }
  void pop_far() {
    std::pop_heap(far_.begin(), far_.end(), std::greater<>{});
    far_.pop_back();
    --size_;
  }

  std::int64_t now_ = 0;
  std::size_t size_ = 0;
  std::vector<std::vector<Entry>> buckets_;
  std::array<std::uint64_t, kWindow / 64> nonempty_{};
  std::vector<Entry> far_;  // min-heap by (k, id)
};

}  // namespace kmr::kinetic
