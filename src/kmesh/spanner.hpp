#pragma once
// The deformable spanner of Gao, Guibas and Nguyen (§4.1.2) with ε = 1, c = 20, as a point-location
// structure over exact (dyadic) points.
//
// Representation. Vertex x is an ℓ-center for every rank ℓ ≤ top(x) (the thesis's maximum rank
// Λ_x); the discretization M_ℓ is {x : top(x) ≥ ℓ}. Only one vertex, the root, has top = top_rank().
// Every other vertex has a parent, a (top(x)+1)-center; kids(y, ℓ) lists the vertices x with
// top(x) = ℓ whose parent is y; neighbors(x, ℓ) lists the ℓ-centers within c·2^ℓ of x (sorted by id).
//
// Invariants (checked by brute force in kmesh/invariants.hpp and tests/kmesh/spanner_test.cpp):
//  S1 separation: two ℓ-centers are more than 2^ℓ apart;
//  S2 covering:   every vertex x other than the root is within 2^(top(x)+1) of a (top(x)+1)-center,
//                 its parent (so M_ℓ covers M_(ℓ−1) at scale 2^ℓ);
//  S3 neighbours: for every rank ℓ ≤ min(top(x), top(y)), y ∈ neighbors(x, ℓ) iff |xy| ≤ c·2^ℓ;
//  S4 pointers:   x ∈ kids(parent(x), top(x)) and nothing else is in a kids list.
// A vertex being converted may, during one rank ℓ of the construction, be an ℓ-center whose parent
// is not yet decided (pending); it is then listed in kids(proxy, ℓ) of an (ℓ+1)-center proxy within
// 5·2^ℓ of it, so that the cousin searches below still find it (spec/kmesh.md).
//
// Searches (the cousins of §4.1.2 and Lemma 4.2.2):
//  * centers_near(p, ℓ, hint): all ℓ-centers within c·2^ℓ of the point p, given an (ℓ+1)-center
//    `hint` within 15·2^ℓ of p: they are children of hint or of its (ℓ+1)-neighbours.
//  * centers_near_below(p, ℓ, above): the same at rank ℓ from the list at rank ℓ+1.
//  * centers_within(p, ℓ): the same by a descent from the root (no hint needed).
//
// Dynamic maintenance (kmesh/spanner_repair.cpp, §4.1.2 after Gao–Guibas–Nguyen), each keeping
// S1–S4 over the live vertices (tests/kmesh/spanner_repair_test.cpp, brute force after every step):
//  * insert_point(p): p joins M_ℓ for every ℓ below the lowest rank where an ℓ-center covers it
//    (within 2^ℓ); its parent is the nearest covering center (ties: smaller id);
//  * remove(x) (the thesis's Remove): x leaves every list; each orphaned kid takes the nearest
//    covering center as parent, or is promoted one rank (and is an orphan there), bottom-up;
//    removing the root makes the live vertex of highest top (smallest id) the root;
//  * relocate(X, positions): the kinetic repair of a batch: the vertices X (the ends of the failed
//    certificates) are detached together, the orphans repaired, and X re-inserted at the new
//    positions, in id order. It assumes the certificates among the other vertices still hold.
// Removed vertices keep their id (alive(x) is false) so that ids stay stable.
#include <cstdint>
#include <map>
#include <vector>

#include "kmesh/filtered.hpp"
#include "kmesh/satellites.hpp"

namespace kmr::kmesh {

using Rank = std::int64_t;
inline constexpr std::int64_t kC = 20;  // c = 4 + 16/ε with ε = 1

// Exact comparisons of |pq| with k·2^ℓ in input units: stored coordinates are kScale times the input's
// (kmesh/satellites.hpp), so the squared threshold is (k·kScale)²·4^ℓ.
Dyadic threshold2(std::int64_t k, Rank l);
bool within(const Point2& p, const Point2& q, std::int64_t k, Rank l);  // |pq| ≤ k·2^ℓ
// The smallest ℓ with |pq| ≤ k·2^ℓ (p ≠ q).
Rank min_rank_within(const Point2& p, const Point2& q, std::int64_t k);

class Spanner {
 public:
  // Operation counter (T4.2.12): distance tests and list visits made by the searches.
  mutable std::uint64_t ops = 0;

