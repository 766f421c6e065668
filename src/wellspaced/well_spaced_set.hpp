#pragma once
// Dynamic well-spaced point sets in [0,1]^D (thesis Chapter 3): StableWS (Fig. 3.4) and its
// change propagation PropagateWS / Insert / Delete (Fig. 3.8). Public API for the CLI, the tests,
// the audit and the CGAL oracle.
//
// Guarantees (each is checked by a test in tests/wellspaced or proptests/wellspaced):
//  * Every decision is exact: input doubles convert exactly to rationals; Steiner vertices are
//    doubles where the picking region holds one, else finer dyadics (VertexPoint<D>; issue 11),
//    and vertices() reports them without rounding (Vertex::exact).
//  * Output: a ρ-well-spaced superset of the input (Vor(v) ∩ [0,1]^D inside the closed ball of
//    radius ρ·NN(v) for every vertex v) that is size-conforming with c = 2ρ/(ρ−1) (Thm 3.3.4,
//    Lemma 3.3.3).
//  * Determinism: vertices(), canonical_graph() and the quadtree depend only on the current input
//    SET and the parameters — not on input order, update history, pointers or hashes.
//  * Lemma 3.4.2: after insert/erase, vertices() equals and canonical_graph() is identical to
//    (i.e. the computation graphs are isomorphic under the labelling by vertex coordinates and
//    time, squares by corners) those of a from-scratch WellSpacedSet on the current input.
//  * Bad input (non-finite or out-of-domain coordinates, duplicates, erasing an absent point,
//    inserting a present one, points closer than the tree's depth limit, fewer than 2 input points)
//    throws kmr::InputError and leaves the object unchanged.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "wellspaced/vertex_point.hpp"

namespace kmr::wellspaced {

// Parameters ρ, β (exact dyadics: every double is one). κ and ℓ(r) are derived so that
// Lemma 3.3.12 holds: ℓ(r) = the largest power of two < ρ^r/√D, κ = ⌊1 + 6βρ√D⌋ + 1
// (so κ > 1 + 3βρ^{r+1}/ℓ(r) for every r). Documented in spec/wellspaced.md.
struct Params {
  double rho = 1.5;   // well-spacedness ratio ρ > 1
  double beta = 3.0;  // clipping ratio β > ρ
  bool exact_only = false;  // skip the interval tier (tests compare both tiers; results are equal)
  // Called during change propagation (construction and updates) about every 1024 operations with
  // the current number of vertices and of operations processed (the CLI's progress line).
  std::function<void(std::size_t vertices, std::size_t operations)> progress;
  // Test hook (issue 11 §1, Lemma 3.4.2's (I1)): when nonzero, the operations of one time bucket
  // of the propagation queue (equal time, different vertices) are processed in an order shuffled
  // with this seed instead of by vertex. Results must not change (an operation sees only what
  // was created strictly before its time).
  std::uint64_t bucket_shuffle_seed = 0;
};

// An estimate of |M| before the construction, from the input alone, for refusing runs whose
// output is out of reach (spec/wellspaced.md, "Output-size estimate"). The leaves of the balanced
// 2^D-tree are Θ(lfs) (Lemma 3.1.5), and M is size-conforming with c = 2ρ/(ρ−1) (Lemma 3.3.3), so
// |M| = O(c^D · leaves); measured, the Steiner vertices grow like c^{D−1} per input vertex and per
// graded leaf (a leaf beyond the k_D leaves an isolated input brings), so
//   |M| ≈ n + c^{D−1}·(b_D·n + a_D·graded),  graded = max(0, leaves − k_D·n),
// with a_D, b_D, k_D the measured envelope (spec/wellspaced.md gives the fit and its accuracy).
struct OutputEstimate {
  std::size_t input = 0;   // n (distinct points)
  std::size_t leaves = 0;  // leaves of the balanced 2^D-tree (QTBuild; independent of ρ, β)
  int depth = 0;           // the deepest leaf's level
  double vertices = 0;     // the estimate of |M|
};
// The estimate for n inputs whose tree has `leaves` leaves, at ρ (D = 2, 3, 4).
double estimated_vertices(std::size_t dim, std::size_t n, std::size_t leaves, double rho);
// Builds the tree of `input` (QTBuild) and estimates. InputError on bad input, as the construction;
// rho must be > 1 and finite (a precondition, as for estimated_vertices: the CLI validates it first).
template <std::size_t D>
OutputEstimate estimate_output(const std::vector<Point<D>>& input, double rho);

template <std::size_t D>
struct Vertex {
  Point<D> x;                // below(): equal to the vertex iff exact.is_double()
  bool is_steiner = false;
  VertexPoint<D> exact;      // the vertex, exactly
};

// Counts of one run (construction or the whole lifetime).
struct Stats {
  std::uint64_t dispatches = 0, fills = 0;         // executed operations
  std::uint64_t cv_calls = 0;                       // QTClippedVoronoi calls
  std::uint64_t cv_squares_total = 0, cv_squares_max = 0;  // squares read per call
  std::uint64_t cv_neighbors_max = 0;               // |CV| max
  std::uint64_t steiner_per_fill_max = 0;           // Lemma 3.3.9
  std::uint64_t steiner = 0;                        // Steiner vertices in the output
  std::uint64_t ops = 0;                            // operations in the computation graph
  std::uint64_t exact_fallbacks = 0;                // clipped-Voronoi calls and fills the interval tier could not decide
  std::uint64_t dyadic_steiner = 0;                 // Steiner vertices finer than doubles (pick step 5)
  std::uint64_t squares = 0;                        // quadtree leaves
  int min_rank = 0, max_rank = 0;
  double seconds = 0;
};

// One dynamic update (Fig. 3.8).
struct UpdateStats {
  std::uint64_t obsolete = 0;      // operations removed (Ω⊖)
  std::uint64_t fresh = 0;         // operations executed for the first time (Ω⊕)
  std::uint64_t inconsistent = 0;  // operations re-executed (Ω⊗)
  std::uint64_t steiner_inserted = 0, steiner_deleted = 0;
  std::uint64_t obsolete_squares = 0, fresh_squares = 0;
  std::uint64_t cv_squares_total = 0, cv_calls = 0;
  double seconds = 0;
  std::uint64_t touched() const { return obsolete + fresh + inconsistent; }
};

// One operation v_(t) of the computation graph (§3.2.3), t = (rank, D/F, colour), with its reads
// and out-edges. computation_graph() lists them sorted by (t, v): the graph canonical_graph()
// prints as lines, in structured form (for measurements: Lemmas 3.3.6, 3.3.15).
template <std::size_t D>
struct GraphOperation {
  struct Square {  // a square of the 2^D-tree: level and integer corner
    int level = 0;
    std::array<std::uint64_t, D> corner{};
    friend bool operator==(const Square&, const Square&) = default;
    friend auto operator<=>(const Square&, const Square&) = default;
  };
  Point<D> v{};  // below() of the vertex: exact unless a coordinate is finer than a double (then two
                 // operations' v may coincide; canonical_graph() names vertices exactly)
  int rank = 0;
  bool fill = false;          // F (else D)
  std::int64_t color = 0;     // fills only
  bool executed = false;
  bool input_dispatch = false;                        // the edge v_(0) → v_(t) (input vertex)
  std::vector<std::size_t> targets;                   // operations it enqueued (indexes), sorted
  std::vector<Square> reads;                          // squares read, sorted
  std::vector<std::pair<Point<D>, Square>> steiners;  // Steiner vertices inserted and their squares
  auto key() const { return std::make_tuple(rank, fill, color, v); }  // (t, v), as sorted
};

template <std::size_t D>
class WellSpacedSet {
 public:
  // StableWS(N). Throws InputError (naming the offending point's index) on bad input.
  explicit WellSpacedSet(const std::vector<Point<D>>& input, Params params = {});
  ~WellSpacedSet();
  WellSpacedSet(WellSpacedSet&&) noexcept;
  WellSpacedSet& operator=(WellSpacedSet&&) noexcept;

