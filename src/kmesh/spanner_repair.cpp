// Dynamic and kinetic maintenance of the deformable spanner (§4.1.2, after Gao–Guibas–Nguyen):
// insertion of a point, Remove (the thesis's name, Fig. 4.5) with the repair of the orphaned kids by
// re-parenting or promotion, and the kinetic repair of a batch by detaching and re-inserting the
// vertices of its failed certificates. The invariants S1–S4 of kmesh/spanner.hpp hold after each.
//
// Why the searches are complete (the invariant every step rests on): every ℓ-center w with
// top(w) = ℓ is either *floating* (an orphan being repaired, listed explicitly) or a kid of its
// parent, an (ℓ+1)-center within 2^(ℓ+1) of w (S2, S4). So an ℓ-center within c·2^ℓ of p is an
// (ℓ+1)-center within c·2^(ℓ+1) of p, a floating vertex, or a kid of an (ℓ+1)-center within
// (c + 2)·2^ℓ ≤ c·2^(ℓ+1) of p: descend() finds every one from the root's list, rank by rank.
#include <algorithm>
#include <set>

#include "exact/error.hpp"
#include "kmesh/spanner.hpp"

namespace kmr::kmesh {
namespace {

void sorted_erase(std::vector<int>& v, int x) {
  auto it = std::lower_bound(v.begin(), v.end(), x);
  KMR_CHECK(it != v.end() && *it == x, "spanner repair: a neighbour list misses an entry");
  v.erase(it);
}

}  // namespace

// All ℓ-centers within c·2^ℓ of p, by a descent from the root; `floating` are centers without a
// parent (other than the root), which no kids list reaches.
std::vector<int> Spanner::descend(const Point2& p, Rank l, const std::vector<int>& floating) const {
  IPoint pe = enclose(p);
  std::vector<int> L;
  if (within_filtered(p, pe, nodes_[root_].p, nodes_[root_].e, kC, top_rank_)) L.push_back(root_);
  for (Rank r = top_rank_ - 1; r >= l; --r) {
    std::vector<int> above = L;
    for (int z : floating)
      if (nodes_[z].top >= r + 1) above.push_back(z);
    L = centers_near_below(p, r, above);
    for (int z : floating) {
      ++ops;
      if (nodes_[z].top == r && within_filtered(p, pe, nodes_[z].p, nodes_[z].e, kC, r)) L.push_back(z);
    }
    std::sort(L.begin(), L.end());
    L.erase(std::unique(L.begin(), L.end()), L.end());
  }
  return L;
}

void Spanner::raise_root() {
  ++nodes_[root_].top;
  ++top_rank_;
}

int Spanner::insert_point(const Point2& p, int reuse) {
  KMR_CHECK(alive_count_ >= 1, "insert_point into an empty spanner");
  // Every vertex stays within 2^(top−3) of the root, so the root's list at the top rank is complete.
  while (!within(p, nodes_[root_].p, 1, top_rank_ - 3)) raise_root();
  IPoint pe = enclose(p);
  std::map<Rank, std::vector<int>> L;
  L[top_rank_] = {root_};
  Rank covered = top_rank_;  // the lowest rank with a center within 2^rank of p
  for (Rank r = top_rank_ - 1;; --r) {
    L[r] = centers_near_below(p, r, L[r + 1]);
    if (L[r].empty()) break;
    for (int y : L[r]) {
      if (nodes_[y].p == p) throw InputError("insert of a point at the place of vertex " + std::to_string(y));
      ++ops;
      if (within_filtered(p, pe, nodes_[y].p, nodes_[y].e, 1, r)) covered = r;
    }
  }
  int parent = -1;
  for (int y : L[covered]) {  // sorted: ties keep the smaller id
    ++ops;
    if (!within_filtered(p, pe, nodes_[y].p, nodes_[y].e, 1, covered)) continue;
    if (parent < 0 || compare_distance(p, pe, nodes_[y].p, nodes_[y].e, nodes_[parent].p, nodes_[parent].e) < 0)
      parent = y;
  }
  KMR_CHECK(parent >= 0, "insert_point: no covering center");
  int id = reuse;
  if (id < 0) {
    id = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
  } else {
    KMR_CHECK(!nodes_[id].alive, "insert_point: reuse of a live id");
  }
  nodes_[id] = Node{p, pe, covered - 1, parent, {}, {}};
  ++alive_count_;
  for (auto& [r, list] : L)
    if (r <= covered - 1)
      for (int y : list) add_neighbor_pair(id, y, r);
  add_kid(parent, covered - 1, id);
  return id;
}

// Takes the vertices xs out of every list; returns their orphaned kids (not in xs). If the root
// goes, the live vertex of highest top (smallest id) becomes the root: its parent is gone too.
std::vector<int> Spanner::detach(const std::vector<int>& xs) {
  std::set<int> gone(xs.begin(), xs.end());
  KMR_CHECK(gone.size() < alive_count_, "spanner: removal of every vertex");
  for (int x : gone) {
    KMR_CHECK(nodes_[x].alive, "spanner: removal of a dead vertex");
    if (nodes_[x].parent >= 0 && !gone.count(nodes_[x].parent)) remove_kid(nodes_[x].parent, nodes_[x].top, x);
  }
  for (int x : gone)
    for (auto& [r, list] : nodes_[x].nbrs)
      for (int y : list)
        if (!gone.count(y)) {
          ++ops;
          auto& ly = nodes_[y].nbrs[r];
          sorted_erase(ly, x);
          touched.push_back(y);
          if (ly.empty()) nodes_[y].nbrs.erase(r);
        }
  std::vector<int> orphans;
  for (int x : gone) {
    for (auto& [r, list] : nodes_[x].kids)
      for (int y : list)
        if (!gone.count(y)) nodes_[y].parent = -1, orphans.push_back(y);
    nodes_[x].nbrs.clear();
    nodes_[x].kids.clear();
    nodes_[x].parent = -1;
    nodes_[x].alive = false;
    --alive_count_;
  }
  if (gone.count(root_)) {
    int best = -1;
    for (int y : orphans)
      if (best < 0 || nodes_[y].top > nodes_[best].top || (nodes_[y].top == nodes_[best].top && y < best)) best = y;
    KMR_CHECK(best >= 0, "spanner: no vertex to become the root");
    root_ = best;
    nodes_[best].top = top_rank_;
    orphans.erase(std::find(orphans.begin(), orphans.end(), best));
    // Every vertex was within 2^(top−3) of the old root, so within 2^(top+1) of the new one.
    for (int i = 0; i < 4; ++i) raise_root();
  }
  std::sort(orphans.begin(), orphans.end());
  return orphans;
}

// Bottom-up: an orphan y with top k takes the nearest (k+1)-center within 2^(k+1) as its parent; if
// there is none it is promoted to rank k+1 (no (k+1)-center within 2^(k+1): separation holds) with
// the (k+1)-centers within c·2^(k+1) as neighbours, and is an orphan there.
void Spanner::repair_orphans(std::vector<int> orphans) {
  std::set<std::pair<Rank, int>> queue;
  for (int y : orphans) queue.insert({nodes_[y].top, y});
  while (!queue.empty()) {
    auto [k, y] = *queue.begin();
    queue.erase(queue.begin());
    std::vector<int> floating;
    for (auto& [kk, z] : queue) floating.push_back(z);
    floating.push_back(y);
    std::vector<int> C = descend(nodes_[y].p, k + 1, floating);
    int parent = -1;
    for (int z : C) {
      ++ops;
      if (z == y || !within_filtered(nodes_[y].p, nodes_[y].e, nodes_[z].p, nodes_[z].e, 1, k + 1)) continue;
      if (parent < 0 ||
          compare_distance(nodes_[y].p, nodes_[y].e, nodes_[z].p, nodes_[z].e, nodes_[parent].p, nodes_[parent].e) < 0)
        parent = z;
    }
    if (parent >= 0) {
      nodes_[y].parent = parent;
      add_kid(parent, k, y);
      continue;
    }
    while (top_rank_ <= k + 1) raise_root();
    nodes_[y].top = k + 1;
    for (int z : C)
      if (z != y) add_neighbor_pair(y, z, k + 1);
    queue.insert({k + 1, y});
  }
}

Spanner Spanner::compacted(const std::vector<int>& new_id) const {
  Spanner s;
  s.top_rank_ = top_rank_;
  s.lambda_ = lambda_;
  s.root_ = new_id[root_];
  s.alive_count_ = alive_count_;
  s.nodes_.resize(alive_count_);
  auto remap = [&](const std::vector<int>& v) {
    std::vector<int> out;
    for (int y : v) out.push_back(new_id[y]);
    std::sort(out.begin(), out.end());
    return out;
  };
  for (std::size_t x = 0; x < nodes_.size(); ++x) {
    if (!nodes_[x].alive) continue;
    Node& d = s.nodes_[new_id[x]];
    d.p = nodes_[x].p;
    d.e = nodes_[x].e;
    d.top = nodes_[x].top;
    d.parent = nodes_[x].parent < 0 ? -1 : new_id[nodes_[x].parent];
    for (auto& [r, v] : nodes_[x].nbrs) d.nbrs[r] = remap(v);
    for (auto& [r, v] : nodes_[x].kids)
      if (!v.empty()) d.kids[r] = remap(v);
  }
  return s;
}

void Spanner::remove(int x) { repair_orphans(detach({x})); }

void Spanner::relocate(const std::vector<int>& xs, const std::vector<Point2>& positions) {
  KMR_CHECK(xs.size() == positions.size(), "relocate: one position per vertex");
  std::vector<std::pair<int, Point2>> order;
  for (std::size_t i = 0; i < xs.size(); ++i) order.push_back({xs[i], positions[i]});
  std::sort(order.begin(), order.end(), [](auto& a, auto& b) { return a.first < b.first; });
  order.erase(std::unique(order.begin(), order.end(), [](auto& a, auto& b) { return a.first == b.first; }), order.end());
  if (order.size() == alive_count_) {  // everything moves: nothing to keep
    std::vector<int> ids;
    for (auto& [x, p] : order) ids.push_back(x);
    int keep = ids.front();
    ids.erase(ids.begin());
    repair_orphans(detach(ids));
    // keep is now the only vertex, the root; it may move freely.
    nodes_[keep].p = order.front().second;
    nodes_[keep].e = enclose(nodes_[keep].p);
    order.erase(order.begin());
  } else {
    std::vector<int> ids;
    for (auto& [x, p] : order) ids.push_back(x);
    repair_orphans(detach(ids));
  }
  for (auto& [x, p] : order) insert_point(p, x);
}

}  // namespace kmr::kmesh
