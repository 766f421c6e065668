#pragma once
// Internal to src/wellspaced (included only by well_spaced_set.cpp, through the files of impl/):
// the state of WellSpacedSet<D> — the 2^D-tree and its leaves (the vertex store), the vertices,
// the computation graph (operations, their reads and the readers of each square), the queue of
// pending operations — and the declarations of the algorithm's parts, each defined in the file
// of impl/ named for its part of the thesis:
//   ranks.hpp              ranks ⌊log_ρ NN⌋, ℓ(r), colours (§3.2.1–3.2.2, Lemma 3.3.12)
//   vertex_store.hpp       vertices in the leaves of the 2^D-tree (QTInsertSteiner, §3.1.2)
//   computation_graph.hpp  operations, Enqueue, MarkReaders; the canonical form (§3.2.3)
//   clipped_voronoi.hpp    QTClippedVoronoi (Fig. 3.6, Lemma 3.2.1)
//   stable_ws.hpp          StableWS: Dispatch, Fill and the Steiner choice (Fig. 3.4)
//   propagate_ws.hpp       PropagateWS, Insert, Delete (Fig. 3.8; the invariants of Lemma 3.4.2)
#include "wellspaced/well_spaced_set.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <unordered_map>
#include <algorithm>
#include <random>
#include <bit>

#include "exact/error.hpp"
#include "wellspaced/polytope.hpp"
#include "wellspaced/quadtree.hpp"

namespace kmr::wellspaced {

namespace {

// Time of an operation (§3.2.3): (rank, D < F, color); time 0 is rank = INT_MIN.
struct Time {
  int rank = std::numeric_limits<int>::min();
  int type = 0;  // 0 dispatch, 1 fill
  std::int64_t color = 0;
  friend bool operator==(const Time&, const Time&) = default;
  friend auto operator<=>(const Time&, const Time&) = default;
  bool is_origin() const { return rank == std::numeric_limits<int>::min(); }
  std::string str() const {
    if (is_origin()) return "0";
    return std::to_string(rank) + (type ? ",F," + std::to_string(color) : std::string(",D"));
  }
};

template <std::size_t D>
std::string fmt_point(const Point<D>& x) {
  std::string s;
  char buf[64];
  for (std::size_t i = 0; i < D; ++i) {
    std::snprintf(buf, sizeof buf, "%a", x[i]);
    s += (i ? " " : "") + std::string(buf);
  }
  return s;
}

template <std::size_t D>
std::string fmt_point(const VertexPoint<D>& x) {
  if (x.is_double()) return fmt_point<D>(x.below());
  std::string s;
  for (std::size_t i = 0; i < D; ++i) s += (i ? " " : "") + x.text(i);
  return s;
}

template <std::size_t D>
void validate_point(const Point<D>& p, const std::string& where) {
  for (std::size_t i = 0; i < D; ++i) {
    if (!std::isfinite(p[i])) throw InputError(where + ": coordinate " + std::to_string(i + 1) + " is not finite");
    if (p[i] < 0.0 || p[i] > 1.0)
      throw InputError(where + ": coordinate " + std::to_string(i + 1) + " = " + std::to_string(p[i]) + " is outside [0,1]");
  }
}

}  // namespace

template <std::size_t D>
struct WellSpacedSet<D>::Impl {
  using K = Key<D>;
  using Pt = VertexPoint<D>;  // a vertex (doubles, or finer dyadics: vertex_point.hpp)
  struct OpKey {
    Time t;
    Pt v;
    friend bool operator==(const OpKey&, const OpKey&) = default;
    friend auto operator<=>(const OpKey&, const OpKey&) = default;
  };
  struct Op {
    bool input_source = false;      // edge v_(0) → this (input dispatch)
    std::vector<OpKey> sources;     // operations that enqueued this one
    bool executed = false;
    std::vector<K> reads;           // squares read (edges s → op)
    std::vector<OpKey> targets;     // operations enqueued (edges op → op)
    std::vector<Pt> steiners;       // Steiner vertices inserted (edges op → square of w)
  };
  // An operation's record in `ops`: std::map nodes do not move, so a reader list holds pointers to
  // them (an operation is erased only after undo took it off its squares' lists; issue 11 §4, ws12)
  using OpRec = std::pair<const OpKey, Op>;
  struct Vtx {
    bool steiner = false;
    Time created;
    K leaf;
  };
  struct Leaf {
    const Point<D>* input = nullptr;  // input vertices are doubles
    std::vector<Pt> verts;  // vertices (input and Steiner) inside
    std::vector<Time> born;  // born[i] = creation time of verts[i] (saves a vtx lookup per scan)
    K key;
    // cache of tree.adjacent_leaves(key), valid if adjacent_ok; the pointers stay valid while it is
    // (unordered_map nodes do not move; a vanished leaf's neighbours are all invalidated)
    std::vector<Leaf*> adjacent;
    bool adjacent_ok = false;
    std::uint64_t stamp = 0;  // the last scan that reached this square
    // the executed operations that read this square (MarkReaders' edges s → op), unordered. Kept
    // in the leaf record (ws12: was a hash map keyed by square, 8 % of a 2D run at n = 10^4): a
    // square is read only while it is a leaf, and when it stops being one its readers are all
    // queued (MarkReaders(s, 0)) and undone in the same update, so the list may go with the record.
    std::vector<OpRec*> readers;
  };

