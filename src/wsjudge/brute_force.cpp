// Exact brute-force judges (see brute_force.hpp). Everything is relative to the judged vertex v
// (v at the origin): the bisector of v and u is the halfspace 2u·x ≤ |u|².
#include "wsjudge/brute_force.hpp"

#include <algorithm>
#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

namespace kmr::wsjudge {

namespace {

using Q = boost::multiprecision::mpq_rational;
template <std::size_t D>
using V = std::array<Q, D>;

template <std::size_t D>
Q dotq(const V<D>& a, const V<D>& b) {
  Q s = 0;
  for (std::size_t i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

template <std::size_t D>
V<D> rel(const V<D>& p, const V<D>& v) {
  V<D> x;
  for (std::size_t i = 0; i < D; ++i) x[i] = p[i] - v[i];
  return x;
}

// Points as the judges read them: exact, and rounded to doubles for near()'s filters (which need
// to know whether the rounding was exact).
template <std::size_t D>
struct Points {
  std::vector<V<D>> q;
  std::vector<std::array<double, D>> d;
  bool doubles = true;  // every coordinate is a double: d is exact
};
template <std::size_t D>
Points<D> points(const std::vector<std::array<double, D>>& M) {
  Points<D> P{{}, M, true};
  for (const auto& p : M) {
    V<D> x;
    for (std::size_t i = 0; i < D; ++i) x[i] = Q(p[i]);
    P.q.push_back(x);
  }
  return P;
}
template <std::size_t D>
Points<D> points(const std::vector<V<D>>& M) {
  Points<D> P{M, {}, true};
  bool all = true;
  for (const auto& x : M) {
    std::array<double, D> p;
    for (std::size_t i = 0; i < D; ++i) {
      p[i] = x[i].template convert_to<double>();
      if (!std::isfinite(p[i])) throw std::invalid_argument("wsjudge: a coordinate beyond the range of doubles");
      all = all && Q(p[i]) == x[i];
    }
    P.d.push_back(p);
  }
  P.doubles = all;
  return P;
}

template <std::size_t D>
std::string fmt(const V<D>& x) {  // "%a" of each coordinate; "~" marks one that is not a double
  std::string s = "(";
  char buf[48];
  for (std::size_t i = 0; i < D; ++i) {
    const double d = x[i].template convert_to<double>();
    std::snprintf(buf, sizeof buf, "%s%s%a", i ? " " : "", Q(d) == x[i] ? "" : "~", d);
    s += buf;
  }
  return s + ")";
}

template <std::size_t D>
struct Half {  // a·x ≤ b, with a, b rounded to doubles (ad, bd) for the filter of holds()
  V<D> a;
  Q b;
  std::array<double, D> ad{};
  double bd = 0;
  void round() {
    for (std::size_t i = 0; i < D; ++i) ad[i] = a[i].template convert_to<double>();
    bd = b.template convert_to<double>();
  }
};

// a·x ≤ b, exactly. Filter: with every input of the double sum rounded once (relative error
// ≤ 2^-53) and ≤ 2D + 1 roundings in the sum, |error| ≤ 2^-50·(Σ|a_i x_i| + |b|) + 2^-1000
// (underflow); the margin 2^-45 covers it. Values are ≤ a few units (points in [0,1]^D).
template <std::size_t D>
bool holds(const Half<D>& h, const V<D>& x, const std::array<double, D>& xd) {
  double s = 0, m = std::fabs(h.bd);
  for (std::size_t i = 0; i < D; ++i) {
    s += h.ad[i] * xd[i];
    m += std::fabs(h.ad[i] * xd[i]);
  }
  if (s <= h.bd - 0x1p-45 * m - 0x1p-1000) return true;
  if (s >= h.bd + 0x1p-45 * m + 0x1p-1000) return false;
  return dotq<D>(h.a, x) <= h.b;
}

template <std::size_t D>
Half<D> bisector(const V<D>& u) {  // points at least as close to the origin as to u
  Half<D> h;
  for (std::size_t i = 0; i < D; ++i) h.a[i] = 2 * u[i];
  h.b = dotq<D>(u, u);
  h.round();
  return h;
}

template <std::size_t D>
using Refs = std::vector<const Half<D>*>;

// The point of the flat {x : a·x = b for every constraint of E} nearest to the origin, or nullopt
// if the flat is empty: x = Σ λ_e a_e with G λ = b, G = Gram matrix (Gauss–Jordan; a dependent row
// must have a zero right-hand side, else the flat is empty).
template <std::size_t D>
std::optional<V<D>> project(const Refs<D>& E) {
  const std::size_t k = E.size();
  std::vector<std::vector<Q>> G(k, std::vector<Q>(k + 1));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) G[i][j] = dotq<D>(E[i]->a, E[j]->a);
    G[i][k] = E[i]->b;
  }
  std::vector<std::size_t> pivot;  // pivot column of each reduced row
  std::size_t r = 0;
  for (std::size_t c = 0; c < k && r < k; ++c) {
    std::size_t p = r;
    while (p < k && G[p][c] == 0) ++p;
    if (p == k) continue;
    std::swap(G[p], G[r]);
    for (std::size_t i = 0; i < k; ++i)
      if (i != r && G[i][c] != 0) {
        const Q f = G[i][c] / G[r][c];
        for (std::size_t j = c; j <= k; ++j) G[i][j] -= f * G[r][j];
      }
    pivot.push_back(c);
    ++r;
  }
  for (std::size_t i = r; i < k; ++i)
    if (G[i][k] != 0) return std::nullopt;
  V<D> x;
  for (auto& c : x) c = 0;
  for (std::size_t i = 0; i < r; ++i) {
    const Q lam = G[i][k] / G[i][pivot[i]];
    for (std::size_t d = 0; d < D; ++d) x[d] += lam * E[pivot[i]]->a[d];
  }
  return x;
}

// Seidel's incremental algorithm for the point of {x on the flat of E : H[0..n) hold} nearest to
// the origin (an LP-type problem: if the optimum for H[0..i) violates H[i], the optimum for
// H[0..i] lies on H[i]'s hyperplane). Each constraint pushed onto E raises the flat's codimension
// (it is violated at the flat's optimum), so |E| = D means the flat is a point. nullopt: empty.
template <std::size_t D>
std::optional<V<D>> min_norm(Refs<D>& E, const Refs<D>& H, std::size_t n) {
  auto x = project<D>(E);
  if (!x) return x;
  std::array<double, D> xd;
  for (std::size_t i = 0; i < D; ++i) xd[i] = (*x)[i].template convert_to<double>();
  for (std::size_t i = 0; i < n; ++i) {
    if (holds<D>(*H[i], *x, xd)) continue;
    if (E.size() == D) return std::nullopt;
    E.push_back(H[i]);
    x = min_norm<D>(E, H, i);
    E.pop_back();
    if (!x) return x;
    for (std::size_t j = 0; j < D; ++j) xd[j] = (*x)[j].template convert_to<double>();
  }
  return x;
}

template <std::size_t D>
Refs<D> shuffled(const std::vector<Half<D>>& hs) {  // a fixed pseudo-random order (expected O(m))
  Refs<D> r;
  for (const auto& h : hs) r.push_back(&h);
  std::mt19937_64 rng(20121);
  std::shuffle(r.begin(), r.end(), rng);
  return r;
}

// Determinant of a k×k matrix (k ≤ 3 here), by expansion along the first row.
Q det(const std::vector<std::vector<Q>>& A) {
  const std::size_t k = A.size();
  if (k == 0) return 1;
  Q s = 0;
  for (std::size_t c = 0; c < k; ++c) {
    if (A[0][c] == 0) continue;
    std::vector<std::vector<Q>> m;
    for (std::size_t r = 1; r < k; ++r) {
      std::vector<Q> row;
      for (std::size_t j = 0; j < k; ++j)
        if (j != c) row.push_back(A[r][j]);
      m.push_back(row);
    }
    const Q t = A[0][c] * det(m);
    s += (c % 2) ? -t : t;
  }
  return s;
}

// The generalised cross product of the D − 1 normals of S (d_j = (−1)^j · the minor without
// column j): orthogonal to all of them, nonzero iff they are independent (then the flat of S is a
// line with direction d).
template <std::size_t D>
std::optional<V<D>> line_direction(const Refs<D>& S) {
  V<D> d;
  bool nonzero = false;
  for (std::size_t j = 0; j < D; ++j) {
    std::vector<std::vector<Q>> m;
    for (const auto* h : S) {
      std::vector<Q> row;
      for (std::size_t i = 0; i < D; ++i)
        if (i != j) row.push_back(h->a[i]);
      m.push_back(row);
    }
    d[j] = det(m);
    if (j % 2) d[j] = -d[j];
    nonzero = nonzero || d[j] != 0;
  }
  if (!nonzero) return std::nullopt;
  return d;
}

// Calls f on every (D−1)-subset S of the facets F (as Refs) whose flat meets the polytope
// ∩ F (subsets are extended only while their flat meets it: a line through a vertex lies in such
// flats), in lexicographic order of indexes; stops when f returns false.
template <std::size_t D, class Fn>
bool for_subsets(const Refs<D>& F, std::size_t from, Refs<D>& S, Fn&& f) {
  if (S.size() == D - 1) return f(S);
  for (std::size_t i = from; i < F.size(); ++i) {
    S.push_back(F[i]);
    if (S.size() >= 2 && S.size() < D - 1) {
      Refs<D> E = S;
      if (!min_norm<D>(E, F, F.size())) {
        S.pop_back();
        continue;
      }
    }
    const bool go = for_subsets<D>(F, i + 1, S, f);
    S.pop_back();
    if (!go) return false;
  }
  return true;
}

// The vertices u ≠ v with |uv|² ≤ f·NN(v)² (f exact), relative to v, and NN(v)², exact. A double
// filter only narrows the exact scan: with d̃ the double |uv|² (relative error ≤ ε = 2^-45 for
// D ≤ 4, absolute ≤ δ = 2^-1000 from underflow), every u with |uv|² ≤ f·NN² has
// d̃_u ≤ f·(d̃_min + δ)(1 + ε)/(1 − ε) + δ, which the threshold below exceeds.
template <std::size_t D>
struct Near {
  std::optional<Q> nn2;
  std::vector<std::size_t> idx;
  std::vector<V<D>> q;
};
// Points finer than doubles: their rounded doubles c̃ (|c̃ − c| ≤ 2^-53·|c̃| + 2^-1074) only bound the
// distances. Per coordinate the true |Δ| lies in [|Δ̃|(1 − 2^-52) − a, |Δ̃|(1 + 2^-52) + a],
// a = (2^-53·(|ũ_i| + |ṽ_i|) + 2^-1073)(1 + 2^-50); summing the squares in doubles costs a relative
// 2^-50 at most (D ≤ 4), covered by the factors 1 ∓ 2^-48 and 2^-1000 for underflow. So
// lo_u ≤ |uv|² ≤ hi_u, NN² ≤ H = min hi, and only u with lo_u ≤ max(1, f)·H need the exact scan.
template <std::size_t D>
Near<D> near_fine(const Points<D>& P, std::size_t v, const Q& f) {
  Near<D> out;
  const auto& M = P.d;
  std::vector<double> lo(M.size());
  double H = std::numeric_limits<double>::infinity();
  for (std::size_t u = 0; u < M.size(); ++u) {
    if (u == v) continue;
    double l = 0, h = 0;
    for (std::size_t i = 0; i < D; ++i) {
      const double a = (0x1p-53 * (std::fabs(M[u][i]) + std::fabs(M[v][i])) + 0x1p-1073) * (1 + 0x1p-50);
      const double t = std::fabs(M[u][i] - M[v][i]);
      const double li = std::max(0.0, t * (1 - 0x1p-52) - a), hi = t * (1 + 0x1p-52) + a;
      l += li * li;
      h += hi * hi;
    }
    lo[u] = l * (1 - 0x1p-48);
    H = std::min(H, h * (1 + 0x1p-48) + 0x1p-1000);
  }
  const double bound = std::max(1.0, f.convert_to<double>() * (1 + 0x1p-30)) * H * (1 + 0x1p-30);
  std::vector<std::pair<std::size_t, Q>> cand;
  for (std::size_t u = 0; u < M.size(); ++u) {
    if (u == v || !(lo[u] <= bound)) continue;
    const V<D> x = rel<D>(P.q[u], P.q[v]);
    const Q d = dotq<D>(x, x);
    if (!out.nn2 || d < *out.nn2) out.nn2 = d;
    cand.emplace_back(u, d);
  }
  for (const auto& [u, d] : cand)
    if (d <= f * *out.nn2) {
      out.idx.push_back(u);
      out.q.push_back(rel<D>(P.q[u], P.q[v]));
    }
  return out;
}
// Double points: the filter above.
template <std::size_t D>
Near<D> near(const Points<D>& P, std::size_t v, const Q& f) {
  if (!P.doubles) return near_fine<D>(P, v, f);
  const auto& M = P.d;
  std::vector<double> dd(M.size());
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t u = 0; u < M.size(); ++u) {
    double d = 0;
    for (std::size_t i = 0; i < D; ++i) d += (M[u][i] - M[v][i]) * (M[u][i] - M[v][i]);
    dd[u] = d;
    if (u != v) dmin = std::min(dmin, d);
  }
  Near<D> out;
  if (M.size() < 2) return out;
  const double delta = 0x1p-1000;
  auto threshold = [&](double factor) { return factor * (1 + 0x1p-30) * (dmin + delta) * (1 + 0x1p-30) + delta; };
  const double t1 = threshold(1), tf = threshold(f.convert_to<double>() * (1 + 0x1p-30));
  std::vector<std::pair<std::size_t, Q>> cand;
  for (std::size_t u = 0; u < M.size(); ++u) {
    if (u == v || !(dd[u] <= std::max(t1, tf))) continue;
    const V<D> x = rel<D>(P.q[u], P.q[v]);
    const Q d = dotq<D>(x, x);
    if (dd[u] <= t1 && (!out.nn2 || d < *out.nn2)) out.nn2 = d;
    cand.emplace_back(u, d);
    out.q.push_back(x);
  }
  std::vector<V<D>> q;
  for (std::size_t j = 0; j < cand.size(); ++j)
    if (cand[j].second <= f * *out.nn2) {
      out.idx.push_back(cand[j].first);
      q.push_back(out.q[j]);
    }
  out.q = std::move(q);
  return out;
}


// Vor(v) ∩ [0,1]^D ⊆ B(v, R), R = ρ·NN: only vertices u with |uv| ≤ 2R can cut B(v, R), and the
// cell C' of those constraints is inside B(v, R) iff the true cell is (if C' poked out, the segment
// from v to such a point would leave the true cell inside B(v, R), through the bisector of some u
// with |uv| ≤ 2R). C' is the intersection of its facets (the constraints whose hyperplane meets
// C', found by min_norm); every vertex of C' is an endpoint of C' ∩ ℓ for the line ℓ of some
// D − 1 independent facets through it, and the farthest point of C' from v is a vertex.
template <std::size_t D>
bool well_spaced(const Points<D>& P, double rho, std::string* why) {
  const auto& M = P.q;
  for (std::size_t v = 0; v < M.size(); ++v) {
    const Q rho2 = Q(rho) * Q(rho);
    const Near<D> nb = near<D>(P, v, 4 * rho2);
    if (!nb.nn2) continue;
    const auto& nn2 = nb.nn2;
    const Q R2 = rho2 * *nn2;
    std::vector<Half<D>> hs;
    for (std::size_t i = 0; i < D; ++i) {
      Half<D> lo, hi;  // −x_i ≤ v_i and x_i ≤ 1 − v_i
      for (std::size_t j = 0; j < D; ++j) lo.a[j] = hi.a[j] = 0;
      lo.a[i] = -1;
      lo.b = M[v][i];
      hi.a[i] = 1;
      hi.b = 1 - M[v][i];
      lo.round();
      hi.round();
      hs.push_back(lo);
      hs.push_back(hi);
    }
    for (const auto& x : nb.q) hs.push_back(bisector<D>(x));  // |uv| ≤ 2R
    const Refs<D> all = shuffled<D>(hs);
    Refs<D> facets;
    for (std::size_t c = 0; c < all.size(); ++c) {
      Refs<D> E{all[c]}, H;
      for (std::size_t j = 0; j < all.size(); ++j)
        if (j != c) H.push_back(all[j]);
      if (min_norm<D>(E, H, H.size())) facets.push_back(all[c]);
    }
    bool ok = true;
    Refs<D> S;
    for_subsets<D>(facets, 0, S, [&](const Refs<D>& S) {
      auto x0 = project<D>(S);
      auto d = line_direction<D>(S);
      if (!x0 || !d) return true;
      std::optional<Q> tlo, thi;
      for (const auto* f : facets) {
        if (std::find(S.begin(), S.end(), f) != S.end()) continue;
        const Q ad = dotq<D>(f->a, *d), s = f->b - dotq<D>(f->a, *x0);
        if (ad == 0) {
          if (s < 0) return true;  // the line misses C'
        } else if (ad > 0) {
          const Q t = s / ad;
          if (!thi || t < *thi) thi = t;
        } else {
          const Q t = s / ad;
          if (!tlo || t > *tlo) tlo = t;
        }
      }
      if (!tlo || !thi) {  // C' is bounded (the box): cannot happen
        ok = false;
        if (why) *why = "vertex " + fmt<D>(M[v]) + ": unbounded cell in the judge (bug)";
        return false;
      }
      if (*tlo > *thi) return true;
      for (const Q& t : {*tlo, *thi}) {
        V<D> x;
        for (std::size_t i = 0; i < D; ++i) x[i] = (*x0)[i] + t * (*d)[i];
        if (dotq<D>(x, x) > R2) {
          ok = false;
          if (why) *why = "vertex " + fmt<D>(M[v]) + " is not rho-well-spaced (a vertex of its cell is farther than rho*NN)";
          return false;
        }
      }
      return true;
    });
    if (!ok) return false;
  }
  return true;
}

template <std::size_t D>
bool size_conforming(const std::vector<V<D>>& N, const std::vector<V<D>>& M, double rho, std::string* why) {
  const Q c = Q(2) * Q(rho) / (Q(rho) - 1), c2 = c * c;
  for (std::size_t v = 0; v < M.size(); ++v) {
    // lfs_N(v): radius of the smallest ball around v holding two input points
    std::optional<Q> a, b;
    for (const auto& x : N) {
      const V<D> d = rel<D>(x, M[v]);
      const Q r = dotq<D>(d, d);
      if (!a || r < *a) {
        b = a;
        a = r;
      } else if (!b || r < *b) {
        b = r;
      }
    }
    std::optional<Q> nn2;
    for (std::size_t u = 0; u < M.size(); ++u)
      if (u != v) {
        const V<D> d = rel<D>(M[u], M[v]);
        const Q r = dotq<D>(d, d);
        if (!nn2 || r < *nn2) nn2 = r;
      }
    if (!b || !nn2) continue;
    if (c2 * *nn2 < *b) {
      if (why) *why = "vertex " + fmt<D>(M[v]) + " violates NN >= lfs/c";
      return false;
    }
  }
  return true;
}

// u is a β-clipped Voronoi neighbour of v iff the nearest point to v of the face of Vor(v) on the
// bisector of v, u (min_norm with that bisector tight) is within r = β·NN. Only vertices w with
// |wv| ≤ 2r matter: a point x with |xv| ≤ r has |xw| ≥ |wv| − r ≥ r ≥ |xv| for the others, so
// dropping them changes neither "some face point within r" nor "none".
template <std::size_t D>
std::vector<std::size_t> neighbors(const Points<D>& P, std::size_t v, double beta) {
  std::vector<std::size_t> out;
  const Q beta2 = Q(beta) * Q(beta);
  const Near<D> nb = near<D>(P, v, 4 * beta2);  // |uv| ≤ 2r, r = β·NN
  if (!nb.nn2) return out;
  const Q r2 = beta2 * *nb.nn2;
  const std::vector<std::size_t>& cand = nb.idx;
  std::vector<Half<D>> hs;
  for (const auto& x : nb.q) hs.push_back(bisector<D>(x));
  const Refs<D> order = shuffled<D>(hs);
  for (std::size_t i = 0; i < cand.size(); ++i) {
    Refs<D> E{&hs[i]}, H;
    for (const auto* h : order)
      if (h != &hs[i]) H.push_back(h);
    auto x = min_norm<D>(E, H, H.size());
    if (x && dotq<D>(*x, *x) <= r2) out.push_back(cand[i]);
  }
  return out;
}

}  // namespace

