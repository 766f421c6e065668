// Exact part of the Chapter 3 oracles (CGAL-free): clipped Voronoi cells by exact half-space
// clipping, ρ-well-spacedness, size conformity (Lemma 3.3.3), β-clipped Voronoi neighbours.
// See ws_oracle.hpp for the guarantees. All arithmetic on GMP rationals; nothing is rounded.
//
// Clipped cell of v: start from the box (2^D vertices, each knowing the D facet planes through it)
// and cut by each half-space n·x ≤ h in turn. A vertex records every processed plane it lies on.
// New vertices are the crossings of H with the polytope's edges; two vertices a (inside) and b
// (outside) lie on a common edge iff they share planes whose normals span rank D−1 (the face of a
// convex polytope cut by those supporting planes is the edge through a and b). Crossings of
// several vertex pairs on one edge line coincide and are merged.
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <map>
#include <set>
#include <string>

#include "exact/error.hpp"
#include "ws_exact_q.hpp"
#include "ws_oracle.hpp"

namespace kmr::oracle::ws {

// The exact hex-float reader (ws_oracle.hpp).
std::optional<exact::Dyadic> parse_hex_exact(const std::string& text) {
  std::size_t i = 0;
  bool neg = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) neg = text[i++] == '-';
  if (text.compare(i, 2, "0x") != 0 && text.compare(i, 2, "0X") != 0) return std::nullopt;
  i += 2;
  exact::Integer m = 0;
  std::int64_t e = 0, digits = 0;
  bool point = false;
  for (; i < text.size() && text[i] != 'p' && text[i] != 'P'; ++i) {
    const char c = text[i];
    int d = -1;
    if (c >= '0' && c <= '9') d = c - '0';
    else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
    else if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (d < 0) return std::nullopt;
    m = m * 16 + d;
    ++digits;
    if (point) e -= 4;
  }
  if (digits == 0 || i + 1 >= text.size()) return std::nullopt;
  char* end = nullptr;
  const long long pe = std::strtoll(text.c_str() + i + 1, &end, 10);
  if (*end != '\0') return std::nullopt;
  exact::Dyadic x(m, e + pe);
  return neg ? -x : x;
}


using detail::Q;

double Rho::approx() const { return std::sqrt(sq_num.to_double() / sq_den.to_double()); }

template <std::size_t D>
std::vector<XPoint<D>> to_exact(const std::vector<DPoint<D>>& pts) {
  std::vector<XPoint<D>> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t k = 0; k < D; ++k) out[i][k] = exact::Dyadic::from_double(pts[i][k]);
  return out;
}

namespace {

template <std::size_t D>
using QP = std::array<Q, D>;

template <std::size_t D>
QP<D> qp(const XPoint<D>& p) {
  QP<D> r;
  for (std::size_t k = 0; k < D; ++k) r[k] = detail::to_q(p[k]);
  return r;
}

template <std::size_t D>
Q dist2(const QP<D>& a, const QP<D>& b) {
  Q s = 0;
  for (std::size_t k = 0; k < D; ++k) {
    Q d = a[k] - b[k];
    s += d * d;
  }
  return s;
}

template <std::size_t D>
Q dot(const QP<D>& a, const QP<D>& b) {
  Q s = 0;
  for (std::size_t k = 0; k < D; ++k) s += a[k] * b[k];
  return s;
}

template <std::size_t D>
struct Half {
  QP<D> n;
  Q h;  // n·x ≤ h
};

// Rank of a set of vectors (exact Gaussian elimination).
template <std::size_t D>
std::size_t rank_of(std::vector<QP<D>> rows) {
  std::size_t r = 0;
  for (std::size_t col = 0; col < D && r < rows.size(); ++col) {
    std::size_t piv = r;
    while (piv < rows.size() && rows[piv][col] == 0) ++piv;
    if (piv == rows.size()) continue;
    std::swap(rows[piv], rows[r]);
    for (std::size_t i = r + 1; i < rows.size(); ++i) {
      if (rows[i][col] == 0) continue;
      Q f = rows[i][col] / rows[r][col];
      for (std::size_t k = col; k < D; ++k) rows[i][k] -= f * rows[r][k];
    }
    ++r;
  }
  return r;
}

template <std::size_t D>
struct Polytope {
  struct Vtx {
    QP<D> x;
    std::vector<int> planes;  // sorted ids of the processed planes through x
  };
  std::vector<Half<D>> halves;  // by plane id
  std::vector<Vtx> vs;

