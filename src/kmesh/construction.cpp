#include "kmesh/construction.hpp"

#include <algorithm>
#include <map>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/delaunay.hpp"

namespace kmr::kmesh {
namespace {

// The nearest vertex of `cands` within k·2^l of p with top ≥ min_top (ties: smaller id), or −1.
int nearest_within(const Spanner& S, const Point2& p, const std::vector<int>& cands, std::int64_t k, Rank l,
                   Rank min_top) {
  int best = -1;
  IPoint pe = enclose(p);
  for (int x : cands) {
    ++S.ops;
    if (S.top(x) < min_top || !within_filtered(p, pe, S.position(x), S.enclosure(x), k, l)) continue;
    // cands are sorted, so ties keep the smaller id
    if (best < 0 || compare_distance(p, pe, S.position(x), S.enclosure(x), S.position(best), S.enclosure(best)) < 0)
      best = x;
  }
  return best;
}

struct Builder {
  Mesh& m;
  Spanner& S;
  struct Pending {
    int x, proxy;
  };
  std::map<Rank, std::vector<Pending>> pending;

  // BallEmpty (§4.2.1): the ℓ'-neighbours of s for ℓ' = ℓ … ℓ−7, found from the (ℓ+1)-site h;
  // the ball is empty iff none at ranks ℓ−6 … ℓ−3 lies within 2^(ℓ−2) (Lemma 4.2.4).
  bool ball_empty(const Point2& s, Rank l, int h, std::map<Rank, std::vector<int>>& N) {
    N[l] = S.centers_near(s, l, h);
    for (Rank r = l - 1; r >= l - 7; --r) N[r] = S.centers_near_below(s, r, N[r + 1]);
    IPoint se = enclose(s);
    for (Rank r = l - 6; r <= l - 3; ++r)
      for (int x : N[r]) {
        ++S.ops;
        if (within_filtered(s, se, S.position(x), S.enclosure(x), 1, l - 2)) return false;
      }
    return true;
  }

  // Convert: insert s at its minimum rank λ_s and promote it as high as possible up to ℓ.
  void convert(const Point2& s, Rank l, int nucleus, int ray, int h, std::map<Rank, std::vector<int>>& N) {
    KMR_CHECK(N[l - 7].empty(), "Convert: a neighbour at rank l-7 of an empty certificate ball (Lemma 4.2.10)");
    Rank lam = l + 1;
    for (Rank r = l; r >= l - 6; --r)
      if (!N[r].empty()) lam = r;
    Rank top = l - 2;
    if (nearest_within(S, s, N[l - 1], 1, l - 1, l - 1) < 0) {
      top = l - 1;
      if (nearest_within(S, s, N[l], 1, l, l) < 0) top = l;
    }
    int parent = -1, proxy = -1;
    if (top < l) {
      parent = nearest_within(S, s, N[top + 1], 1, top + 1, top + 1);
      KMR_CHECK(parent >= 0, "Convert: no parent found");
    } else {
      parent = nearest_within(S, s, N[l], 2, l, l + 1);
      if (parent < 0) proxy = h;
    }
    std::map<Rank, std::vector<int>> nb;
    for (Rank r = lam; r <= top; ++r)
      if (!N[r].empty()) nb[r] = N[r];
    int id = S.insert(s, top, nb, parent, proxy);
    m.info.push_back(VertexInfo{true, nucleus, l, ray});
    if (parent < 0) pending[top].push_back({id, proxy});
  }

