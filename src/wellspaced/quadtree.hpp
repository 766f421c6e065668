#pragma once
// The minimal balanced 2^D-tree over [0,1]^D of §3.1.2 (crowding + grading over all 3^D−1
// same-size neighbours), with QTBuild, QTInsertInput and QTDeleteInput.
// Guarantees (tests/wellspaced/quadtree_test.cpp, proptests/wellspaced):
//  * internal() is the least set of cells closed under crowding (a cell with ≥ 2 inputs, or with
//    one input and another input in a same-size neighbour, is split) and grading (every neighbour of
//    an internal node exists) — computed from scratch by build(), or locally by update() after one
//    insertion or deletion; both give the same set (the tree depends only on the input set).
//  * update() touches O(log Δ) cells (the 5^D blocks around the path of v̂, Lemmas 3.1.1–3.1.4) and
//    returns the obsolete squares (old leaves that are gone) and the fresh ones.
//  * Cells are half-open [k·2^-L, (k+1)·2^-L) except the last one in each axis, which contains 1.
//  * Depth is limited to kMaxLevel; inputs needing deeper cells are refused (InputError).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "exact/error.hpp"
#include "wellspaced/vertex_point.hpp"

namespace kmr::wellspaced {

inline constexpr int kMaxLevel = 56;

template <std::size_t D>
struct Key {
  int level = 0;
  std::array<std::uint64_t, D> k{};
  friend bool operator==(const Key&, const Key&) = default;
  friend auto operator<=>(const Key&, const Key&) = default;
  Key parent() const {
    Key p{level - 1, k};
    for (auto& x : p.k) x >>= 1;
    return p;
  }
  Key child(unsigned m) const {
    Key c{level + 1, k};
    for (std::size_t i = 0; i < D; ++i) c.k[i] = 2 * k[i] + ((m >> i) & 1u);
    return c;
  }
  double side() const { return std::ldexp(1.0, -level); }
  std::string str() const {
    std::string s = std::to_string(level) + ":";
    for (std::size_t i = 0; i < D; ++i) s += (i ? "," : "") + std::to_string(k[i]);
    return s;
  }
};

template <std::size_t D>
struct KeyHash {
  std::size_t operator()(const Key<D>& key) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(key.level + 1);
    for (auto x : key.k) h = (h ^ x) * 0x100000001b3ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

template <std::size_t D>
inline std::uint64_t cell_index(double x, int level) {
  double f = std::floor(std::ldexp(x, level));
  std::uint64_t n = std::uint64_t(1) << level;
  std::uint64_t i = static_cast<std::uint64_t>(f);
  return i >= n ? n - 1 : i;
}

template <std::size_t D>
inline Key<D> cell_of(const std::array<double, D>& x, int level) {
  Key<D> c{level, {}};
  for (std::size_t i = 0; i < D; ++i) c.k[i] = cell_index<D>(x[i], level);
  return c;
}

// The cell of a vertex (exact also for coordinates finer than doubles: ⌊x·2^L⌋ of the dyadic).
template <std::size_t D>
inline Key<D> cell_of(const VertexPoint<D>& x, int level) {
  if (x.is_double()) return cell_of<D>(x.below(), level);
  Key<D> c{level, {}};
  const std::uint64_t n = std::uint64_t(1) << level;
  for (std::size_t i = 0; i < D; ++i) {
    std::uint64_t k = x.coord(i).shifted(level).floor().template convert_to<std::uint64_t>();
    c.k[i] = k >= n ? n - 1 : k;
  }
  return c;
}

template <std::size_t D>
inline bool cell_contains(const Key<D>& c, const std::array<double, D>& x) {
  return cell_of<D>(x, c.level) == c;
}

// Calls f(n) for every cell n with Chebyshev index distance ≤ radius from c (c included), in range.
template <std::size_t D, class F>
void for_block(const Key<D>& c, int radius, F&& f) {
  const std::int64_t n = std::int64_t(1) << c.level;
  std::array<std::int64_t, D> off;
  off.fill(-radius);
  while (true) {
    Key<D> m{c.level, {}};
    bool ok = true;
    for (std::size_t i = 0; i < D; ++i) {
      std::int64_t v = static_cast<std::int64_t>(c.k[i]) + off[i];
      if (v < 0 || v >= n) ok = false;
      m.k[i] = static_cast<std::uint64_t>(v);
    }
    if (ok) f(m);
    std::size_t i = 0;
    while (i < D && off[i] == radius) off[i++] = -radius;
    if (i == D) break;
    ++off[i];
  }
}

template <std::size_t D>
class Quadtree {
 public:
  using K = Key<D>;
  using Pt = std::array<double, D>;