  // Insert(Q, v̂) / Delete(Q, v̂) with PropagateWS. InputError (object unchanged) on bad input.
  UpdateStats insert(const Point<D>& p);
  UpdateStats erase(const Point<D>& p);

  // Output vertices sorted lexicographically by coordinates.
  std::vector<Vertex<D>> vertices() const;
  // Current input, sorted lexicographically.
  std::vector<Point<D>> input() const;
  // Canonical form of the computation graph: sorted lines naming squares by level and integer
  // corner, operations by vertex coordinates (%a) and time (rank, D/F, color), one line per node
  // and per edge. Two graphs are isomorphic (Lemma 3.4.2) iff these vectors are equal.
  std::vector<std::string> canonical_graph() const;
  // The same graph, structured (see GraphOperation).
  std::vector<GraphOperation<D>> computation_graph() const;
  // "" if the internal indexes are consistent (readers = inverse of reads, sources = inverse of
  // targets, each vertex in the leaf locate() gives, nothing pending, adjacency caches equal the
  // tree's), else the first inconsistency found. For tests (Lemma 3.4.2 property).
  std::string check_internal_indexes() const;
  // Internal nodes of the balanced 2^D-tree as "level:k1,k2,...", sorted (tree identity).
  std::vector<std::string> tree_internal_nodes() const;
  // Squares (leaves) of the tree, same format.
  std::vector<std::string> tree_leaves() const;

  // QTClippedVoronoi(v, β) on the current output (every vertex visible): the β-clipped Voronoi
  // neighbours of output vertex v, sorted; *squares_read (if given) is the number of squares read.
  std::vector<VertexPoint<D>> clipped_voronoi_neighbors(const VertexPoint<D>& v, std::size_t* squares_read = nullptr) const;

  const Params& params() const;
  int kappa() const;
  const Stats& stats() const;  // of the construction (and counters accumulated since)

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// The exact brute-force judges of the output (is_well_spaced, is_size_conforming, the β-clipped
// Voronoi neighbours) are in src/wsjudge/brute_force.hpp: they share no code with this layer.

}  // namespace kmr::wellspaced