  // The box [lo, hi]^D per axis; planes 2k: −x_k ≤ −lo_k, 2k+1: x_k ≤ hi_k.
  Polytope(const QP<D>& lo, const QP<D>& hi) {
    for (std::size_t k = 0; k < D; ++k) {
      Half<D> a, b;
      for (std::size_t j = 0; j < D; ++j) a.n[j] = b.n[j] = 0;
      a.n[k] = -1;
      a.h = -lo[k];
      b.n[k] = 1;
      b.h = hi[k];
      halves.push_back(a);
      halves.push_back(b);
    }
    for (std::size_t mask = 0; mask < (std::size_t(1) << D); ++mask) {
      Vtx v;
      for (std::size_t k = 0; k < D; ++k) {
        bool up = (mask >> k) & 1;
        v.x[k] = up ? hi[k] : lo[k];
        v.planes.push_back(static_cast<int>(2 * k + (up ? 1 : 0)));
      }
      std::sort(v.planes.begin(), v.planes.end());
      vs.push_back(std::move(v));
    }
  }

  bool on_common_edge(const std::vector<int>& shared) const {
    if (shared.size() + 1 < D) return false;
    if (D <= 3) return true;  // distinct, non-parallel planes (see header comment)
    std::vector<QP<D>> rows;
    for (int id : shared) rows.push_back(halves[static_cast<std::size_t>(id)].n);
    return rank_of<D>(rows) + 1 >= D;
  }

  static std::size_t shared_count(const std::vector<int>& a, const std::vector<int>& b) {
    std::size_t n = 0;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
      if (a[i] < b[j]) ++i;
      else if (b[j] < a[i]) ++j;
      else ++n, ++i, ++j;
    }
    return n;
  }

  static std::vector<int> intersect(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> r;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(r));
    return r;
  }

  void add_vertex(std::vector<Vtx>& out, Vtx v) {
    for (auto& w : out)
      if (w.x == v.x) {
        std::vector<int> u;
        std::set_union(w.planes.begin(), w.planes.end(), v.planes.begin(), v.planes.end(),
                       std::back_inserter(u));
        w.planes = std::move(u);
        return;
      }
    out.push_back(std::move(v));
  }

  // Returns the id of the new plane.
  int clip(const Half<D>& h) {
    const int id = static_cast<int>(halves.size());
    halves.push_back(h);
    std::vector<Q> s(vs.size());
    bool any_out = false;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      s[i] = dot<D>(h.n, vs[i].x) - h.h;
      if (s[i] > 0) any_out = true;
    }
    if (!any_out) {
      for (std::size_t i = 0; i < vs.size(); ++i)
        if (s[i] == 0) vs[i].planes.push_back(id);
      return id;
    }
    std::vector<Vtx> out;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      if (s[i] > 0) continue;
      Vtx v = vs[i];
      if (s[i] == 0) v.planes.push_back(id);
      add_vertex(out, std::move(v));
    }
    for (std::size_t a = 0; a < vs.size(); ++a) {
      if (s[a] >= 0) continue;
      for (std::size_t b = 0; b < vs.size(); ++b) {
        if (s[b] <= 0) continue;
        if (shared_count(vs[a].planes, vs[b].planes) + 1 < D) continue;
        std::vector<int> shared = intersect(vs[a].planes, vs[b].planes);
        if (!on_common_edge(shared)) continue;
        Q t = s[a] / (s[a] - s[b]);
        Vtx w;
        for (std::size_t k = 0; k < D; ++k) w.x[k] = vs[a].x[k] + t * (vs[b].x[k] - vs[a].x[k]);
        w.planes = std::move(shared);
        w.planes.push_back(id);
        add_vertex(out, std::move(w));
      }
    }
    KMR_CHECK(!out.empty(), "clipped cell became empty");
    vs = std::move(out);
    return id;
  }

  bool contains(const QP<D>& x) const {
    for (const auto& h : halves)
      if (dot<D>(h.n, x) > h.h) return false;
    return true;
  }
};

template <std::size_t D>
Half<D> bisector(const QP<D>& v, const QP<D>& u) {  // |x−v|² ≤ |x−u|²
  Half<D> h;
  for (std::size_t k = 0; k < D; ++k) h.n[k] = 2 * (u[k] - v[k]);
  h.h = dot<D>(u, u) - dot<D>(v, v);
  return h;
}

