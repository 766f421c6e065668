#pragma once
// Measurements shared by bench/wellspaced, the tests and the audit: update-cost sampling, the
// operations of a computation graph that changed in an update, exact nearest-neighbour distances
// and the geometric spread.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "exact/dyadic.hpp"
#include "geometry/point.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace kmr::wellspaced {

struct UpdateSample {
  double mean_seconds = 0;   // per insertion or deletion
  double mean_touched = 0;   // obsolete + fresh + inconsistent operations per update
  std::uint64_t updates = 0;
};

// Inserts and then erases each extra point (the input is unchanged afterwards) and returns the mean
// time and operations per update.
template <std::size_t D>
UpdateSample sample_updates(WellSpacedSet<D>& ws, const std::vector<Point<D>>& extra) {
  UpdateSample s;
  double seconds = 0;
  std::uint64_t touched = 0;
  for (const auto& p : extra) {
    for (const UpdateStats& u : {ws.insert(p), ws.erase(p)}) {
      seconds += u.seconds;
      touched += u.touched();
      ++s.updates;
    }
  }
  if (s.updates) {
    s.mean_seconds = seconds / double(s.updates);
    s.mean_touched = double(touched) / double(s.updates);
  }
  return s;
}

// ---------- the computation graph (structured: WellSpacedSet::computation_graph()) ----------

// The vertices of the operations named by a line of canonical form that graph a has and graph b
// has not (both sorted as computation_graph() returns them): an operation absent from b or whose
// executed flag differs, the input edge v_(0) → it, an edge op → op (both ends), a read, a Steiner
// vertex with its square (Lemma 3.3.15's M̂ for a = G, b = G′; M̂′ for a = G′, b = G).
template <std::size_t D>
std::set<Point<D>> vertices_of_changed_operations(const std::vector<GraphOperation<D>>& a,
                                                  const std::vector<GraphOperation<D>>& b) {
  std::map<decltype(a[0].key()), std::size_t> in_b;
  for (std::size_t j = 0; j < b.size(); ++j) in_b.emplace(b[j].key(), j);
  auto edges = [](const std::vector<GraphOperation<D>>& g) {
    std::set<std::pair<decltype(g[0].key()), decltype(g[0].key())>> e;
    for (const auto& o : g)
      for (std::size_t t : o.targets) e.emplace(o.key(), g[t].key());
    return e;
  };
  const auto ea = edges(a), eb = edges(b);
  std::set<Point<D>> out;
  for (const auto& o : a) {
    auto it = in_b.find(o.key());
    if (it == in_b.end()) {
      out.insert(o.v);
      continue;
    }
    const auto& p = b[it->second];
    if (o.executed != p.executed || (o.input_dispatch && !p.input_dispatch) ||
        !std::includes(p.reads.begin(), p.reads.end(), o.reads.begin(), o.reads.end()) ||
        !std::includes(p.steiners.begin(), p.steiners.end(), o.steiners.begin(), o.steiners.end()))
      out.insert(o.v);
  }
  for (const auto& [from, to] : ea)
    if (!eb.count({from, to})) {
      out.insert(std::get<3>(from));
      out.insert(std::get<3>(to));
    }
  return out;
}

// ---------- nearest neighbours and spread ----------

// Exact squared distance of two points with double (dyadic) coordinates.
template <std::size_t D>
exact::Dyadic dist2_exact(const Point<D>& a, const Point<D>& b) {
  geometry::Point<D, exact::Dyadic> x, y;
  for (std::size_t i = 0; i < D; ++i) {
    x[i] = exact::Dyadic::from_double(a[i]);
    y[i] = exact::Dyadic::from_double(b[i]);
  }
  return geometry::dist2(x, y);
}
template <std::size_t D>
double dist2_approx(const Point<D>& a, const Point<D>& b) {
  return geometry::dist2(a, b);
}

// NN_M(v) for every v of M, squared and exact: a sweep in x_1 finds the candidates in doubles (a
// difference of doubles is rounded once, so 1e-9 relative slack keeps every true minimiser), then
// the candidates are compared exactly. M must have ≥ 2 distinct points.
template <std::size_t D>
std::map<Point<D>, exact::Dyadic> nearest_neighbor_dist2(std::vector<Point<D>> M) {
  std::sort(M.begin(), M.end());
  std::map<Point<D>, exact::Dyadic> out;
  for (std::size_t i = 0; i < M.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::pair<double, std::size_t>> cand;
    auto scan = [&](std::size_t j) {  // false: no later point in this direction can be closer
      double dx = M[j][0] - M[i][0];
      if (dx * dx > best * (1 + 1e-9)) return false;
      double d = dist2_approx<D>(M[i], M[j]);
      if (d <= best * (1 + 1e-9)) cand.emplace_back(d, j);
      best = std::min(best, d);
      return true;
    };
    for (std::size_t j = i + 1; j < M.size() && scan(j);) ++j;
    for (std::size_t j = i; j-- > 0 && scan(j);) {}
    std::optional<exact::Dyadic> nn;
    for (auto& [d, j] : cand)
      if (d <= best * (1 + 1e-9)) {
        exact::Dyadic e = dist2_exact<D>(M[i], M[j]);
        if (!nn || e < *nn) nn = e;
      }
    out.emplace(M[i], nn.value());
  }
  return out;
}