template <std::size_t D>
bool is_well_spaced(const std::vector<std::array<double, D>>& M, double rho, std::string* why) {
  return well_spaced<D>(points<D>(M), rho, why);
}
template <std::size_t D>
bool is_well_spaced(const std::vector<ExactPoint<D>>& M, double rho, std::string* why) {
  return well_spaced<D>(points<D>(M), rho, why);
}
template <std::size_t D>
bool is_size_conforming(const std::vector<std::array<double, D>>& N, const std::vector<std::array<double, D>>& M,
                        double rho, std::string* why) {
  return size_conforming<D>(points<D>(N).q, points<D>(M).q, rho, why);
}
template <std::size_t D>
bool is_size_conforming(const std::vector<std::array<double, D>>& N, const std::vector<ExactPoint<D>>& M, double rho,
                        std::string* why) {
  return size_conforming<D>(points<D>(N).q, M, rho, why);
}
template <std::size_t D>
std::vector<std::size_t> clipped_voronoi_neighbors(const std::vector<std::array<double, D>>& M, std::size_t v, double beta) {
  return neighbors<D>(points<D>(M), v, beta);
}
template <std::size_t D>
std::vector<std::size_t> clipped_voronoi_neighbors(const std::vector<ExactPoint<D>>& M, std::size_t v, double beta) {
  return neighbors<D>(points<D>(M), v, beta);
}