template <std::size_t D>
void check_points(const std::vector<XPoint<D>>& pts, const char* who) {
  if (pts.size() < 2) throw InputError(std::string(who) + ": needs at least two points");
  const exact::Dyadic zero(0), one(1);
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t k = 0; k < D; ++k)
      if (pts[i][k] < zero || pts[i][k] > one)
        throw InputError(std::string(who) + ": point " + std::to_string(i) + " coordinate " +
                         pts[i][k].to_decimal() + " outside the domain [0,1]");
  std::vector<std::size_t> idx(pts.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return pts[a] < pts[b]; });
  for (std::size_t i = 1; i < idx.size(); ++i)
    if (pts[idx[i]] == pts[idx[i - 1]])
      throw InputError(std::string(who) + ": duplicate points " + std::to_string(idx[i - 1]) +
                       " and " + std::to_string(idx[i]));
}

}  // namespace

template <std::size_t D>
struct CellOracle<D>::Impl {
  std::vector<XPoint<D>> pts;
  std::vector<QP<D>> q;
  std::vector<std::vector<std::uint32_t>> adj;
  std::vector<Q> nn2;
  std::vector<std::uint32_t> nn;

  Polytope<D> unit_box() const {
    QP<D> lo, hi;
    for (std::size_t k = 0; k < D; ++k) lo[k] = 0, hi[k] = 1;
    return Polytope<D>(lo, hi);
  }

  // Cell of v clipped to `box`; plane id of neighbour adj[v][k] is 2D + k.
  // Nearest neighbours first: the polytope shrinks early, later cuts touch fewer vertices.
  Polytope<D> cell(std::size_t v, Polytope<D> box) const {
    std::vector<std::pair<Q, std::uint32_t>> order;
    for (std::uint32_t u : adj[v]) order.emplace_back(dist2<D>(q[v], q[u]), u);
    std::sort(order.begin(), order.end());
    for (const auto& [d, u] : order) box.clip(bisector<D>(q[v], q[u]));
    return box;
  }

  Q far2(const Polytope<D>& P, std::size_t v) const {
    Q best = 0;
    for (const auto& w : P.vs) best = std::max(best, dist2<D>(w.x, q[v]));
    return best;
  }

  std::vector<std::uint32_t> beta(std::size_t v, const Q& beta_sq, BetaOptions opt) const {
    std::vector<std::uint32_t> cand;
    std::vector<int> plane_of;
    Polytope<D> P = clipped_cell(v, beta_sq, opt, cand, plane_of);
    const Q bound = beta_sq * nn2[v];
    std::vector<std::uint32_t> out;
    for_each_face(P, cand, plane_of, [&](std::uint32_t u, int id, const auto& face) {
      if (within(face_dist2(P, id, face, v, u, opt.face_distance, &bound, opt.strict), bound,
                 opt.strict))
        out.push_back(u);
    });
    std::sort(out.begin(), out.end());
    return out;
  }

