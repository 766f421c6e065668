// WellSpacedSet<D>: the public API over the parts in impl/ (impl/state.hpp lists them), and the
// exact brute-force checks. See well_spaced_set.hpp for the guarantees and spec/wellspaced.md for
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
  for (const auto& [x, V] : impl_->vtx) out.push_back({x, V.steiner});
  return out;
}
template <std::size_t D>
std::vector<Point<D>> WellSpacedSet<D>::input() const {
  std::vector<Point<D>> out;
  for (const auto& [x, V] : impl_->vtx)
    if (!V.steiner) out.push_back(x);
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
std::vector<Point<D>> WellSpacedSet<D>::clipped_voronoi_neighbors(const Point<D>& v, std::size_t* squares_read) const {
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

// ---------- exact brute-force checks ----------
template <std::size_t D>
bool is_well_spaced(const std::vector<Point<D>>& M, double rho, std::string* why) {
  Q r2 = Q(rho) * Q(rho);
  std::vector<QPoint<D>> q;
  for (const auto& p : M) q.push_back(to_q<D>(p));
  for (std::size_t v = 0; v < M.size(); ++v) {
    std::vector<std::pair<Q, std::size_t>> byd;
    for (std::size_t u = 0; u < M.size(); ++u)
      if (u != v) byd.emplace_back(dist2(q[u], q[v]), u);
    if (byd.empty()) continue;
    std::sort(byd.begin(), byd.end());
    QPoint<D> lo, hi;
    for (std::size_t i = 0; i < D; ++i) {
      lo[i] = 0;
      hi[i] = 1;
    }
    Polytope<D> P = Polytope<D>::box(lo, hi);
    Q maxd = P.max_dist2(q[v]);
    for (auto& [d, u] : byd) {
      if (d > 4 * maxd) break;
      P.clip(bisector<D>(q[v], q[u]));
      maxd = P.max_dist2(q[v]);
    }
    if (maxd > r2 * byd.front().first) {
      if (why) *why = "vertex " + fmt_point<D>(M[v]) + " is not rho-well-spaced";
      return false;
    }
  }
  return true;
}

template <std::size_t D>
bool is_size_conforming(const std::vector<Point<D>>& N, const std::vector<Point<D>>& M, double rho, std::string* why) {
  Q c = Q(2) * Q(rho) / (Q(rho) - 1);
  Q c2 = c * c;
  std::vector<QPoint<D>> nq, mq;
  for (const auto& p : N) nq.push_back(to_q<D>(p));
  for (const auto& p : M) mq.push_back(to_q<D>(p));
  for (std::size_t v = 0; v < M.size(); ++v) {
    // lfs(v): radius of the smallest ball around v containing two input points
    Q a = -1, b = -1;
    for (const auto& x : nq) {
      Q d = dist2(x, mq[v]);
      if (a < 0 || d < a) {
        b = a;
        a = d;
      } else if (b < 0 || d < b) {
        b = d;
      }
    }
    Q nn = -1;
    for (std::size_t u = 0; u < M.size(); ++u)
      if (u != v) {
        Q d = dist2(mq[u], mq[v]);
        if (nn < 0 || d < nn) nn = d;
      }
    if (b < 0 || nn < 0) continue;
    if (c2 * nn < b) {
      if (why) *why = "vertex " + fmt_point<D>(M[v]) + " violates NN >= lfs/c";
      return false;
    }
  }
  return true;
}

template <std::size_t D>
std::vector<std::size_t> brute_clipped_voronoi_neighbors(const std::vector<Point<D>>& M, std::size_t v, double beta) {
  std::vector<QPoint<D>> q;
  for (const auto& p : M) q.push_back(to_q<D>(p));
  Q nn = -1;
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v) {
      Q d = dist2(q[u], q[v]);
      if (nn < 0 || d < nn) nn = d;
    }
  Q r2 = Q(beta) * Q(beta) * nn;
  // box far enough: [v − 8·R, v + 8·R] with R = 1 + sqrt(D) covers everything
  QPoint<D> lo, hi;
  for (std::size_t i = 0; i < D; ++i) {
    lo[i] = q[v][i] - 16;
    hi[i] = q[v][i] + 16;
  }
  Polytope<D> P = Polytope<D>::box(lo, hi);
  std::vector<int> idx(M.size(), -1);
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v) idx[u] = P.clip(bisector<D>(q[v], q[u]));
  std::vector<std::size_t> out;
  for (std::size_t u = 0; u < M.size(); ++u)
    if (u != v && P.face_within(idx[u], q[v], r2, 2 * static_cast<int>(D))) out.push_back(u);
  return out;
}

#define KMR_WS_INSTANTIATE(DIM)                                                                               \
  template class WellSpacedSet<DIM>;                                                                         \
  template bool is_well_spaced<DIM>(const std::vector<Point<DIM>>&, double, std::string*);                   \
  template bool is_size_conforming<DIM>(const std::vector<Point<DIM>>&, const std::vector<Point<DIM>>&, double, \
                                        std::string*);                                                       \
  template std::vector<std::size_t> brute_clipped_voronoi_neighbors<DIM>(const std::vector<Point<DIM>>&, std::size_t, double);
KMR_WS_INSTANTIATE(2)
KMR_WS_INSTANTIATE(3)
KMR_WS_INSTANTIATE(4)

}  // namespace kmr::wellspaced