// [+-]0x<hex>[.<hex>]p[+-]<dec>, exactly: the hex digits as an integer m with f fraction digits,
// value m·2^(e − 4f).
Rational read_hex_float(const std::string& s) {
  auto bad = [&] { return std::invalid_argument("not a hex float: \"" + s + "\""); };
  std::size_t i = 0;
  bool neg = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  if (s.compare(i, 2, "0x") != 0 && s.compare(i, 2, "0X") != 0) throw bad();
  i += 2;
  boost::multiprecision::mpz_int m = 0;
  long frac = 0, digits = 0;
  bool point = false;
  for (; i < s.size() && s[i] != 'p' && s[i] != 'P'; ++i) {
    const char c = s[i];
    int h;
    if (c >= '0' && c <= '9') h = c - '0';
    else if (c >= 'a' && c <= 'f') h = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') h = c - 'A' + 10;
    else if (c == '.' && !point) { point = true; continue; }
    else throw bad();
    m = m * 16 + h;
    ++digits;
    if (point) ++frac;
  }
  if (digits == 0 || i + 1 >= s.size()) throw bad();
  ++i;  // 'p'
  bool eneg = false;
  if (s[i] == '+' || s[i] == '-') eneg = s[i++] == '-';
  if (i >= s.size() || s.size() - i > 9) throw bad();
  long e = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') throw bad();
    e = e * 10 + (s[i] - '0');
  }
  e = (eneg ? -e : e) - 4 * frac;
  Rational x(m);
  if (e >= 0) x *= Rational(boost::multiprecision::mpz_int(1) << static_cast<unsigned>(e));
  else x /= Rational(boost::multiprecision::mpz_int(1) << static_cast<unsigned>(-e));
  return neg ? Rational(-x) : x;
}