  // The cell of v cut by the bisectors of all candidates (cand[k] has plane id plane_of[k]).
  Polytope<D> clipped_cell(std::size_t v, const Q& beta_sq, BetaOptions opt,
                           std::vector<std::uint32_t>& cand, std::vector<int>& plane_of) const {
    // Candidates: every point u with |uv| ≤ 2β·NN(v) (a face point x with |xv| ≤ β·NN(v) has
    // |uv| ≤ |ux| + |xv| = 2|xv|). They are found by a search of CGAL's Delaunay graph from v
    // restricted to that ball, which reaches all of them (greedy routing: every site u ≠ v has a
    // Delaunay neighbour closer to v). Using all candidates' bisectors, not only the chosen
    // triangulation's edges, finds the neighbours that merely touch the cell (cospherical sites).
    const Q r2 = 4 * beta_sq * nn2[v];
    cand.clear();
    if (opt.brute_force) {
      for (std::size_t u = 0; u < q.size(); ++u)
        if (u != v) cand.push_back(static_cast<std::uint32_t>(u));
    } else {
      std::vector<std::uint32_t> stack{static_cast<std::uint32_t>(v)};
      std::set<std::uint32_t> seen{static_cast<std::uint32_t>(v)};
      while (!stack.empty()) {
        std::uint32_t w = stack.back();
        stack.pop_back();
        for (std::uint32_t u : adj[w]) {
          if (seen.count(u) || dist2<D>(q[u], q[v]) > r2) continue;
          seen.insert(u);
          cand.push_back(u);
          stack.push_back(u);
        }
      }
    }
    // Nearest candidates first (the polytope shrinks early); the final polytope, and the planes
    // recorded at each of its vertices, do not depend on the order.
    std::sort(cand.begin(), cand.end(), [&](std::uint32_t a, std::uint32_t b) {
      Q da = dist2<D>(q[a], q[v]), db = dist2<D>(q[b], q[v]);
      return da < db || (da == db && a < b);
    });
    Polytope<D> P = unit_box();
    if (!opt.clip_to_domain) {
      // A box containing the closed ball B(v, β·NN(v)): half side max(1, β²)·|v − nn|_1.
      Q l1 = 0;
      for (std::size_t k = 0; k < D; ++k) l1 += abs(q[v][k] - q[nn[v]][k]);
      Q s = std::max(Q(1), beta_sq) * l1;
      QP<D> lo, hi;
      for (std::size_t k = 0; k < D; ++k) lo[k] = q[v][k] - s, hi[k] = q[v][k] + s;
      P = Polytope<D>(lo, hi);
    }
    plane_of.assign(cand.size(), 0);
    for (std::size_t k = 0; k < cand.size(); ++k) plane_of[k] = P.clip(bisector<D>(q[v], q[cand[k]]));
    return P;
  }

  static bool within(const Q& d2, const Q& bound, bool strict) {
    return d2 >= 0 && (strict ? d2 < bound : d2 <= bound);
  }

  using Face = std::vector<const typename Polytope<D>::Vtx*>;

  // f(u, plane id, vertices of F_u) for each candidate u whose face F_u = P ∩ bisector(v, u) is
  // nonempty (the others are not Voronoi neighbours within the clipping box).
  template <class F>
  static void for_each_face(const Polytope<D>& P, const std::vector<std::uint32_t>& cand,
                            const std::vector<int>& plane_of, F&& f) {
    for (std::size_t k = 0; k < cand.size(); ++k) {
      const int id = plane_of[k];
      Face face;
      for (const auto& w : P.vs)
        if (std::binary_search(w.planes.begin(), w.planes.end(), id)) face.push_back(&w);
      if (!face.empty()) f(cand[k], id, face);
    }
  }

  // dist(v, F_u)² by the chosen method; with stop_at, any value within it may be returned as soon
  // as one is found (the decision is the same).
  Q face_dist2(const Polytope<D>& P, int id, const Face& face, std::size_t v, std::uint32_t u,
               FaceDistance how, const Q* stop_at, bool strict) const {
    if (how == FaceDistance::Auto) how = D <= 3 ? FaceDistance::Edges23 : FaceDistance::KktFaceVertices;
    switch (how) {
      case FaceDistance::Edges23:
        KMR_CHECK(D <= 3, "the edge scan is the face distance for D = 2, 3 only");
        return face_dist2_23(P, face, v, q[u]);
      case FaceDistance::KktFaceVertices: {
        // Vertices of F_u, then subsets of the planes through one face vertex, |T| ≤ D − 2.
        Q best = -1;
        for (auto* w : face) {
          Q d = dist2<D>(w->x, q[v]);
          if (best < 0 || d < best) best = d;
        }
        if (stop_at && within(best, *stop_at, strict)) return best;
        std::vector<std::vector<int>> pools;
        for (auto* w : face) {
          pools.emplace_back();
          for (int p : w->planes)
            if (p != id) pools.back().push_back(p);
        }
        return kkt_min(P, id, pools, D - 2, q[v], best, stop_at, strict);
      }
      case FaceDistance::KktAllFacePlanes: {
        // Self-test form: every subset (|T| ≤ D − 1) of all planes meeting F_u, no vertex distances.
        std::set<int> all;
        for (auto* w : face)
          for (int p : w->planes)
            if (p != id) all.insert(p);
        return kkt_min(P, id, {std::vector<int>(all.begin(), all.end())}, D - 1, q[v], Q(-1), stop_at,
                       strict);
      }
      case FaceDistance::Auto: break;
    }
    KMR_CHECK(false, "unknown face distance method");
    return -1;
  }