// log2 of the geometric spread Δ = diameter / closest-pair distance of a point set (doubles, for
// reports: the ratio denominators of Theorems 3.3.11 and 3.4.5).
template <std::size_t D>
double log2_spread(const std::vector<Point<D>>& P) {
  double diam = 0, close = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i)
    for (std::size_t j = i + 1; j < P.size(); ++j) {
      double d = dist2_approx<D>(P[i], P[j]);
      diam = std::max(diam, d);
      close = std::min(close, d);
    }
  return 0.5 * std::log2(diam / close);
}

// ρ^{2e}·NN² < ρ^{2k} decided exactly for integers e, k ≥ 0 (ρ is a dyadic double).
inline bool scaled_less(const exact::Dyadic& nn2, double rho, int e, int k) {
  exact::Dyadic r2 = exact::Dyadic::from_double(rho) * exact::Dyadic::from_double(rho), a = nn2, b = 1;
  for (int i = 0; i < e; ++i) a *= r2;
  for (int i = 0; i < k; ++i) b *= r2;
  return a < b;
}
// NN < ρ^{r+1}, exactly (Lemma 3.3.6's upper bound for an operation at rank r).
inline bool below_next_rank(const exact::Dyadic& nn2, double rho, int r) {
  return r + 1 >= 0 ? scaled_less(nn2, rho, 0, r + 1) : scaled_less(nn2, rho, -(r + 1), 0);
}

// ---------- Lemma 3.3.6 and Lemma 3.3.15 from the computation graph ----------

// NN_∞(v)/ρ^r over the operations v_(t) of the final graph (t of rank r), NN_∞ = NN in the output.
// Operations scheduled by another operation get rank ⌊log_ρ d⌋ from a distance d ≥ NN_t(v) ≥ NN_∞(v)
// (§3.2.3), so for them NN_∞(v) < ρ^{r+1} exactly; `above` counts violations. Input dispatches take
// their rank from v's square (Lemma 3.1.5) and are reported apart.
struct RankRatios {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;        // scheduled operations
  double in_lo = std::numeric_limits<double>::infinity(), in_hi = 0;  // input dispatches
  std::size_t ops = 0, above = 0;
  double spread() const { return std::max(hi, in_hi) / std::min(lo, in_lo); }
};
template <std::size_t D>
RankRatios rank_ratios(const WellSpacedSet<D>& ws) {
  std::vector<Point<D>> M;
  for (const auto& x : ws.vertices()) M.push_back(x.x);
  auto nn = nearest_neighbor_dist2<D>(M);
  const double rho = ws.params().rho;
  RankRatios R;
  for (const auto& op : ws.computation_graph()) {
    const exact::Dyadic& nn2 = nn.at(op.v);
    double ratio = std::sqrt(nn2.to_double()) / std::pow(rho, op.rank);
    ++R.ops;
    if (op.input_dispatch) {
      R.in_lo = std::min(R.in_lo, ratio);
      R.in_hi = std::max(R.in_hi, ratio);
    } else {
      R.lo = std::min(R.lo, ratio);
      R.hi = std::max(R.hi, ratio);
      R.above += !below_next_rank(nn2, rho, op.rank);
    }
  }
  return R;
}

// Lemma 3.3.15 for one update v̂ (graphs G, G' and outputs M, M' before and after): the operations
// named by a line of G missing from G' form M̂ (Ω⁻ ∪ changed Ω×), those of a line of G' missing from
// G form M̂' (Ω⁺ ∪ changed Ω×). Returns max |v v̂|/NN_M(v) over M̂ and |v v̂|/NN_M'(v) over M̂'.
// Inconsistent operations whose re-execution changed nothing are invisible here (a subset of M̂).
struct AffectedRatio {
  double max_ratio = 0;
  std::size_t vertices = 0;  // |M̂ ∪ M̂'|
};
template <std::size_t D>
AffectedRatio affected_ratio(const std::vector<GraphOperation<D>>& G, const std::vector<Vertex<D>>& M,
                             const std::vector<GraphOperation<D>>& G2, const std::vector<Vertex<D>>& M2,
                             const Point<D>& vhat) {
  AffectedRatio A;
  std::set<Point<D>> all;
  auto side = [&](const std::vector<GraphOperation<D>>& a, const std::vector<GraphOperation<D>>& b,
                  const std::vector<Vertex<D>>& out) {
    std::set<Point<D>> hat = vertices_of_changed_operations<D>(a, b);
    if (hat.empty()) return;
    std::vector<Point<D>> P;
    for (const auto& x : out) P.push_back(x.x);
    auto nn = nearest_neighbor_dist2<D>(P);
    for (const auto& v : hat) {
      A.max_ratio = std::max(A.max_ratio, std::sqrt(dist2_approx<D>(v, vhat) / nn.at(v).to_double()));
      all.insert(v);
    }
  };
  side(G, G2, M);
  side(G2, G, M2);
  A.vertices = all.size();
  return A;
}

}  // namespace kmr::wellspaced