  // The static top-down construction of §4.1.2 over distinct points, in id order (ids 0..n−1).
  // The root is vertex 0; top_rank() = Λ + extra where Λ = max_w ⌈lg |v0 w|⌉.
  static Spanner build(const std::vector<Point2>& points, Rank extra_top);

  std::size_t size() const { return nodes_.size(); }
  const Point2& position(int x) const { return nodes_[x].p; }
  const IPoint& enclosure(int x) const { return nodes_[x].e; }
  Rank top(int x) const { return nodes_[x].top; }
  int parent(int x) const { return nodes_[x].parent; }
  Rank top_rank() const { return top_rank_; }
  Rank lambda() const { return lambda_; }  // Λ of the input
  int root() const { return root_; }
  bool alive(int x) const { return nodes_[x].alive; }
  std::size_t alive_count() const { return alive_count_; }
  const std::vector<int>& neighbors(int x, Rank l) const;
  const std::map<Rank, std::vector<int>>& all_neighbors(int x) const { return nodes_[x].nbrs; }
  const std::map<Rank, std::vector<int>>& all_kids(int x) const { return nodes_[x].kids; }
  const std::vector<int>& kids(int y, Rank l) const;
  // The lowest rank where x has a neighbour (its minimum rank λ_x), or top(x)+1 if none.
  Rank min_rank(int x) const;
  // The ℓ-center representing x at rank ℓ ≥ top(x)... : x itself if top(x) ≥ ℓ, else that of parent.
  int rep(int x, Rank l) const;

  std::vector<int> centers_near(const Point2& p, Rank l, int hint) const;
  std::vector<int> centers_near_below(const Point2& p, Rank l, const std::vector<int>& above) const;
  std::vector<int> centers_within(const Point2& p, Rank l) const { return descend(p, l, {}); }

  // Dynamic and kinetic maintenance (kmesh/spanner_repair.cpp).
  int insert_point(const Point2& p, int reuse = -1);  // reuse: a dead id to give it
  void remove(int x);
  void relocate(const std::vector<int>& xs, const std::vector<Point2>& positions);
  // Vertices whose neighbour lists changed since the caller last cleared it (for activation ranks).
  std::vector<int> touched;
  // The same spanner over the live vertices renumbered by new_id (−1 for a dead vertex).
  Spanner compacted(const std::vector<int>& new_id) const;

  // Insertion of a new vertex (Convert, TryToPromote): `nbrs[ℓ]` are its ℓ-neighbours for the ranks
  // it is a center at and has neighbours; top its maximum rank; parent (or −1 with a proxy while
  // pending). Returns its id.
  int insert(const Point2& p, Rank top, const std::map<Rank, std::vector<int>>& nbrs, int parent,
             int proxy);
  // Resolve a pending vertex at rank top(x): give it `parent` (an (top+1)-center).
  void set_parent(int x, int parent, int proxy);
  // Promote a pending vertex x from rank top(x) to top(x)+1 with the given neighbours there; it
  // becomes pending at the new rank with `proxy`, or gets `parent` if ≥ 0.
  void promote(int x, const std::vector<int>& nbrs, int parent, int proxy, int old_proxy);
  // Replace every position (a kinetic snapshot; the pointers are kept as they are).
  void move_to(const std::vector<Point2>& positions);

 private:
  struct Node {
    Point2 p;
    IPoint e;  // enclosure of p (kmesh/filtered.hpp)
    Rank top = 0;
    int parent = -1;
    std::map<Rank, std::vector<int>> nbrs;
    std::map<Rank, std::vector<int>> kids;
    bool alive = true;
  };
  // spanner_repair.cpp
  std::vector<int> descend(const Point2& p, Rank l, const std::vector<int>& floating) const;
  void raise_root();
  std::vector<int> detach(const std::vector<int>& xs);
  void repair_orphans(std::vector<int> orphans);
  void add_kid(int y, Rank l, int x);
  void remove_kid(int y, Rank l, int x);
  void add_neighbor_pair(int x, int y, Rank l);
  std::vector<Node> nodes_;
  Rank top_rank_ = 0, lambda_ = 0;
  int root_ = 0;
  std::size_t alive_count_ = 0;
};

}  // namespace kmr::kmesh