  // Exact dist(v, F_u)² for every candidate u with a nonempty face (self-tests).
  std::vector<std::pair<std::uint32_t, Q>> face_distances(std::size_t v, const Q& beta_sq,
                                                          BetaOptions opt) const {
    std::vector<std::uint32_t> cand;
    std::vector<int> plane_of;
    Polytope<D> P = clipped_cell(v, beta_sq, opt, cand, plane_of);
    std::vector<std::pair<std::uint32_t, Q>> out;
    for_each_face(P, cand, plane_of, [&](std::uint32_t u, int id, const auto& face) {
      out.emplace_back(u, face_dist2(P, id, face, v, u, opt.face_distance, nullptr, opt.strict));
    });
    std::sort(out.begin(), out.end());
    return out;
  }

  // dist(v, F_u)², F_u = P ∩ bisector(v, u) (D = 2, 3): the midpoint of uv if it lies in P (the
  // projection of v onto the bisector), else the nearest point lies on the boundary of F_u, a
  // vertex or a point of an edge of F_u (F_u has dimension ≤ 2).
  Q face_dist2_23(const Polytope<D>& P, const std::vector<const typename Polytope<D>::Vtx*>& face,
                  std::size_t v, const QP<D>& u) const {
    QP<D> m;
    for (std::size_t j = 0; j < D; ++j) m[j] = (q[v][j] + u[j]) / 2;
    if (P.contains(m)) return dist2<D>(m, q[v]);
    Q d2 = dist2<D>(face[0]->x, q[v]);
    for (auto* w : face) d2 = std::min(d2, dist2<D>(w->x, q[v]));
    for (std::size_t a = 0; a < face.size(); ++a)
      for (std::size_t b = a + 1; b < face.size(); ++b) {
        auto shared = Polytope<D>::intersect(face[a]->planes, face[b]->planes);
        if (!P.on_common_edge(shared)) continue;
        QP<D> ab, av;
        for (std::size_t j = 0; j < D; ++j)
          ab[j] = face[b]->x[j] - face[a]->x[j], av[j] = q[v][j] - face[a]->x[j];
        Q t = dot<D>(av, ab) / dot<D>(ab, ab);
        if (t <= 0 || t >= 1) continue;
        QP<D> p;
        for (std::size_t j = 0; j < D; ++j) p[j] = face[a]->x[j] + t * ab[j];
        d2 = std::min(d2, dist2<D>(p, q[v]));
      }
    return d2;
  }

  // KKT points of min |vx|² over F = P ∩ {plane id}, any D. The nearest point x* lies in the
  // relative interior of the smallest face G of P containing it, G ⊆ F, so x* is the projection of
  // v onto aff(G) = ∩ of the planes tight on G (id among them). Those planes all pass through each
  // vertex w of G, and a row basis of them containing id has ≤ D − 1 rows unless G is a vertex. So
  // dist(v, F)² is the least of |vw|² over the vertices w of F and of |vx|² over the projections x
  // of v onto {id} ∪ T, T ⊆ planes(w) \ {id}, |T| ≤ D − 2, independent rows, that lie in P; each
  // such x is a point of F, so no candidate undercuts the true distance. kkt_min takes subsets T of
  // each pool (|T| ≤ max_t) starting from `best` (−1: none yet); candidates not below the current
  // best (or, with stop_at, not within it) are not tested for P.
  static Q kkt_min(const Polytope<D>& P, int id, const std::vector<std::vector<int>>& pools,
                   std::size_t max_t, const QP<D>& y, Q best, const Q* stop_at, bool strict) {
    std::set<std::vector<int>> tried;
    std::vector<int> T;
    const std::vector<int>* pool = nullptr;
    bool done = false;
    auto visit = [&] {
      std::vector<int> rows{id};
      rows.insert(rows.end(), T.begin(), T.end());
      if (!tried.insert(rows).second) return;
      QP<D> x;
      if (!project(P, rows, y, x)) return;
      Q d = dist2<D>(x, y);
      if (best >= 0 && d >= best) return;
      if (stop_at && !within(d, *stop_at, strict)) return;
      if (!P.contains(x)) return;
      best = d;
      if (stop_at) done = true;
    };
    auto rec = [&](auto&& self, std::size_t from) -> void {  // T stays sorted
      visit();
      if (done || T.size() >= max_t) return;
      for (std::size_t i = from; i < pool->size() && !done; ++i) {
        T.push_back((*pool)[i]);
        self(self, i + 1);
        T.pop_back();
      }
    };
    for (const auto& p : pools) {
      pool = &p;
      rec(rec, 0);
      if (done) break;
    }
    return best;
  }