  Params params;
  Q rho2, beta2;
  int kappa = 0;
  int rmax = 0;
  Quadtree<D> tree;
  std::map<Pt, Vtx> vtx;
  std::unordered_map<K, Leaf, KeyHash<D>> leaves;
  std::uint64_t scan_stamp = 0;  // numbers the clipped-Voronoi scans (Leaf::stamp)
  std::map<OpKey, Op> ops;
  std::map<Pt, std::set<Time>> ops_by_vertex;
  std::set<OpKey> pending;
  std::map<int, Q> rho_pow2;  // ρ^{2r}
  std::map<int, IntervalNT> rho_pow2_i;  // enclosures of ρ^{2r}
  std::map<int, int> ell_exp; // ℓ(r) = 2^{ell_exp}
  Stats stats;
  UpdateStats* upd = nullptr;
  std::size_t n_input = 0;

  // ---------- parameters, ranks, colors (§3.2.1–3.2.2, Lemma 3.3.12): impl/ranks.hpp ----------
  void set_params(const Params& p);
  const Q& rpow(int r);
  int rank_of(const Q& d2);
  int rank_between(const Pt& a, const Pt& b);
  template <class NT>
  int rank_in(const NT& d2);
  const IntervalNT& rpow_i(int r);
  int ell(int r);
  std::int64_t color(const Pt& w, int r);
  void refuse_out_of_reach(int depth) const;

  // ---------- vertices and squares: impl/vertex_store.hpp ----------
  const Point<D>* leaf_input(const K& leaf) const;
  Leaf& leaf_of(const K& s);
  const std::vector<Leaf*>& adjacent_leaves(Leaf& L);
  void place(const Pt& x);
  void unplace(const Pt& x);

  // ---------- operations and the computation graph (§3.2.3): impl/computation_graph.hpp ----------
  void mark_readers(const K& s, const Time& t);  // MarkReaders(s, t)
  Op& get_op(const OpKey& k);
  void erase_op(typename std::map<OpKey, Op>::iterator it);
  void enqueue(const Pt& w, int type, int rank, const OpKey& from, Op& fromop);
  Time input_dispatch_time(const Pt& v);
  std::string check_internal_indexes() const;
  std::vector<std::string> canonical_graph() const;
  std::vector<GraphOperation<D>> computation_graph() const;