  // QTBuild from the definition (least fixed point of crowding and grading).
  void build(const std::vector<Pt>& pts) {
    internal_.clear();
    std::vector<const Pt*> active;
    for (const auto& p : pts) active.push_back(&p);
    int L = 0;
    while (!active.empty()) {
      std::unordered_map<K, int, KeyHash<D>> cnt;
      for (auto* p : active) ++cnt[cell_of<D>(*p, L)];
      std::vector<const Pt*> next;
      bool any = false;
      for (auto* p : active) {
        K c = cell_of<D>(*p, L);
        int n = cnt[c];
        bool crowded = n >= 2;
        if (n == 1)
          for_block<D>(c, 1, [&](const K& m) {
            if (!(m == c) && cnt.count(m)) crowded = true;
          });
        if (crowded) {
          // leaves are at most at level kMaxLevel (the same condition in update())
          if (L >= kMaxLevel) throw InputError("points too close together: the 2^D-tree would exceed depth " + std::to_string(kMaxLevel));
          internal_.emplace(c, 0);
          next.push_back(p);
          any = true;
        }
      }
      if (!any) break;
      active = std::move(next);
      ++L;
    }
    // grading closure, deepest level first
    std::vector<std::vector<K>> by_level(kMaxLevel + 2);
    for (auto& [c, n] : internal_) by_level[c.level].push_back(c);
    for (int l = kMaxLevel + 1; l >= 1; --l) {
      for (std::size_t idx = 0; idx < by_level[l].size(); ++idx) {
        K s = by_level[l][idx];
        for_block<D>(s, 1, [&](const K& m) {
          K p = m.parent();
          if (internal_.emplace(p, 0).second) by_level[p.level].push_back(p);
        });
      }
    }
    for (auto& [c, n] : internal_) KMR_CHECK(c.level == 0 || internal_.count(c.parent()), "tree not closed");
    for (const auto& p : pts)
      for (int l = 0;; ++l) {
        auto it = internal_.find(cell_of<D>(p, l));
        if (it == internal_.end()) break;
        ++it->second;
      }
  }

  bool internal(const K& c) const { return internal_.count(c) > 0; }
  bool exists(const K& c) const { return c.level == 0 || internal_.count(c.parent()) > 0; }
  bool leaf(const K& c) const { return exists(c) && !internal(c); }
  std::size_t internal_count() const { return internal_.size(); }

  // The leaf containing x (a double point or a VertexPoint).
  template <class P>
  K locate(const P& x) const {
    K c{0, {}};
    while (internal(c)) c = cell_of<D>(x, c.level + 1);
    return c;
  }
  // The leaf containing cell c (c inside or equal to a leaf), or c itself if internal.
  K existing_ancestor(K c) const {
    while (!exists(c)) c = c.parent();
    return c;
  }

  std::vector<K> internal_nodes() const {
    std::vector<K> out;
    for (auto& [c, n] : internal_) out.push_back(c);
    std::sort(out.begin(), out.end());
    return out;
  }
  std::vector<K> leaves() const {
    std::vector<K> out;
    if (internal_.empty()) return {K{0, {}}};
    for (auto& [c, n] : internal_)
      for (unsigned m = 0; m < (1u << D); ++m) {
        K ch = c.child(m);
        if (!internal(ch)) out.push_back(ch);
      }
    std::sort(out.begin(), out.end());
    return out;
  }

