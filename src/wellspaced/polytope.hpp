#pragma once
// Exact convex polytopes in Q^D by halfspace clipping (§3.2.4: clipped Voronoi cells).
// Guarantees (tests/wellspaced/polytope_test.cpp):
//  * clip() keeps exactly the vertices of the clipped polytope (rational, exact); each vertex carries
//    the sorted set of constraints tight at it. Edges are found by the combinatorial adjacency test
//    (p, q adjacent iff no third vertex is tight on every constraint tight at both), exact also for
//    degenerate (cospherical, cocircular) inputs.
//  * face_distance_at_most(): exact decision "some point of the face {x ∈ P : constraint j tight}
//    lies within squared distance r2 of point v", by the active-set enumeration of the KKT points.
#include <algorithm>
#include <array>
#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace kmr::wellspaced {

using Q = boost::multiprecision::mpq_rational;

template <std::size_t D>
using QPoint = std::array<Q, D>;

template <std::size_t D>
struct Halfspace {  // a·x ≤ b
  QPoint<D> a;
  Q b;
};

template <std::size_t D>
std::array<double, D> to_d(const QPoint<D>& x) {
  std::array<double, D> d;
  for (std::size_t i = 0; i < D; ++i) d[i] = x[i].template convert_to<double>();
  return d;
}

// Floating-point filter: sign of a·x − b from double approximations of a, x, b (each within a
// relative 2^-53 of the exact value); 0 means "too close to call, decide exactly".
template <std::size_t D>
int filtered_sign(const std::array<double, D>& a, const std::array<double, D>& x, double b) {
  double s = -b, mag = std::abs(b);
  for (std::size_t i = 0; i < D; ++i) {
    double t = a[i] * x[i];
    s += t;
    mag += std::abs(t);
  }
  double bound = 1e-12 * mag + 1e-300;
  return s > bound ? 1 : (s < -bound ? -1 : 0);
}