#define KMR_WSJUDGE_INSTANTIATE(DIM)                                                                              \
  template bool is_well_spaced<DIM>(const std::vector<std::array<double, DIM>>&, double, std::string*);          \
  template bool is_size_conforming<DIM>(const std::vector<std::array<double, DIM>>&,                             \
                                        const std::vector<std::array<double, DIM>>&, double, std::string*);     \
  template std::vector<std::size_t> clipped_voronoi_neighbors<DIM>(const std::vector<std::array<double, DIM>>&, \
                                                                   std::size_t, double);
#define KMR_WSJUDGE_INSTANTIATE_EXACT(DIM)                                                                        \
  template bool is_well_spaced<DIM>(const std::vector<ExactPoint<DIM>>&, double, std::string*);                  \
  template bool is_size_conforming<DIM>(const std::vector<std::array<double, DIM>>&,                             \
                                        const std::vector<ExactPoint<DIM>>&, double, std::string*);             \
  template std::vector<std::size_t> clipped_voronoi_neighbors<DIM>(const std::vector<ExactPoint<DIM>>&,         \
                                                                   std::size_t, double);
KMR_WSJUDGE_INSTANTIATE_EXACT(2)
KMR_WSJUDGE_INSTANTIATE_EXACT(3)
KMR_WSJUDGE_INSTANTIATE_EXACT(4)
KMR_WSJUDGE_INSTANTIATE(2)
KMR_WSJUDGE_INSTANTIATE(3)
KMR_WSJUDGE_INSTANTIATE(4)

}  // namespace kmr::wsjudge