  // Leaves adjacent to leaf s (sharing at least a point), sorted.
  std::vector<K> adjacent_leaves(const K& s) const {
    std::vector<K> out;
    for_block<D>(s, 1, [&](const K& n) {
      if (n == s) return;
      std::array<int, D> dir;
      for (std::size_t i = 0; i < D; ++i) dir[i] = n.k[i] > s.k[i] ? 1 : (n.k[i] < s.k[i] ? -1 : 0);
      if (!exists(n)) {
        out.push_back(existing_ancestor(n));
        return;
      }
      std::function<void(const K&)> down = [&](const K& c) {
        if (!internal(c)) {
          out.push_back(c);
          return;
        }
        for (unsigned m = 0; m < (1u << D); ++m) {
          bool ok = true;
          for (std::size_t i = 0; i < D; ++i) {
            unsigned bit = (m >> i) & 1u;
            if (dir[i] == 1 && bit != 0) ok = false;
            if (dir[i] == -1 && bit != 1) ok = false;
          }
          if (ok) down(c.child(m));
        }
      };
      down(n);
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // Input count of cell c, given the leaf→input lookup of the current tree.
  template <class LeafInput>
  int count(const K& c, const LeafInput& leaf_input) const {
    auto it = internal_.find(c);
    if (it != internal_.end()) return it->second;
    K a = existing_ancestor(c);
    const Pt* p = leaf_input(a);
    return (p && cell_contains<D>(c, *p)) ? 1 : 0;
  }

  struct Change {
    std::vector<K> obsolete, fresh;  // squares (leaves)
  };

  // QTInsertInput (sign = +1) or QTDeleteInput (sign = −1) of p. The current tree must represent the
  // input set before the change; leaf_input(leaf) gives the input point in a leaf (nullptr if none)
  // before the change. Throws InputError (tree unchanged) if the insertion needs too deep cells.
  template <class LeafInput>
  Change update(const Pt& p, int sign, const LeafInput& leaf_input) {
    auto cnt_new = [&](const K& c) { return count(c, leaf_input) + (cell_contains<D>(c, p) ? sign : 0); };
    auto crowded_new = [&](const K& c) {
      int n = cnt_new(c);
      if (n >= 2) return true;
      if (n <= 0) return false;
      bool any = false;
      for_block<D>(c, 1, [&](const K& m) {
        if (!any && !(m == c) && cnt_new(m) >= 1) any = true;
      });
      return any;
    };
    int lmax;
    if (sign > 0) {
      int L = 0;
      while (crowded_new(cell_of<D>(p, L))) {
        // the condition of build(): a crowded cell at level ≥ kMaxLevel would make leaves deeper
        // than kMaxLevel (test WellspacedQuadtree.DepthLimitSameForBuildAndInsert)
        if (L >= kMaxLevel) throw InputError("point too close to another: the 2^D-tree would exceed depth " + std::to_string(kMaxLevel));
        ++L;
      }
      lmax = L + 1;
    } else {
      lmax = locate(p).level + 1;
    }
    lmax = std::min(lmax, kMaxLevel + 1);
    std::unordered_map<K, bool, KeyHash<D>> now;  // new status of candidates
    auto internal_new = [&](const K& c) {
      auto it = now.find(c);
      return it != now.end() ? it->second : internal(c);
    };
    std::vector<K> changed;
    for (int L = lmax; L >= 0; --L) {
      std::vector<K> cand;
      for_block<D>(cell_of<D>(p, L), 2, [&](const K& c) { cand.push_back(c); });
      for (const K& c : cand) {
        bool in = crowded_new(c);
        if (!in && L < kMaxLevel + 1) {
          const std::int64_t n1 = std::int64_t(1) << (L + 1);
          std::array<std::int64_t, D> off;
          off.fill(-1);
          while (!in) {
            K t{L + 1, {}};
            bool ok = true;
            for (std::size_t i = 0; i < D; ++i) {
              std::int64_t v = 2 * static_cast<std::int64_t>(c.k[i]) + off[i];
              if (v < 0 || v >= n1) ok = false;
              t.k[i] = static_cast<std::uint64_t>(v);
            }
            if (ok && internal_new(t)) in = true;
            std::size_t i = 0;
            while (i < D && off[i] == 2) off[i++] = -1;
            if (i == D) break;
            ++off[i];
          }
        }
        now[c] = in;
        if (in != internal(c)) changed.push_back(c);
      }
    }
    // leaf statuses before
    std::vector<K> touched;
    for (const K& c : changed) {
      touched.push_back(c);
      for (unsigned m = 0; m < (1u << D); ++m) touched.push_back(c.child(m));
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    std::vector<char> was_leaf(touched.size());
    for (std::size_t i = 0; i < touched.size(); ++i) was_leaf[i] = leaf(touched[i]);
    // counts along the path, then apply
    for (int l = 0;; ++l) {
      auto it = internal_.find(cell_of<D>(p, l));
      if (it == internal_.end()) break;
      it->second += sign;
    }
    std::vector<std::pair<K, int>> added;
    for (const K& c : changed)
      if (now[c]) added.emplace_back(c, cnt_new(c));
    for (const K& c : changed)
      if (!now[c]) internal_.erase(c);
    for (auto& [c, n] : added) internal_.emplace(c, n);
    Change ch;
    for (std::size_t i = 0; i < touched.size(); ++i) {
      bool is_leaf = leaf(touched[i]);
      if (was_leaf[i] && !is_leaf) ch.obsolete.push_back(touched[i]);
      if (!was_leaf[i] && is_leaf) ch.fresh.push_back(touched[i]);
    }
    return ch;
  }

 private:
  std::unordered_map<K, int, KeyHash<D>> internal_;  // internal node → number of inputs inside
};

}  // namespace kmr::wellspaced