  // Orthogonal projection of y onto {x : n_i·x = h_i, i ∈ rows} (x = y − Σ λ_i n_i with
  // G λ = (n_i·y − h_i), G the Gram matrix). False if the rows are linearly dependent.
  static bool project(const Polytope<D>& P, const std::vector<int>& rows, const QP<D>& y, QP<D>& x) {
    const std::size_t r = rows.size();
    std::vector<std::vector<Q>> G(r, std::vector<Q>(r + 1));
    for (std::size_t i = 0; i < r; ++i) {
      const auto& hi = P.halves[static_cast<std::size_t>(rows[i])];
      for (std::size_t j = 0; j < r; ++j)
        G[i][j] = dot<D>(hi.n, P.halves[static_cast<std::size_t>(rows[j])].n);
      G[i][r] = dot<D>(hi.n, y) - hi.h;
    }
    for (std::size_t c = 0; c < r; ++c) {  // Gauss–Jordan; G is singular iff rows are dependent
      std::size_t piv = c;
      while (piv < r && G[piv][c] == 0) ++piv;
      if (piv == r) return false;
      std::swap(G[piv], G[c]);
      for (std::size_t i = 0; i < r; ++i) {
        if (i == c || G[i][c] == 0) continue;
        Q f = G[i][c] / G[c][c];
        for (std::size_t j = c; j <= r; ++j) G[i][j] -= f * G[c][j];
      }
    }
    x = y;
    for (std::size_t i = 0; i < r; ++i) {
      Q lambda = G[i][r] / G[i][i];
      const auto& n = P.halves[static_cast<std::size_t>(rows[i])].n;
      for (std::size_t k = 0; k < D; ++k) x[k] -= lambda * n[k];
    }
    return true;
  }
};

template <std::size_t D>
CellOracle<D>::CellOracle(std::vector<XPoint<D>> points) : impl_(std::make_unique<Impl>()) {
  check_points<D>(points, "well-spaced oracle");
  impl_->pts = std::move(points);
  const auto& P = impl_->pts;
  for (const auto& p : P) impl_->q.push_back(qp<D>(p));
  impl_->adj = cgal_delaunay_adjacency<D>(P);
  impl_->nn2.resize(P.size());
  impl_->nn.resize(P.size());
  for (std::size_t v = 0; v < P.size(); ++v) {
    KMR_CHECK(!impl_->adj[v].empty(), "a vertex without Delaunay neighbours");
    bool first = true;
    for (std::uint32_t u : impl_->adj[v]) {  // NN(v) is a Delaunay neighbour of v
      Q d = dist2<D>(impl_->q[v], impl_->q[u]);
      if (first || d < impl_->nn2[v]) impl_->nn2[v] = d, impl_->nn[v] = u, first = false;
    }
  }
}

template <std::size_t D>
CellOracle<D>::~CellOracle() = default;
template <std::size_t D>
CellOracle<D>::CellOracle(CellOracle&&) noexcept = default;
template <std::size_t D>
CellOracle<D>& CellOracle<D>::operator=(CellOracle&&) noexcept = default;