  // ---------- QTClippedVoronoi (§3.2.4, Fig. 3.6): impl/clipped_voronoi.hpp ----------
  // Every geometric decision below is made by a two-tier filter (spec/wellspaced.md, "Exactness"):
  // the tier templated on NT = IntervalNT runs first and throws Uncertain when some decision is too
  // close to call; the call is then redone with NT = Q. Both tiers make the same decisions, so the
  // results do not depend on which tier answered. Doubles only order work and prune it rigorously.
  struct CVResult {
    std::vector<K> reads;  // squares read, sorted
    std::vector<Leaf*> read_leaves;  // their leaf records, in the same order
    Pt nn{};               // a nearest visible vertex (the lexicographically least on ties)
    std::vector<Pt> cv;    // β-clipped Voronoi neighbours, sorted
  };
  static std::array<std::pair<IntervalNT, IntervalNT>, D> square_bounds(const K& s);
  static IntervalNT axis_gap(const IntervalNT& c, const IntervalNT& lo, const IntervalNT& hi);
  static double box_dist2_lower(const Pt& v, const IPoint<D>& vi, const K& s);
  // Enclosures, per vertex c of a cell C around v, of c's absolute coordinates and of |cv|².
  struct VertexBounds {
    std::array<double, D> lo, hi;
    double r_lo, r_hi;
  };
  // The certificate region of C as the scan tests it: the bounds of C's vertices (vb[j] for C.v[j]),
  // their indices by decreasing r_hi (ties: index), the vertex whose ball met the last square that
  // met the region (tried first: neighbouring squares often meet the same ball), and scratch.
  struct CertificateRegion {
    std::vector<VertexBounds> vb;
    std::vector<std::uint32_t> by_radius;
    std::uint32_t hint = 0;
    std::vector<std::uint32_t> undecided;
  };
  template <class NT>
  static bool meets_certificate_region(const Polytope<D, NT>& C, CertificateRegion& R, const Pt& v, const K& s, double d2_lower);
  // Storage reused by every clipped-Voronoi scan and fill (issue 11 §4: no allocation per call).
  // Each call starts by clearing what it uses; a call the interval tier abandons (Uncertain)
  // leaves nothing the next one reads.
  struct ScanSquare {  // a square to scan, ordered by (lower bound on its distance, key)
    double key;
    Leaf* leaf;
    bool operator>(const ScanSquare& o) const { return key != o.key ? key > o.key : leaf->key > o.leaf->key; }
  };
  struct ScanCandidate {
    double approx;   // |uv|² rounded (the clipping order)
    IntervalNT d;    // |uv|² enclosed
    Pt u;
  };
  struct ScanBuffers {
    std::vector<ScanSquare> heap;  // a binary min-heap (std::push_heap/pop_heap)
    std::vector<ScanCandidate> cand;
    std::vector<std::pair<Leaf*, double>> late;
    std::vector<int> cidx;
    std::vector<Pt> here;
    CertificateRegion region;
  };
  ScanBuffers scan_buffers;
  Polytope<D, IntervalNT> scan_cell_i, fill_cell_i;  // the scan's C and the fill's cell, per tier
  Polytope<D, Q> scan_cell_q, fill_cell_q;
  template <class NT>
  Polytope<D, NT>& scan_cell() {
    if constexpr (is_interval_v<NT>) return scan_cell_i;
    else return scan_cell_q;
  }
  template <class NT>
  Polytope<D, NT>& fill_cell() {
    if constexpr (is_interval_v<NT>) return fill_cell_i;
    else return fill_cell_q;
  }
  template <class NT>
  CVResult clipped_voronoi_tier(const Pt& v, const Time& t);
  template <class NT>
  static NT sq(double x) { return NT(x) * NT(x); }
  CVResult clipped_voronoi_neighbors(const Pt& v, const Time& t);

  // ---------- StableWS: Dispatch and Fill (Fig. 3.4): impl/stable_ws.hpp ----------
  void construct(const std::vector<Point<D>>& input);
  std::vector<Leaf*> read_leaves;  // the squares the last dispatch/fill read (process lists it as their reader)
  void dispatch(const OpKey& k, Op& op);
  template <class NT>
  Pt pick(const std::array<NT, D>& vq, const Pt& v, const Pt& nn, const NT& nn2, const Polytope<D, NT>& P);
  // Step 4 of pick (exact tier): the first double w (in ring order around p, then offsets in
  // lexicographic order) with in_region(w) among the doubles of the box of P (relative to v)
  // ∩ [v − B, v + B] ∩ [0,1]^D. complete: the rings covered that box (so a miss is a proof).
  struct Enumeration {
    std::optional<Point<D>> w;
    bool complete = false;
    std::uint64_t tried = 0;
  };
  template <class InRegion>
  static Enumeration pick_by_enumeration(const QPoint<D>& v, const std::array<Q, D>& p, const InRegion& in_region, const Polytope<D, Q>& P, double B);
  // Step 5 of pick: p rounded to finer and finer dyadic grids until in the picking region.
  template <class InRegion>
  Pt pick_dyadic(const QPoint<D>& p, double nn, const InRegion& in_region);
  template <class NT>
  static double floor_div_pow2(const NT& x, int e);
  template <class NT>
  std::vector<Pt> fill_tier(const Pt& v, const CVResult& cv);
  void fill(const OpKey& k, Op& op);

  // ---------- change propagation (Fig. 3.8): impl/propagate_ws.hpp ----------
  void undo(const OpKey& k, Op& op);
  void process(const OpKey& k);
  void propagate();
  void set_input_dispatch(const Pt& v);
  void clear_input_dispatch(const Pt& v);
  std::vector<std::pair<OpKey, Op*>> ops_of(const Pt& v);
  std::vector<Pt> apply_tree_change(const typename Quadtree<D>::Change& ch);
  void redo_input_dispatch(const Pt& u);
  UpdateStats insert(const Point<D>& p);
  UpdateStats erase(const Point<D>& p);

};

}  // namespace kmr::wellspaced