template <std::size_t D>
Q dot(const QPoint<D>& a, const QPoint<D>& b) {
  Q s = 0;
  for (std::size_t i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

template <std::size_t D>
Q dist2(const QPoint<D>& a, const QPoint<D>& b) {
  Q s = 0;
  for (std::size_t i = 0; i < D; ++i) {
    Q d = a[i] - b[i];
    s += d * d;
  }
  return s;
}

// Bisector halfspace of v against u: points at least as close to v as to u.
template <std::size_t D>
Halfspace<D> bisector(const QPoint<D>& v, const QPoint<D>& u) {
  Halfspace<D> h;
  for (std::size_t i = 0; i < D; ++i) h.a[i] = u[i] - v[i];
  h.b = (dot<D>(u, u) - dot<D>(v, v)) / 2;
  return h;
}

template <std::size_t D>
struct Polytope {
  struct Vert {
    QPoint<D> x;
    std::vector<int> tight;  // sorted constraint indices
    std::array<double, D> xd{};  // double approximation of x (filter)
  };
  std::vector<Halfspace<D>> h;
  std::vector<std::pair<std::array<double, D>, double>> hd;  // double approximations of h
  std::vector<Vert> v;
  unsigned version = 0;  // bumped whenever the vertex set changes

  // The box [lo, hi]; constraint 2i is x_i ≤ hi_i, 2i+1 is −x_i ≤ −lo_i.
  static Polytope box(const QPoint<D>& lo, const QPoint<D>& hi) {
    Polytope P;
    for (std::size_t i = 0; i < D; ++i) {
      Halfspace<D> up, dn;
      for (std::size_t j = 0; j < D; ++j) up.a[j] = dn.a[j] = 0;
      up.a[i] = 1;
      up.b = hi[i];
      dn.a[i] = -1;
      dn.b = -lo[i];
      P.h.push_back(up);
      P.h.push_back(dn);
      P.hd.push_back({to_d<D>(up.a), up.b.template convert_to<double>()});
      P.hd.push_back({to_d<D>(dn.a), dn.b.template convert_to<double>()});
    }
    for (unsigned m = 0; m < (1u << D); ++m) {
      Vert c;
      for (std::size_t i = 0; i < D; ++i) {
        bool hiside = (m >> i) & 1u;
        c.x[i] = hiside ? hi[i] : lo[i];
        c.tight.push_back(static_cast<int>(2 * i + (hiside ? 0 : 1)));
      }
      std::sort(c.tight.begin(), c.tight.end());
      c.xd = to_d<D>(c.x);
      P.v.push_back(std::move(c));
    }
    return P;
  }

  Q slack(const Halfspace<D>& hs, const QPoint<D>& x) const { return dot<D>(hs.a, x) - hs.b; }
  // Exact sign of constraint k at vertex x (filtered).
  int sign_at(std::size_t k, const Vert& x) const {
    int f = filtered_sign<D>(hd[k].first, x.xd, hd[k].second);
    return f ? f : slack(h[k], x.x).sign();
  }

  // Adds constraint hs (index = h.size() before the call) and clips. Returns its index.
  int clip(const Halfspace<D>& hs) {
    int j = static_cast<int>(h.size());
    h.push_back(hs);
    hd.push_back({to_d<D>(hs.a), hs.b.template convert_to<double>()});
    std::vector<Q> s(v.size());
    std::vector<char> have(v.size(), 0);
    std::vector<int> sg(v.size());
    bool any_out = false;
    for (std::size_t k = 0; k < v.size(); ++k) {
      sg[k] = sign_at(static_cast<std::size_t>(j), v[k]);
      any_out |= sg[k] > 0;
    }
    auto exact_s = [&](std::size_t k) -> const Q& {
      if (!have[k]) {
        s[k] = slack(hs, v[k].x);
        have[k] = 1;
      }
      return s[k];
    };
    if (!any_out) {
      for (std::size_t k = 0; k < v.size(); ++k)
        if (sg[k] == 0) v[k].tight.push_back(j);
      return j;
    }
    ++version;
    std::vector<Vert> out;
    for (std::size_t p = 0; p < v.size(); ++p) {
      if (sg[p] >= 0) continue;
      for (std::size_t q = 0; q < v.size(); ++q) {
        if (sg[q] <= 0) continue;
        std::vector<int> common;
        std::set_intersection(v[p].tight.begin(), v[p].tight.end(), v[q].tight.begin(), v[q].tight.end(),
                              std::back_inserter(common));
        if (common.size() + 1 < D) continue;
        bool adjacent = true;
        for (std::size_t r = 0; r < v.size() && adjacent; ++r) {
          if (r == p || r == q) continue;
          if (std::includes(v[r].tight.begin(), v[r].tight.end(), common.begin(), common.end())) adjacent = false;
        }
        if (!adjacent) continue;
        Vert nv;
        Q lam = exact_s(p) / (exact_s(p) - exact_s(q));
        for (std::size_t i = 0; i < D; ++i) nv.x[i] = v[p].x[i] + (v[q].x[i] - v[p].x[i]) * lam;
        nv.xd = to_d<D>(nv.x);
        nv.tight = std::move(common);
        nv.tight.push_back(j);
        out.push_back(std::move(nv));
      }
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (sg[k] > 0) continue;
      if (sg[k] == 0) v[k].tight.push_back(j);
      out.push_back(std::move(v[k]));
    }
    v = std::move(out);
    return j;
  }

  bool contains(const QPoint<D>& x) const {
    auto xd = to_d<D>(x);
    for (std::size_t k = 0; k < h.size(); ++k) {
      int f = filtered_sign<D>(hd[k].first, xd, hd[k].second);
      if (f > 0 || (f == 0 && slack(h[k], x) > 0)) return false;
    }
    return true;
  }
  // Approximate max squared distance from c over the vertices (for pruning only).
  double max_dist2_approx(const std::array<double, D>& c) const {
    double m = 0;
    for (const auto& x : v) {
      double d = 0;
      for (std::size_t i = 0; i < D; ++i) d += (x.xd[i] - c[i]) * (x.xd[i] - c[i]);
      m = std::max(m, d);
    }
    return m;
  }
  // Exact: is some vertex farther than sqrt(r2) from c? (filtered)
  bool some_vertex_beyond(const QPoint<D>& c, const Q& r2) const {
    auto cd = to_d<D>(c);
    double rd = r2.template convert_to<double>();
    for (const auto& x : v) {
      double d = 0;
      for (std::size_t i = 0; i < D; ++i) d += (x.xd[i] - cd[i]) * (x.xd[i] - cd[i]);
      if (d > rd * (1 + 1e-9)) return true;
      if (d >= rd * (1 - 1e-9) && dist2<D>(x.x, c) > r2) return true;
    }
    return false;
  }

  // Max squared distance from c over the vertices.
  Q max_dist2(const QPoint<D>& c) const {
    Q m = 0;
    for (const auto& x : v) {
      Q d = dist2<D>(x.x, c);
      if (d > m) m = d;
    }
    return m;
  }

  // Projection of c onto {x : h_k·x = b_k for k in rows}; nullopt if the rows are dependent.
  std::optional<QPoint<D>> project(const QPoint<D>& c, const std::vector<int>& rows) const {
    std::size_t m = rows.size();
    std::vector<std::vector<Q>> G(m, std::vector<Q>(m + 1));
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t k = 0; k < m; ++k) G[i][k] = dot<D>(h[rows[i]].a, h[rows[k]].a);
      G[i][m] = dot<D>(h[rows[i]].a, c) - h[rows[i]].b;
    }
    for (std::size_t col = 0; col < m; ++col) {
      std::size_t piv = col;
      while (piv < m && G[piv][col] == 0) ++piv;
      if (piv == m) return std::nullopt;
      std::swap(G[piv], G[col]);
      for (std::size_t r = 0; r < m; ++r) {
        if (r == col || G[r][col] == 0) continue;
        Q f = G[r][col] / G[col][col];
        for (std::size_t k = col; k <= m; ++k) G[r][k] -= f * G[col][k];
      }
    }
    QPoint<D> x = c;
    for (std::size_t i = 0; i < m; ++i) {
      Q lam = G[i][m] / G[i][i];
      for (std::size_t d = 0; d < D; ++d) x[d] -= lam * h[rows[i]].a[d];
    }
    return x;
  }

  // Exact: does the face F_j = {x ∈ P : constraint j tight} contain a point within squared
  // distance r2 of c? (Minimum of |x−c|² over F_j is the projection of c onto the affine hull of
  // the minimal face containing the minimiser; enumerate those affine hulls.) `skip_from`:
  // constraints with index < skip_from (the bounding box) are never active at a minimiser within r2.
  bool face_within(int j, const QPoint<D>& c, const Q& r2, int skip_from) const {
    std::vector<int> rel;  // constraints tight at some vertex of F_j
    bool nonempty = false;
    auto cd = to_d<D>(c);
    double rd = r2.template convert_to<double>();
    for (const auto& x : v) {
      if (!std::binary_search(x.tight.begin(), x.tight.end(), j)) continue;
      nonempty = true;
      double dd = 0;
      for (std::size_t i = 0; i < D; ++i) dd += (x.xd[i] - cd[i]) * (x.xd[i] - cd[i]);
      if (dd < rd * (1 - 1e-9)) return true;
      if (dd <= rd * (1 + 1e-9) && dist2<D>(x.x, c) <= r2) return true;
      for (int t : x.tight)
        if (t != j && t >= skip_from) rel.push_back(t);
    }
    if (!nonempty) return false;
    std::sort(rel.begin(), rel.end());
    rel.erase(std::unique(rel.begin(), rel.end()), rel.end());
    // subsets of rel of size 0..D-2 together with j (size D would be a vertex: done above)
    std::vector<int> rows{j};
    bool found = false;
    auto rec = [&](auto&& self, std::size_t start) -> void {
      if (found) return;
      if (auto x = project(c, rows)) {
        if (dist2<D>(*x, c) <= r2 && contains(*x)) {
          found = true;
          return;
        }
      } else {
        return;  // dependent rows: supersets are dependent too
      }
      if (rows.size() + 1 >= D) return;
      for (std::size_t i = start; i < rel.size() && !found; ++i) {
        rows.push_back(rel[i]);
        self(self, i + 1);
        rows.pop_back();
      }
    };
    rec(rec, 0);
    return found;
  }
};

template <std::size_t D>
QPoint<D> to_q(const std::array<double, D>& p) {
  QPoint<D> q;
  for (std::size_t i = 0; i < D; ++i) q[i] = Q(p[i]);
  return q;
}

}  // namespace kmr::wellspaced