template <std::size_t D>
std::size_t CellOracle<D>::size() const {
  return impl_->pts.size();
}
template <std::size_t D>
const std::vector<std::uint32_t>& CellOracle<D>::delaunay_neighbors(std::size_t v) const {
  return impl_->adj.at(v);
}
template <std::size_t D>
std::uint32_t CellOracle<D>::nearest_neighbor(std::size_t v) const {
  return impl_->nn.at(v);
}
template <std::size_t D>
std::string CellOracle<D>::nn_squared(std::size_t v) const {
  return detail::to_text(impl_->nn2.at(v));
}
template <std::size_t D>
std::string CellOracle<D>::far_squared(std::size_t v) const {
  return detail::to_text(impl_->far2(impl_->cell(v, impl_->unit_box()), v));
}
template <std::size_t D>
bool CellOracle<D>::well_spaced(std::size_t v, const Rho& rho) const {
  Q r2 = impl_->far2(impl_->cell(v, impl_->unit_box()), v);
  return r2 * detail::to_q(rho.sq_den) <= detail::to_q(rho.sq_num) * impl_->nn2.at(v);
}
template <std::size_t D>
std::vector<std::uint32_t> CellOracle<D>::beta_neighbors(std::size_t v, const exact::Dyadic& beta,
                                                         BetaOptions opt) const {
  return beta_neighbors_sq(v, beta * beta, exact::Dyadic(1), opt);
}
template <std::size_t D>
std::vector<std::uint32_t> CellOracle<D>::beta_neighbors_sq(std::size_t v, const exact::Dyadic& num,
                                                            const exact::Dyadic& den,
                                                            BetaOptions opt) const {
  return impl_->beta(v, detail::to_q(num) / detail::to_q(den), opt);
}
template <std::size_t D>
std::vector<std::pair<std::uint32_t, std::string>> CellOracle<D>::face_distances_squared(
    std::size_t v, const exact::Dyadic& beta, BetaOptions opt) const {
  std::vector<std::pair<std::uint32_t, std::string>> out;
  for (const auto& [u, d2] : impl_->face_distances(v, detail::to_q(beta * beta), opt))
    out.emplace_back(u, detail::to_text(d2));
  return out;
}
template <std::size_t D>
std::string CellOracle<D>::far_squared_brute_force(std::size_t v) const {
  Polytope<D> P = impl_->unit_box();
  for (std::size_t u = 0; u < impl_->q.size(); ++u)
    if (u != v) P.clip(bisector<D>(impl_->q[v], impl_->q[u]));
  return detail::to_text(impl_->far2(P, v));
}

template <std::size_t D>
WellSpacedReport judge_well_spaced(const std::vector<XPoint<D>>& points, const Rho& rho) {
  CellOracle<D> O(points);
  const auto* I = &O.impl();
  const Q num = detail::to_q(rho.sq_num), den = detail::to_q(rho.sq_den);
  WellSpacedReport r;
  r.vertices = points.size();
  r.ratio.resize(points.size());
  Q worst = -1;
  for (std::size_t v = 0; v < points.size(); ++v) {
    Q r2 = I->far2(I->cell(v, I->unit_box()), v);
    Q ratio2 = r2 / I->nn2[v];
    r.ratio[v] = std::sqrt(detail::to_dbl(ratio2));
    if (r2 * den > num * I->nn2[v]) ++r.violations;
    if (ratio2 > worst) worst = ratio2, r.worst_vertex = v;
  }
  r.ok = r.violations == 0;
  r.worst_ratio_sq = detail::to_text(worst);
  r.worst_ratio = std::sqrt(detail::to_dbl(worst));
  return r;
}

namespace {

// lfs² of each query w.r.t. input: the second smallest squared distance to an input point. The
// second-nearest site of x is a Delaunay neighbour of a nearest site p1 of x (the ball centred at
// x through the second-nearest p2 shrinks, tangent at p2, to an empty ball through p1 and p2).
template <std::size_t D>
std::vector<Q> lfs2(const std::vector<XPoint<D>>& input, const std::vector<XPoint<D>>& queries) {
  check_points<D>(input, "lfs oracle (input)");
  std::vector<QP<D>> in;
  for (const auto& p : input) in.push_back(qp<D>(p));
  std::vector<Q> out;
  out.reserve(queries.size());
  if constexpr (D <= 3) {
    auto nearest = cgal_nearest_site<D>(input, queries);
    auto adj = cgal_delaunay_adjacency<D>(input);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      QP<D> x = qp<D>(queries[i]);
      std::uint32_t p1 = nearest[i];
      bool first = true;
      Q best;
      for (std::uint32_t u : adj[p1]) {
        Q d = dist2<D>(x, in[u]);
        if (first || d < best) best = d, first = false;
      }
      KMR_CHECK(!first, "nearest site without Delaunay neighbours");
      KMR_CHECK(dist2<D>(x, in[p1]) <= best, "CGAL nearest site is not nearest");
      out.push_back(best);
    }
  } else {  // D = 4: exact brute force (small sets only)
    for (const auto& qq : queries) {
      QP<D> x = qp<D>(qq);
      Q d1 = -1, d2 = -1;
      for (const auto& p : in) {
        Q d = dist2<D>(x, p);
        if (d1 < 0 || d < d1) d2 = d1, d1 = d;
        else if (d2 < 0 || d < d2) d2 = d;
      }
      out.push_back(d2);
    }
  }
  return out;
}

}  // namespace

