// WellSpacedSet<D>: the public API over the parts in impl/ (impl/state.hpp lists them). The
// brute-force judges live apart, in src/wsjudge (no shared code). See well_spaced_set.hpp for the guarantees and spec/wellspaced.md for
// the design choices.
#include "wellspaced/well_spaced_set.hpp"

#include "wellspaced/impl/state.hpp"
#include "wellspaced/impl/ranks.hpp"
#include "wellspaced/impl/vertex_store.hpp"
#include "wellspaced/impl/computation_graph.hpp"
#include "wellspaced/impl/clipped_voronoi.hpp"
#include "wellspaced/impl/stable_ws.hpp"
#include "wellspaced/impl/propagate_ws.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
WellSpacedSet<D>::WellSpacedSet(const std::vector<Point<D>>& input, Params params) : impl_(std::make_unique<Impl>()) {
  impl_->set_params(params);
  impl_->construct(input);
}
template <std::size_t D>
WellSpacedSet<D>::~WellSpacedSet() = default;
template <std::size_t D>
WellSpacedSet<D>::WellSpacedSet(WellSpacedSet&&) noexcept = default;
template <std::size_t D>
WellSpacedSet<D>& WellSpacedSet<D>::operator=(WellSpacedSet&&) noexcept = default;

template <std::size_t D>
UpdateStats WellSpacedSet<D>::insert(const Point<D>& p) {
  return impl_->insert(p);
}
template <std::size_t D>
UpdateStats WellSpacedSet<D>::erase(const Point<D>& p) {
  return impl_->erase(p);
}
template <std::size_t D>
std::vector<Vertex<D>> WellSpacedSet<D>::vertices() const {
  std::vector<Vertex<D>> out;
  for (const auto& [x, V] : impl_->vtx) out.push_back({x.below(), V.steiner, x});
  return out;
}
template <std::size_t D>
std::vector<Point<D>> WellSpacedSet<D>::input() const {
  std::vector<Point<D>> out;
  for (const auto& [x, V] : impl_->vtx)
    if (!V.steiner) out.push_back(x.below());  // inputs are doubles
  return out;
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::canonical_graph() const {
  return impl_->canonical_graph();
}
template <std::size_t D>
std::vector<GraphOperation<D>> WellSpacedSet<D>::computation_graph() const {
  return impl_->computation_graph();
}
template <std::size_t D>
std::string WellSpacedSet<D>::check_internal_indexes() const {
  return impl_->check_internal_indexes();
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::tree_internal_nodes() const {
  std::vector<std::string> out;
  for (const auto& k : impl_->tree.internal_nodes()) out.push_back(k.str());
  return out;
}
template <std::size_t D>
std::vector<std::string> WellSpacedSet<D>::tree_leaves() const {
  std::vector<std::string> out;
  for (const auto& k : impl_->tree.leaves()) out.push_back(k.str());
  return out;
}
template <std::size_t D>
std::vector<VertexPoint<D>> WellSpacedSet<D>::clipped_voronoi_neighbors(const VertexPoint<D>& v, std::size_t* squares_read) const {
  if (!impl_->vtx.count(v)) throw InputError("clipped_voronoi_neighbors: " + fmt_point<D>(v) + " is not an output vertex");
  Time end;
  end.rank = std::numeric_limits<int>::max();
  auto res = impl_->clipped_voronoi_neighbors(v, end);
  if (squares_read) *squares_read = res.reads.size();
  return res.cv;
}
template <std::size_t D>
const Params& WellSpacedSet<D>::params() const {
  return impl_->params;
}
template <std::size_t D>
int WellSpacedSet<D>::kappa() const {
  return impl_->kappa;
}
template <std::size_t D>
const Stats& WellSpacedSet<D>::stats() const {
  Stats& s = impl_->stats;
  s.steiner = 0;
  for (const auto& [x, V] : impl_->vtx) s.steiner += V.steiner;
  s.ops = impl_->ops.size();
  s.squares = impl_->leaves.size();
  s.min_rank = std::numeric_limits<int>::max();
  s.max_rank = std::numeric_limits<int>::min();
  for (const auto& [k, op] : impl_->ops) {
    s.min_rank = std::min(s.min_rank, k.t.rank);
    s.max_rank = std::max(s.max_rank, k.t.rank);
  }
  return s;
}

// The measured envelope (spec/wellspaced.md, "Output-size estimate"): k_D = leaves of the tree
// per isolated input (uniform inputs), b_D = Steiner vertices per input ÷ c^{D−1} (uniform), a_D =
// vertices per graded leaf ÷ c^{D−1} (pairs 2^-10 … 2^-53 apart, the largest over β ∈ {3, 4, 8}).
double estimated_vertices(std::size_t dim, std::size_t n, std::size_t leaves, double rho) {
  KMR_CHECK(dim >= 2 && dim <= 4 && rho > 1, "estimated_vertices: D in 2..4, rho > 1");
  static constexpr double k[] = {11, 30, 88}, b[] = {0.33, 0.14, 0.03}, a[] = {0.5, 0.072, 0.012};
  const std::size_t i = dim - 2;
  // c = 2ρ/(ρ−1) (Lemma 3.3.3). Measured (2D pairs), the output grows more slowly than c^{D−1}
  // once ρ < 1.05 (c > 42): ×2.5–2.9 from ρ = 1.05 to 1 + 2^-7, ×1.2 from there to 1 + 2^-9; so
  // c counts fully up to 42 and logarithmically beyond (an envelope of those runs).
  // (2ρ/(ρ−1) written without overflow: a huge ρ is refused later, by the construction)
  const double c0 = 2 / (1 - 1 / rho), c = c0 <= 42 ? c0 : 42 * (1 + std::log(c0 / 42));
  const double graded = std::max(0.0, double(leaves) - k[i] * double(n));
  return double(n) + std::pow(c, double(dim - 1)) * (b[i] * double(n) + a[i] * graded);
}

template <std::size_t D>
OutputEstimate estimate_output(const std::vector<Point<D>>& input, double rho) {
  std::set<Point<D>> seen;
  for (std::size_t i = 0; i < input.size(); ++i) {
    validate_point<D>(input[i], "point " + std::to_string(i + 1));
    if (!seen.insert(input[i]).second) throw InputError("point " + std::to_string(i + 1) + " is a duplicate");
  }
  Quadtree<D> tree;
  tree.build(std::vector<Point<D>>(seen.begin(), seen.end()));  // QTBuild, as the construction
  OutputEstimate e;
  e.input = seen.size();
  const auto leaves = tree.leaves();
  e.leaves = leaves.size();
  for (const auto& l : leaves) e.depth = std::max(e.depth, l.level);
  e.vertices = estimated_vertices(D, e.input, e.leaves, rho);
  return e;
}

#define KMR_WS_INSTANTIATE(DIM) template class WellSpacedSet<DIM>; \
  template OutputEstimate estimate_output<DIM>(const std::vector<Point<DIM>>&, double);
KMR_WS_INSTANTIATE(2)
KMR_WS_INSTANTIATE(3)
KMR_WS_INSTANTIATE(4)

}  // namespace kmr::wellspaced