  // TryToPromote at the end of rank ℓ, for every pending Steiner ℓ-center in id order.
  std::size_t try_to_promote(Rank l) {
    std::size_t promoted = 0;
    auto list = std::move(pending[l]);
    pending.erase(l);
    for (auto [x, proxy] : list) {
      int p = nearest_within(S, S.position(x), S.neighbors(x, l), 2, l, l + 1);
      if (p >= 0) {
        S.set_parent(x, p, proxy);
        continue;
      }
      int h2 = S.rep(proxy, l + 2);
      std::vector<int> nb = S.centers_near(S.position(x), l + 1, h2);
      int parent = nearest_within(S, S.position(x), nb, 4, l, l + 2);
      S.promote(x, nb, parent, parent < 0 ? h2 : -1, proxy);
      if (parent < 0) pending[l + 1].push_back({x, h2});
      ++promoted;
    }
    return promoted;
  }
};

}  // namespace

Point2 scaled(const InputPoint& p) { return {Dyadic(p.x * kScale), Dyadic(p.y * kScale)}; }

Point2 scaled_at(const InputPoint& p, const Dyadic& t) {
  return {Dyadic(p.x * kScale) + Dyadic(p.vx * kScale) * t, Dyadic(p.y * kScale) + Dyadic(p.vy * kScale) * t};
}

Mesh construct(std::vector<InputPoint> points, const Dyadic& t) {
  KMR_CHECK(!points.empty(), "construct: no input point");
  std::vector<std::pair<Point2, std::size_t>> at;
  for (std::size_t i = 0; i < points.size(); ++i) at.push_back({scaled_at(points[i], t), i});
  std::sort(at.begin(), at.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (std::size_t i = 1; i < at.size(); ++i)
    if (at[i].first == at[i - 1].first) {
      auto& p = points[at[i].second];
      throw InputError("two input points at the same place at time " + t.to_decimal() + " (point (" + p.x.str() +
                       ", " + p.y.str() + ") moving (" + p.vx.str() + ", " + p.vy.str() + "))");
    }
  Mesh m;
  std::vector<Point2> pts;
  for (auto& [p, i] : at) m.input.push_back(points[i]), pts.push_back(p);
  const int n = static_cast<int>(pts.size());
  m.spanner = Spanner::build(pts, 8);
  Spanner& S = m.spanner;
  m.ops_spanner = S.ops;
  for (int v = 0; v < n; ++v) m.info.push_back(VertexInfo{false, v, 0, -1});
  if (n == 1) return m;

  // Stage 2: activation ranks, conversion and promotion, ranks λ … Λ+4.
  std::vector<Rank> rho(n);
  Rank lo = 0;
  for (int v = 0; v < n; ++v) {
    rho[v] = S.min_rank(v);
    m.info[v].rank = rho[v];
    lo = v == 0 ? rho[v] : std::min(lo, rho[v]);
  }
  const Rank hi = S.lambda() + 4;
  m.lowest = lo;
  m.highest = hi;
  std::vector<int> order(n);
  for (int v = 0; v < n; ++v) order[v] = v;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rho[a] < rho[b]; });
  std::vector<int> active, anc(n);
  for (int v = 0; v < n; ++v) anc[v] = v;
  std::size_t next = 0;
  Builder B{m, S, {}};
  for (Rank l = lo; l <= hi || !B.pending.empty(); ++l) {
    RankStats st;
    st.rank = l;
    if (l <= hi) {
      while (next < order.size() && rho[order[next]] == l) active.push_back(order[next++]);
      std::sort(active.begin(), active.end());
      st.active = active.size();
      std::vector<int> still;
      for (int v : active) {
        anc[v] = S.rep(anc[v], l + 1);  // the (ℓ+1)-site of v's satellites (Lemma 4.2.1), one step up
        bool any = false;
        for (int k : rays_of_rank(l)) {
          Point2 s = satellite_position(S.position(v), k, l);
          std::map<Rank, std::vector<int>> N;
          ++st.considered;
          int before_count = static_cast<int>(S.size());
          bool empty = B.ball_empty(s, l, anc[v], N);
          if (empty) {
            B.convert(s, l, v, k, anc[v], N);
            ++st.converted;
            any = true;
          }
          m.considered.push_back({v, k, l, empty, empty ? static_cast<int>(S.size()) - 1 : -1, before_count});
        }
        if (any) still.push_back(v);
      }
      active = std::move(still);
    }
    KMR_CHECK(l + 2 <= S.top_rank(), "construction ran above the root's rank");
    st.promoted = B.try_to_promote(l);
    m.ranks.push_back(st);
  }
  m.ops_convert = S.ops - m.ops_spanner;

  // Stage 3: the Voronoi neighbours of every vertex, hence the Delaunay triangulation of M.
  std::uint64_t before = S.ops;
  m.stars = voronoi_stars(m);
  m.triangles = triangles_from_stars(m.stars);
  m.ops_delaunay = S.ops - before;
  return m;
}

}  // namespace kmr::kmesh