template <std::size_t D>
std::vector<std::string> lfs_squared(const std::vector<XPoint<D>>& input,
                                     const std::vector<XPoint<D>>& queries) {
  std::vector<std::string> out;
  for (const Q& q : lfs2<D>(input, queries)) out.push_back(detail::to_text(q));
  return out;
}

template <std::size_t D>
SizeConformingReport judge_size_conforming(const std::vector<XPoint<D>>& output,
                                           const std::vector<XPoint<D>>& input, const Rho& rho) {
  const Q q = detail::to_q(rho.sq_num) / detail::to_q(rho.sq_den);  // ρ²
  if (q <= 1) throw InputError("size-conformity oracle: ρ must exceed 1");
  std::set<XPoint<D>> out_set(output.begin(), output.end());
  for (std::size_t i = 0; i < input.size(); ++i)
    if (!out_set.count(input[i]))
      throw InputError("size-conformity oracle: input point " + std::to_string(i) +
                       " missing from the output");
  CellOracle<D> O(output);
  const auto* I = &O.impl();
  std::vector<Q> L = lfs2<D>(input, output);
  SizeConformingReport r;
  r.vertices = output.size();
  const double rr = rho.approx();
  r.c = 2 * rr / (rr - 1);
  Q worst = -1;
  for (std::size_t v = 0; v < output.size(); ++v) {
    const Q& a = I->nn2[v];  // NN²
    const Q& b = L[v];       // lfs²
    // Decide 2ρ·N ≥ (ρ−1)·L for N = √a, L = √b, ρ = √q, exactly (see ws_oracle.hpp).
    bool ok;
    if (4 * a >= b) {
      ok = true;  // 2N ≥ L
    } else {      // L > 2N: need L ≥ ρ(L − 2N) ⟺ 4q·N·L ≥ q(b + 4a) − b =: B
      Q B = q * (b + 4 * a) - b;
      ok = B <= 0 || 16 * q * q * a * b >= B * B;
    }
    if (!ok) ++r.violations;
    Q ratio2 = b / a;
    if (ratio2 > worst) worst = ratio2, r.worst_vertex = v;
  }
  r.ok = r.violations == 0;
  r.worst_ratio_sq = detail::to_text(worst);
  r.worst_ratio = std::sqrt(detail::to_dbl(worst));
  return r;
}

std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_2d(const std::vector<XPoint<2>>& points,
                                                                    std::size_t v,
                                                                    const exact::Dyadic& beta,
                                                                    BetaOptions opt) {
  return CellOracle<2>(points).beta_neighbors(v, beta, opt);
}
std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_3d(const std::vector<XPoint<3>>& points,
                                                                    std::size_t v,
                                                                    const exact::Dyadic& beta,
                                                                    BetaOptions opt) {
  return CellOracle<3>(points).beta_neighbors(v, beta, opt);
}
std::vector<std::uint32_t> beta_clipped_voronoi_neighbors_oracle_4d(const std::vector<XPoint<4>>& points,
                                                                    std::size_t v,
                                                                    const exact::Dyadic& beta,
                                                                    BetaOptions opt) {
  return CellOracle<4>(points).beta_neighbors(v, beta, opt);
}

#define KMR_WS_INSTANTIATE(D)                                                                  \
  template class CellOracle<D>;                                                                \
  template std::vector<XPoint<D>> to_exact<D>(const std::vector<DPoint<D>>&);                  \
  template WellSpacedReport judge_well_spaced<D>(const std::vector<XPoint<D>>&, const Rho&);   \
  template SizeConformingReport judge_size_conforming<D>(const std::vector<XPoint<D>>&,        \
                                                         const std::vector<XPoint<D>>&,        \
                                                         const Rho&);                          \
  template std::vector<std::string> lfs_squared<D>(const std::vector<XPoint<D>>&,              \
                                                   const std::vector<XPoint<D>>&);
KMR_WS_INSTANTIATE(2)
KMR_WS_INSTANTIATE(3)
KMR_WS_INSTANTIATE(4)

}  // namespace kmr::oracle::ws
