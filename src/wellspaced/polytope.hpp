#pragma once
// Convex polytopes in Q^D by halfspace clipping (§3.2.4: clipped Voronoi cells), over a number type
// NT: Q (exact rationals) or exact::IntervalNT (the fast tier: it throws exact::Uncertain whenever a
// decision is too close to call, and the caller redoes the computation with NT = Q).
// Guarantees (tests/wellspaced/polytope_test.cpp):
//  * clip() keeps exactly the vertices of the clipped polytope; each vertex carries the sorted set of
//    constraints tight at it. Edges are found by the combinatorial adjacency test (p, q adjacent iff
//    no third vertex is tight on every constraint tight at both), exact also for degenerate
//    (cospherical, cocircular) inputs.
//  * Every decision (signs of constraints at vertices, distance comparisons) is exact: first on
//    interval enclosures, then, if those do not decide, in NT (exact for Q; Uncertain for intervals).
//    So a Polytope<D, IntervalNT> that does not throw makes the same decisions as Polytope<D, Q>.
//  * face_within(): exact decision "some point of the face {x ∈ P : constraint j tight} lies within
//    squared distance r2 of point c", by the active-set enumeration of the KKT points.
#include <algorithm>
#include <array>
#include <bit>
#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "geometry/point.hpp"
#include "exact/error.hpp"
#include "exact/interval_nt.hpp"
#include "wellspaced/vertex_point.hpp"

namespace kmr::wellspaced {

using Q = boost::multiprecision::mpq_rational;
using exact::IntervalNT;
using exact::Uncertain;
using exact::throw_uncertain;

template <std::size_t D>
using QPoint = std::array<Q, D>;
template <std::size_t D>
using IPoint = std::array<IntervalNT, D>;

template <class NT>
inline constexpr bool is_interval_v = std::is_same_v<NT, IntervalNT>;

// Exact point of a double point, in NT.
template <class NT, std::size_t D>
std::array<NT, D> point_in(const std::array<double, D>& p) {
  std::array<NT, D> q;
  for (std::size_t i = 0; i < D; ++i) q[i] = NT(p[i]);
  return q;
}
// p − v in NT: cells are computed relative to their site v, so that bisectors of nearby points
// carry small, well-conditioned numbers (absolute coordinates would cancel catastrophically).
template <class NT, std::size_t D>
std::array<NT, D> relative_to(const std::array<double, D>& p, const std::array<double, D>& v) {
  std::array<NT, D> q;
  for (std::size_t i = 0; i < D; ++i) q[i] = NT(p[i]) - NT(v[i]);
  return q;
}
template <std::size_t D>
QPoint<D> to_q(const std::array<double, D>& p) { return point_in<Q, D>(p); }

// The exact rational of a dyadic m·2^e.
inline Q to_q(const exact::Dyadic& x) {
  Q q(x.mantissa());
  auto* r = q.backend().data();
  const std::int64_t e = x.exponent();
  if (e > 0) mpq_mul_2exp(r, r, static_cast<mp_bitcnt_t>(e));
  else if (e < 0) mpq_div_2exp(r, r, static_cast<mp_bitcnt_t>(-e));
  return q;
}
// A Q (exact) or its enclosure (IntervalNT).
template <class NT>
NT from_q(const Q& x) {
  if constexpr (is_interval_v<NT>) return exact::enclose(x);
  else return x;
}
// The same for vertices (VertexPoint: doubles as above; finer coordinates through Q).
template <class NT, std::size_t D>
std::array<NT, D> point_in(const VertexPoint<D>& p) {
  if (p.is_double()) return point_in<NT, D>(p.below());
  std::array<NT, D> q;
  for (std::size_t i = 0; i < D; ++i) q[i] = from_q<NT>(to_q(p.coord(i)));
  return q;
}
template <std::size_t D>
QPoint<D> to_q(const VertexPoint<D>& p) { return point_in<Q, D>(p); }
// |ab|² as a double estimate (orders and sizes work only; never decides): for doubles the plain
// double sum (as before VertexPoint), else the exact value rounded.
template <std::size_t D>
double approx_dist2(const VertexPoint<D>& a, const VertexPoint<D>& b) {
  if (a.is_double() && b.is_double()) {
    double nd = 0;
    for (std::size_t i = 0; i < D; ++i) nd += (a.below()[i] - b.below()[i]) * (a.below()[i] - b.below()[i]);
    return nd;
  }
  return geometry::dist2(to_q<D>(a), to_q<D>(b)).template convert_to<double>();
}
template <class NT, std::size_t D>
std::array<NT, D> relative_to(const VertexPoint<D>& p, const VertexPoint<D>& v) {
  if (p.is_double() && v.is_double()) return relative_to<NT, D>(p.below(), v.below());
  std::array<NT, D> q;
  for (std::size_t i = 0; i < D; ++i) q[i] = from_q<NT>(to_q(p.coord(i)) - to_q(v.coord(i)));
  return q;
}

template <class NT, std::size_t D>
IPoint<D> enclose(const std::array<NT, D>& x) {
  IPoint<D> e;
  for (std::size_t i = 0; i < D; ++i) e[i] = exact::enclose(x[i]);
  return e;
}

using geometry::dist2;  // |a − b|², one definition for the library (geometry/point.hpp)
using geometry::dot;

// Sign of a quantity decided on its enclosure `approx` when possible, else by `exact()` (NT = Q)
// or by throwing Uncertain (NT = IntervalNT).
template <class NT, class Exact>
int filtered_sign(const IntervalNT& approx, Exact&& exact) {
  if (approx.lo() > 0) return 1;
  if (approx.hi() < 0) return -1;
  if (approx.lo() == 0 && approx.hi() == 0) return 0;
  if constexpr (is_interval_v<NT>) throw Uncertain();
  else return exact().sign();
}

// Static double filter (issue 11 §4; Shewchuk's fast/exact split) in front of the interval
// enclosures: the value is evaluated once in plain doubles at a point of the enclosures (their
// lower ends) with an a-priori bound E on its distance from the value at EVERY point of them;
// the sign is decided when |value| > E, else 0 ("undecided": the caller falls to the intervals,
// then to exact arithmetic). Bound (u = 2^-53, Higham §3.1): for a ∈ [a', a'+wa], x ∈ [x', x'+wx],
// |a·x − a'·x'| ≤ wa·(|x'| + wx) + |a'|·wx; a dot product of n terms has rounding error
// ≤ γ_n·Σ|terms| < (n+1)·u·Σ|terms|; the bound's own roundings (< 4(D+2)u relative) and underflow
// (each product ≤ 2^-1075 off) are covered by the factor 1 + 2^-40 and the absolute 2^-1000.
namespace double_filter {

using exact::next_down;  // exact/interval_nt.hpp
using exact::next_up;
inline constexpr double kSafety = 1 + 0x1p-40;
inline constexpr double kTinyAbs = 0x1p-1000;
// 1 / −1 when every point of the enclosures has Σ a_i·x_i − b of that sign; 0 undecided.
template <std::size_t D>
inline int dot_minus_sign(const IPoint<D>& a, const IPoint<D>& x, const IntervalNT& b) {
  double s = 0, mag = 0, wide = 0;
  for (std::size_t i = 0; i < D; ++i) {
    const double al = a[i].lo(), xl = x[i].lo(), wa = a[i].hi() - al, wx = x[i].hi() - xl;
    const double p = al * xl;
    s += p;
    mag += std::fabs(p);
    wide += wa * (std::fabs(xl) + wx) + std::fabs(al) * wx;
  }
  const double bl = b.lo();
  s -= bl;
  mag += std::fabs(bl);
  wide += b.hi() - bl;
  const double e = (wide + mag * (double(D + 2) * 0x1p-52)) * kSafety + kTinyAbs;
  if (s > e) return 1;
  if (s < -e) return -1;
  return 0;  // also when e or s is not finite (comparisons with NaN are false)
}
// 1 / −1 when every point of the enclosures has |x − c|² − r2 of that sign; 0 undecided.
template <std::size_t D>
inline int dist2_minus_sign(const IPoint<D>& x, const IPoint<D>& c, const IntervalNT& r2) {
  double s = 0, mag = 0, wide = 0;
  for (std::size_t i = 0; i < D; ++i) {
    // d = fl(x' − c'), within δ = wx + wc + 2u|d| of every x_i − c_i; |t² − d²| ≤ δ(2|d| + δ)
    const double xl = x[i].lo(), cl = c[i].lo();
    const double d = xl - cl, ad = std::fabs(d);
    const double delta = (x[i].hi() - xl) + (c[i].hi() - cl) + ad * 0x1p-52;
    const double q = d * d;
    s += q;
    mag += q;
    wide += delta * (2 * ad + delta);
  }
  const double rl = r2.lo();
  s -= rl;
  mag += std::fabs(rl);
  wide += r2.hi() - rl;
  const double e = (wide + mag * (double(D + 2) * 0x1p-52)) * kSafety + kTinyAbs;
  if (s > e) return 1;
  if (s < -e) return -1;
  return 0;
}
// Enclosure of the meeting point of the lines A·x = B and E·x = F (2D, Cramer's rule:
// x = (B·E1 − A1·F, A0·F − B·E0) / (A0·E1 − A1·E0)) for every point of the enclosures, from
// one evaluation in doubles at their lower ends (issue 11 §4: the new vertices of a 2D clip).
// Each of the three 2×2 terms x·y − z·w is off by ≤ wx(|y'| + wy) + |x'|wy (+ the same for z·w)
// from its value at any point of the enclosures, plus ≤ 3u(|x'y'| + |z'w'|) of rounding; for
// |d − d'| ≤ Ed < |d'| and |n − n'| ≤ En, |n/d − n'/d'| ≤ (En + |n'/d'|·Ed) / (|d'| − Ed), and
// q = fl(n'/d') is within u|q|·(1 + u) of n'/d'. The bound's own roundings are covered by the
// factor 1 + 2^-40 (and 1 − 2^-40 on the denominator), underflow by 2^-1000 absolute; the
// endpoints are then stepped outward by one double. Throws Uncertain when the determinant's
// enclosure may hold 0, is tiny (< 2^-900), or anything is not finite.
inline std::array<IntervalNT, 2> meet_lines_2d(const std::array<IntervalNT, 2>& A, const IntervalNT& B,
                                              const std::array<IntervalNT, 2>& E, const IntervalNT& F) {
  struct Term {
    double v, err;
  };
  auto term = [](const IntervalNT& x, const IntervalNT& y, const IntervalNT& z, const IntervalNT& w) {
    const double xl = x.lo(), yl = y.lo(), zl = z.lo(), wl = w.lo();
    const double wx = x.hi() - xl, wy = y.hi() - yl, wz = z.hi() - zl, ww = w.hi() - wl;
    const double p1 = xl * yl, p2 = zl * wl;
    const double width = wx * (std::fabs(yl) + wy) + std::fabs(xl) * wy + wz * (std::fabs(wl) + ww) + std::fabs(zl) * ww;
    return Term{p1 - p2, (width + 3 * 0x1p-53 * (std::fabs(p1) + std::fabs(p2))) * kSafety + kTinyAbs};
  };
  const Term d = term(A[0], E[1], A[1], E[0]);
  const double ad = std::fabs(d.v);
  if (!(ad >= 0x1p-900 && ad > 2 * d.err)) throw_uncertain();
  const double denom = (ad - d.err) * (1 - 0x1p-40);  // ≤ |d| for every d of the enclosure
  std::array<IntervalNT, 2> x;
  const Term n[2] = {term(B, E[1], A[1], F), term(A[0], F, B, E[0])};
  for (std::size_t i = 0; i < 2; ++i) {
    const double q = n[i].v / d.v, aq = std::fabs(q);
    const double e = ((n[i].err + aq * (1 + 0x1p-52) * d.err) / denom + aq * 0x1p-52) * kSafety + kTinyAbs;
    x[i] = IntervalNT::hull(next_down(q - e), next_up(q + e));  // throws if not finite
  }
  return x;
}
// Enclosure of the solution x of the D×D system a_k·x = b_k (k < D) for EVERY point of the
// enclosures of a_k, b_k, from doubles (issue 11 §5: the new vertices of a 3D/4D clip from their
// D tight constraints, instead of p + λ(q − p) through the enclosures of the edge's ends, whose
// widths compound clip after clip: up to 10 % relative on 4D clustered cells). A posteriori, in
// the manner of Krawczyk and Rump: A', b' are the lower ends, R ≈ A'^-1 (Gauss–Jordan, partial
// pivoting), x̃ = R·b'. For any A, b of the enclosures:
//  * r = b − A·x̃ lies in s ± E: s_k = fl(b'_k − a'_k·x̃), E_k = w(b_k) + Σ_i w(a_ki)·|x̃_i| +
//    γ·(|b'_k| + Σ_i |a'_ki·x̃_i|) (a sum of D + 1 terms: γ = 2(D + 2)u ≥ γ_{D+1}, u = 2^-53);
//  * |I − R·A| ≤ G entrywise: G_ij = |fl(δ_ij − Σ_k R_ik·a'_kj)| + Σ_k |R_ik|·w(a_kj) +
//    γ·(δ_ij + Σ_k |R_ik·a'_kj|); α = max_i Σ_j G_ij must be ≤ ½ (else refused: A may be singular);
//  * R·r lies in c ± ρ: c_i = fl(Σ_k R_ik·s_k), ρ_i = Σ_k |R_ik|·E_k + γ·Σ_k |R_ik·s_k|.
// α < 1 makes R·A, hence A, nonsingular; e = x − x̃ = R·r + (I − R·A)·e gives
// ‖e‖∞ ≤ η = max_i (|c_i| + ρ_i) / (1 − α) and e_i ∈ c_i ± (ρ_i + (Σ_j G_ij)·η). The sum
// m_i = fl(x̃_i + c_i) is within u·|m_i|·(1 + u) of x̃_i + c_i. Every bound is a sum of products of
// nonnegative doubles (relative rounding < 4(D + 2)u: the factor 1 + 2^-40; each product's
// underflow ≤ 2^-1075: the absolute 2^-1000), and the endpoints are stepped outward by one
// double. Returns false (nothing decided; the caller has another way) when a pivot is 0, α > ½,
// or anything is not finite.
template <std::size_t D>
inline bool solve_rows(const std::array<const IPoint<D>*, D>& a, const std::array<const IntervalNT*, D>& b,
                       IPoint<D>& x) {
  constexpr double u = 0x1p-53, gam = 2.0 * double(D + 2) * u;
  double M[D][2 * D];  // [A' | I] → [I | R]
  for (std::size_t k = 0; k < D; ++k)
    for (std::size_t j = 0; j < D; ++j) {
      M[k][j] = (*a[k])[j].lo();
      M[k][D + j] = k == j ? 1.0 : 0.0;
    }
  for (std::size_t col = 0; col < D; ++col) {
    std::size_t piv = col;
    for (std::size_t r = col + 1; r < D; ++r)
      if (std::fabs(M[r][col]) > std::fabs(M[piv][col])) piv = r;
    if (!(std::fabs(M[piv][col]) > 0)) return false;
    if (piv != col)
      for (std::size_t j = 0; j < 2 * D; ++j) std::swap(M[piv][j], M[col][j]);
    const double inv = 1.0 / M[col][col];
    for (std::size_t j = 0; j < 2 * D; ++j) M[col][j] *= inv;
    for (std::size_t r = 0; r < D; ++r) {
      if (r == col || M[r][col] == 0) continue;
      const double f = M[r][col];
      for (std::size_t j = 0; j < 2 * D; ++j) M[r][j] -= f * M[col][j];
    }
  }
  double R[D][D], xt[D];
  for (std::size_t i = 0; i < D; ++i) {
    xt[i] = 0;
    for (std::size_t k = 0; k < D; ++k) {
      R[i][k] = M[i][D + k];
      xt[i] += R[i][k] * b[k]->lo();
    }
  }
  double s[D], E[D];
  for (std::size_t k = 0; k < D; ++k) {
    const double bl = b[k]->lo();
    double v = bl, mag = std::fabs(bl), wide = b[k]->hi() - bl;
    for (std::size_t i = 0; i < D; ++i) {
      const double al = (*a[k])[i].lo(), p = al * xt[i];
      v -= p;
      mag += std::fabs(p);
      wide += ((*a[k])[i].hi() - al) * std::fabs(xt[i]);
    }
    s[k] = v;
    E[k] = (wide + gam * mag) * kSafety + kTinyAbs;
  }
  double alpha = 0, rowG[D];
  for (std::size_t i = 0; i < D; ++i) {
    rowG[i] = 0;
    for (std::size_t j = 0; j < D; ++j) {
      double t = i == j ? 1.0 : 0.0, mag = t, wide = 0;
      for (std::size_t k = 0; k < D; ++k) {
        const double al = (*a[k])[j].lo(), p = R[i][k] * al;
        t -= p;
        mag += std::fabs(p);
        wide += std::fabs(R[i][k]) * ((*a[k])[j].hi() - al);
      }
      rowG[i] += (std::fabs(t) + wide + gam * mag) * kSafety + kTinyAbs;
    }
    rowG[i] *= kSafety;
    alpha = std::max(alpha, rowG[i]);
  }
  if (!(alpha <= 0.5)) return false;
  double c[D], rho[D], eta = 0;
  for (std::size_t i = 0; i < D; ++i) {
    double v = 0, mag = 0, prop = 0;
    for (std::size_t k = 0; k < D; ++k) {
      const double p = R[i][k] * s[k];
      v += p;
      mag += std::fabs(p);
      prop += std::fabs(R[i][k]) * E[k];
    }
    c[i] = v;
    rho[i] = (prop + gam * mag) * kSafety + kTinyAbs;
    eta = std::max(eta, (std::fabs(v) + rho[i]) * kSafety);
  }
  eta = eta / ((1 - alpha) * (1 - 0x1p-40)) * kSafety;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < D; ++i) {
    const double m = xt[i] + c[i];
    const double rad = (rho[i] + rowG[i] * eta + 2 * u * std::fabs(m)) * kSafety + kTinyAbs;
    const double lo = next_down(m - rad), hi = next_up(m + rad);
    if (!(std::fabs(lo) < inf && std::fabs(hi) < inf)) return false;
    x[i] = IntervalNT::hull(lo, hi);
  }
  return true;
}
}  // namespace double_filter

template <std::size_t D, class NT = Q>
struct Halfspace {  // a·x ≤ b
  std::array<NT, D> a;
  NT b;
};

// Bisector halfspace of v against u: points at least as close to v as to u.
template <std::size_t D, class NT>
Halfspace<D, NT> bisector(const std::array<NT, D>& v, const std::array<NT, D>& u) {
  Halfspace<D, NT> h;
  for (std::size_t i = 0; i < D; ++i) h.a[i] = u[i] - v[i];
  h.b = (dot(u, u) - dot(v, v)) * NT(0.5);  // halving: exact (a multiplication is cheaper)
  return h;
}

// The constraints tight at a vertex, sorted: inline up to kInline (D of them at a simple vertex;
// more only at degenerate ones, cocircular/cospherical), on the heap beyond (issue 11 §4: no heap
// traffic per vertex in the common case).
class TightSet {
 public:
  static constexpr std::uint32_t kInline = 6;
  const int* begin() const { return n_ <= kInline ? in_.data() : big_.data(); }
  const int* end() const { return begin() + n_; }
  int* begin() { return n_ <= kInline ? in_.data() : big_.data(); }
  int* end() { return begin() + n_; }
  std::size_t size() const { return n_; }
  void clear() {
    n_ = 0;
    big_.clear();
  }
  void push_back(int x) {
    if (n_ < kInline) {
      in_[n_++] = x;
      return;
    }
    if (n_ == kInline) big_.assign(in_.begin(), in_.end());
    big_.push_back(x);
    ++n_;
  }

 private:
  std::array<int, kInline> in_{};
  std::uint32_t n_ = 0;
  std::vector<int> big_;  // all elements when n_ > kInline
};

// bisector(0, u): the site at the origin (cells relative to their site). The zero terms are left
// out; the values, and in the interval tier the enclosures, are those of bisector(0, u).
template <std::size_t D, class NT>
Halfspace<D, NT> bisector_of_origin(const std::array<NT, D>& u) {
  Halfspace<D, NT> h;
  h.a = u;
  h.b = dot(u, u) * NT(0.5);
  return h;
}

template <std::size_t D, class NT = Q>
struct Polytope {
  using P = std::array<NT, D>;
  struct Vert {
    P x;
    TightSet tight;  // sorted constraint indices
    IPoint<D> xi{};  // enclosure of x (the filter)
    IntervalNT n2i;  // enclosure of |x|² (the squared distance from the site at the origin)
    void set_enclosures() {
      xi = enclose<NT, D>(x);
      n2i = dot(xi, xi);  // = dist2(xi, origin) bit for bit: subtracting [−0, −0] changes no endpoint
    }
  };
  struct Constraint {
    Halfspace<D, NT> h;
    IPoint<D> ai;  // enclosures of h.a, h.b
    IntervalNT bi;
  };
  std::vector<Constraint> h;
  std::vector<Vert> v;
  unsigned version = 0;  // bumped whenever the vertex set changes

  // The box [lo, hi]; constraint 2i is x_i ≤ hi_i, 2i+1 is −x_i ≤ −lo_i.
  static Polytope box(const P& lo, const P& hi) {
    Polytope B;
    B.reset_box(lo, hi);
    return B;
  }
  // Makes this polytope the box [lo, hi], as box(lo, hi) builds it, keeping the storage of its
  // vectors (issue 11 §4: the scan and the fill reuse one cell each instead of allocating a new
  // one per call; test WellspacedPolytope.ReusedCellEqualsFreshCell).
  void reset_box(const P& lo, const P& hi) {
    Polytope& B = *this;
    B.h.clear();
    B.v.clear();
    B.ring_.clear();
    B.version = 0;
    for (std::size_t i = 0; i < D; ++i) {
      Halfspace<D, NT> up, dn;
      for (std::size_t j = 0; j < D; ++j) up.a[j] = dn.a[j] = NT(0);
      up.a[i] = NT(1);
      up.b = hi[i];
      dn.a[i] = NT(-1);
      dn.b = -lo[i];
      B.add(up);
      B.add(dn);
    }
    for (unsigned m = 0; m < (1u << D); ++m) {
      Vert c;
      for (std::size_t i = 0; i < D; ++i) {
        bool hiside = (m >> i) & 1u;
        c.x[i] = hiside ? hi[i] : lo[i];
        c.tight.push_back(static_cast<int>(2 * i + (hiside ? 0 : 1)));
      }
      std::sort(c.tight.begin(), c.tight.end());
      c.set_enclosures();
      B.v.push_back(std::move(c));
    }
    if constexpr (D == 2) {  // the cycle (lo,lo), (hi,lo), (hi,hi), (lo,hi), when lo < hi surely
      bool full = true;
      for (std::size_t i = 0; i < D; ++i) {
        if constexpr (is_interval_v<NT>) full = full && lo[i].hi() < hi[i].lo();
        else full = full && lo[i] < hi[i];
      }
      if (full) B.ring_ = {0, 1, 3, 2};
    }
  }

  NT slack(const Halfspace<D, NT>& hs, const P& x) const { return dot(hs.a, x) - hs.b; }
  // Exact sign of a·x − b for constraint k at a point with enclosure xi.
  int sign_at(std::size_t k, const P& x, const IPoint<D>& xi) const {
    const Constraint& c = h[k];
    if constexpr (is_interval_v<NT>)  // the fast tier only: exact_only runs judge the filter
      if (int s = double_filter::dot_minus_sign<D>(c.ai, xi, c.bi)) return s;
    return filtered_sign<NT>(dot(c.ai, xi) - c.bi, [&] { return slack(c.h, x); });
  }
  // Exact sign of |x − c|² − r2.
  static int compare_dist2(const P& x, const IPoint<D>& xi, const P& c, const IPoint<D>& ci, const NT& r2,
                           const IntervalNT& r2i) {
    if constexpr (is_interval_v<NT>)
      if (int s = double_filter::dist2_minus_sign<D>(xi, ci, r2i)) return s;
    return filtered_sign<NT>(dist2(xi, ci) - r2i, [&] { return dist2(x, c) - r2; });
  }

  // Adds constraint hs (index = h.size() before the call) and clips. Returns its index. In 2D,
  // while the polygon is full-dimensional (the cells of §3.2.4 always are: their site is strictly
  // inside every constraint), by walking its vertex cycle in O(V) (clip_polygon); otherwise, and in
  // 3D/4D, by the combinatorial adjacency test (clip_generic). Both give the same vertices, in the
  // same order, with the same tight sets (test PolygonWalkMatchesCombinatorialClipOnDegenerateCells).
  int clip(const Halfspace<D, NT>& hs) {
    const int j = add(hs);
    if (!cuts(j)) return j;
    if constexpr (D == 2)
      if (ring_.size() == v.size() && v.size() >= 3) {
        clip_polygon(j);
        return j;
      }
    clip_combinatorial(j);
    return j;
  }
  // The same by the combinatorial adjacency test only (the reference of the 2D walk).
  int clip_generic(const Halfspace<D, NT>& hs) {
    const int j = add(hs);
    if (cuts(j)) clip_combinatorial(j);
    return j;
  }
  // The vertex cycle of a full-dimensional polygon (indices into v; empty when not known).
  const std::vector<int>& ring() const { return ring_; }

  // x ∈ P? Constraints listed in `on` are known to be tight at x (not tested: in the exact tier
  // their slack is 0, in the interval tier it would straddle 0 and throw).
  bool contains(const P& x, const std::vector<int>& on = {}) const {
    IPoint<D> xi = enclose<NT, D>(x);
    for (std::size_t k = 0; k < h.size(); ++k)
      if (std::find(on.begin(), on.end(), static_cast<int>(k)) == on.end() && sign_at(k, x, xi) > 0) return false;
    return true;
  }
  // An upper bound on the max squared distance from c over the vertices (rigorous; for pruning).
  double max_dist2_upper(const IPoint<D>& ci) const {
    bool origin = true;
    for (std::size_t i = 0; i < D; ++i) origin = origin && ci[i].lo() == 0 && ci[i].hi() == 0;
    double m = 0;
    for (const auto& x : v) m = std::max(m, origin ? x.n2i.hi() : dist2(x.xi, ci).hi());
    return m;
  }
  // Is some vertex farther than sqrt(r2) from c?
  bool some_vertex_beyond(const P& c, const NT& r2) const {
    IPoint<D> ci = enclose<NT, D>(c);
    IntervalNT r2i = exact::enclose(r2);
    for (const auto& x : v)
      if (compare_dist2(x.x, x.xi, c, ci, r2, r2i) > 0) return true;
    return false;
  }
  // Max squared distance from c over the vertices.
  NT max_dist2(const P& c) const {
    NT m = 0;
    for (const auto& x : v) {
      NT d = dist2(x.x, c);
      if (d > m) m = d;
    }
    return m;
  }

  // Projection of c onto {x : h_k·x = b_k for k in rows}; nullopt if the rows are dependent.
  std::optional<P> project(const P& c, const std::vector<int>& rows) const {
    std::size_t m = rows.size();
    std::vector<std::vector<NT>> G(m, std::vector<NT>(m + 1));
    for (std::size_t i = 0; i < m; ++i) {
      for (std::size_t k = 0; k < m; ++k) G[i][k] = dot(h[rows[i]].h.a, h[rows[k]].h.a);
      G[i][m] = slack(h[rows[i]].h, c);
    }
    for (std::size_t col = 0; col < m; ++col) {
      std::size_t piv = col;
      while (piv < m && G[piv][col] == NT(0)) ++piv;
      if (piv == m) return std::nullopt;
      std::swap(G[piv], G[col]);
      for (std::size_t r = 0; r < m; ++r) {
        if (r == col) continue;
        NT f = G[r][col] / G[col][col];
        for (std::size_t k = col; k <= m; ++k) G[r][k] -= f * G[col][k];
      }
    }
    P x = c;
    for (std::size_t i = 0; i < m; ++i) {
      NT lam = G[i][m] / G[i][i];
      for (std::size_t d = 0; d < D; ++d) x[d] -= lam * h[rows[i]].h.a[d];
    }
    return x;
  }

  // Exact: does the face F_j = {x ∈ P : constraint j tight} contain a point within squared
  // distance r2 of c? (Minimum of |x−c|² over F_j is the projection of c onto the affine hull of
  // the minimal face containing the minimiser; enumerate those affine hulls.) `skip_from`:
  // constraints with index < skip_from (the bounding box) are never active at a minimiser within r2.
  bool face_within(int j, const P& c, const NT& r2, int skip_from) const {
    std::vector<int> rel;  // constraints tight at some vertex of F_j
    bool nonempty = false;
    IPoint<D> ci = enclose<NT, D>(c);
    IntervalNT r2i = exact::enclose(r2);
    for (const auto& x : v) {
      if (!std::binary_search(x.tight.begin(), x.tight.end(), j)) continue;
      nonempty = true;
      if (compare_dist2(x.x, x.xi, c, ci, r2, r2i) <= 0) return true;
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
        IPoint<D> xi = enclose<NT, D>(*x);
        if (compare_dist2(*x, xi, c, ci, r2, r2i) <= 0 && contains(*x, rows)) {
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

 private:
  std::vector<int> scratch_sign_;     // clip's signs, reused
  std::vector<Vert> scratch_verts_;  // clip's output, swapped with v (keeps both allocations)
  std::vector<int> ring_;             // 2D: the vertex cycle while the polygon is full-dimensional
  std::vector<int> scratch_index_;    // clip_polygon's new index of each kept vertex, reused
  std::vector<int> scratch_ring_;     // clip_polygon's new cycle, swapped with ring_
  std::vector<std::uint64_t> scratch_bits_;  // clip_combinatorial's tight bit rows, reused
  std::vector<std::uint64_t> scratch_outside_;  // clip_combinatorial's outside vertices (bits), reused
  std::vector<std::uint64_t> scratch_cand_;     // clip_combinatorial's candidate partners (bits), reused

  // The signs of constraint j at the vertices (into scratch_sign_). When no vertex is strictly
  // outside, records j as tight where it is and returns false (the vertex set is unchanged).
  bool cuts(int j) {
    std::vector<int>& sg = scratch_sign_;
    sg.resize(v.size());
    bool any_out = false;
    for (std::size_t k = 0; k < v.size(); ++k) {
      sg[k] = sign_at(static_cast<std::size_t>(j), v[k].x, v[k].xi);
      any_out |= sg[k] > 0;
    }
    if (!any_out) {
      for (std::size_t k = 0; k < v.size(); ++k)
        if (sg[k] == 0) v[k].tight.push_back(j);
      return false;
    }
    ++version;
    return true;
  }
  // The vertex of edge pq (p strictly inside constraint j, q strictly outside) on constraint j:
  // tight on the constraints common to p and q, and on j. In 2D the meeting point of the lines of
  // j and of the edge by Cramer's rule (fewer operations, and not through p's and q's own
  // roundings); else p + λ(q − p) with λ = s_p / (s_p − s_q). The same point in exact arithmetic.
  void cut_edge(const Vert& p, const Vert& q, int j, const TightSet& common, Vert& nv) const {
    const Halfspace<D, NT>& hs = h[static_cast<std::size_t>(j)].h;
    if constexpr (D == 2) {
      const Halfspace<D, NT>& e = h[static_cast<std::size_t>(*common.begin())].h;
      if constexpr (is_interval_v<NT>) {  // one evaluation in doubles with an error bound
        nv.x = double_filter::meet_lines_2d(hs.a, hs.b, e.a, e.b);
      } else {
        const NT det = hs.a[0] * e.a[1] - hs.a[1] * e.a[0];  // ≠ 0: the lines cross between p and q
        nv.x[0] = (hs.b * e.a[1] - hs.a[1] * e.b) / det;
        nv.x[1] = (hs.a[0] * e.b - hs.b * e.a[0]) / det;
      }
    } else {
      if constexpr (is_interval_v<NT>) {
        // from D of the constraints tight at the new vertex (the first D − 1 of those common to p
        // and q, and j: the vertex satisfies them all, and D independent ones determine it),
        // unless p and q are exact points (then the formula below may give an exact point too)
        bool points = true;
        for (std::size_t i = 0; i < D && points; ++i) points = p.x[i].is_point() && q.x[i].is_point();
        if (!points) {
          std::array<const IPoint<D>*, D> ra;
          std::array<const IntervalNT*, D> rb;
          const int* t = common.begin();
          for (std::size_t k = 0; k + 1 < D; ++k, ++t) {
            ra[k] = &h[static_cast<std::size_t>(*t)].ai;
            rb[k] = &h[static_cast<std::size_t>(*t)].bi;
          }
          ra[D - 1] = &h[static_cast<std::size_t>(j)].ai;
          rb[D - 1] = &h[static_cast<std::size_t>(j)].bi;
          if (double_filter::solve_rows<D>(ra, rb, nv.x)) {
            nv.set_enclosures();
            nv.tight = common;
            nv.tight.push_back(j);
            return;
          }
        }
      }
      NT sp = slack(hs, p.x), sq = slack(hs, q.x);
      NT lam = sp / (sp - sq);
      for (std::size_t i = 0; i < D; ++i) nv.x[i] = p.x[i] + (q.x[i] - p.x[i]) * lam;
    }
    nv.set_enclosures();
    nv.tight = common;
    nv.tight.push_back(j);
  }
  static void common_tight(const TightSet& a0, const TightSet& b0, TightSet& common) {
    common.clear();
    for (const int *a = a0.begin(), *ae = a0.end(), *b = b0.begin(), *be = b0.end(); a != ae && b != be;) {
      if (*a < *b) ++a;
      else if (*b < *a) ++b;
      else {
        common.push_back(*a);
        ++a;
        ++b;
      }
    }
  }
  // Any dimension: an edge pq is a pair of vertices tight on ≥ D − 1 common constraints with no
  // third vertex tight on all of them. Output: the new vertices by (inside p, outside q) in index
  // order, then the kept vertices in order. The "no third vertex" test is the AND of one bit row
  // per common constraint (bit r of row k: vertex r is tight on k), which must hold only p and q:
  // the same test as scanning every r for tight(r) ⊇ common (issue 11 §5: the scan was O(V) per
  // pair, 24 % of a 4D run), in O(|common|·V/64) with an early exit at the first other bit.
  void clip_combinatorial(int j) {
    const std::vector<int>& sg = scratch_sign_;
    ring_.clear();  // the order changes; the cycle is not tracked here
    std::vector<Vert>& out = scratch_verts_;  // reused: its vertices' storage stays allocated
    out.clear();
    const std::size_t n = v.size(), words = (n + 63) / 64;
    std::vector<std::uint64_t>& bits = scratch_bits_;  // row k at [k·words, (k+1)·words)
    bits.assign(h.size() * words, 0);
    for (std::size_t r = 0; r < n; ++r)
      for (int t : v[r].tight) bits[static_cast<std::size_t>(t) * words + r / 64] |= std::uint64_t{1} << (r % 64);
    // The outside vertices q an inside p can share D − 1 constraints with: the OR over the
    // (D − 1)-subsets of tight(p) of the AND of their rows, masked by the outside vertices; the
    // same q as trying every outside vertex, in the same (increasing) order. Degenerate p (more
    // than 8 tight constraints) try every outside vertex.
    std::vector<std::uint64_t>& outside = scratch_outside_;
    std::vector<std::uint64_t>& cand = scratch_cand_;
    outside.assign(words, 0);
    for (std::size_t q = 0; q < n; ++q)
      if (sg[q] > 0) outside[q / 64] |= std::uint64_t{1} << (q % 64);
    TightSet common;
    auto edge = [&](std::size_t p, std::size_t q) {
      common_tight(v[p].tight, v[q].tight, common);
      if (common.size() + 1 < D) return;
      for (std::size_t w = 0; w < words; ++w) {
        std::uint64_t x = ~std::uint64_t{0};
        for (int t : common) x &= bits[static_cast<std::size_t>(t) * words + w];
        if (w == p / 64) x &= ~(std::uint64_t{1} << (p % 64));
        if (w == q / 64) x &= ~(std::uint64_t{1} << (q % 64));
        if (x != 0) return;  // a third vertex is tight on all of common: not an edge
      }
      cut_edge(v[p], v[q], j, common, out.emplace_back());
    };
    for (std::size_t p = 0; p < n; ++p) {
      if (sg[p] >= 0) continue;
      const int* T = v[p].tight.begin();
      const std::size_t k = v[p].tight.size();
      if (k + 1 < D) continue;  // shares at most k < D − 1 constraints with any q
      if (k > 8) {
        for (std::size_t q = 0; q < n; ++q)
          if (sg[q] > 0) edge(p, q);
        continue;
      }
      cand.assign(words, 0);
      std::array<std::size_t, D - 1> ix;  // a (D − 1)-subset of positions in T, increasing
      for (std::size_t i = 0; i + 1 < D; ++i) ix[i] = i;
      while (true) {
        for (std::size_t w = 0; w < words; ++w) {
          std::uint64_t x = outside[w];
          for (std::size_t i = 0; i + 1 < D; ++i) x &= bits[static_cast<std::size_t>(T[ix[i]]) * words + w];
          cand[w] |= x;
        }
        std::size_t i = D - 1;  // next subset in lexicographic order
        while (i > 0 && ix[i - 1] == k - (D - 1) + (i - 1)) --i;
        if (i == 0) break;
        ++ix[i - 1];
        for (std::size_t m = i; m + 1 < D; ++m) ix[m] = ix[m - 1] + 1;
      }
      for (std::size_t w = 0; w < words; ++w)
        for (std::uint64_t x = cand[w]; x != 0; x &= x - 1) edge(p, w * 64 + static_cast<std::size_t>(std::countr_zero(x)));
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (sg[k] > 0) continue;
      if (sg[k] == 0) v[k].tight.push_back(j);
      out.push_back(std::move(v[k]));
    }
    std::swap(v, out);
  }
  // 2D, full-dimensional polygon with its cycle ring_: the edges are the consecutive pairs of the
  // cycle (a full-dimensional convex polygon's vertices are extreme and their tight sets complete,
  // so the combinatorial test accepts exactly these), and a line crosses at most two of them. The
  // output order is clip_combinatorial's: new vertices by (inside, outside) index, then the kept.
  void clip_polygon(int j) {
    const std::vector<int>& sg = scratch_sign_;
    const std::size_t n = v.size();
    struct Crossing {
      int p, q;         // inside, outside vertex
      std::size_t pos;  // the edge (ring_[pos], ring_[pos + 1])
    };
    std::array<Crossing, 2> cr;
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const int a = ring_[i], b = ring_[i + 1 == n ? 0 : i + 1];
      if (sg[a] * sg[b] >= 0) continue;
      KMR_CHECK(m < 2, "a line crosses a convex polygon's boundary more than twice");
      cr[m++] = sg[a] < 0 ? Crossing{a, b, i} : Crossing{b, a, i};
    }
    if (m == 2 && (cr[1].p < cr[0].p || (cr[1].p == cr[0].p && cr[1].q < cr[0].q))) std::swap(cr[0], cr[1]);
    std::vector<Vert>& out = scratch_verts_;
    out.clear();
    TightSet common;
    for (std::size_t c = 0; c < m; ++c) {
      common_tight(v[static_cast<std::size_t>(cr[c].p)].tight, v[static_cast<std::size_t>(cr[c].q)].tight, common);
      cut_edge(v[static_cast<std::size_t>(cr[c].p)], v[static_cast<std::size_t>(cr[c].q)], j, common, out.emplace_back());
    }
    std::vector<int>& idx = scratch_index_;
    idx.assign(n, -1);
    for (std::size_t k = 0; k < n; ++k) {
      if (sg[k] > 0) continue;
      if (sg[k] == 0) v[k].tight.push_back(j);
      idx[k] = static_cast<int>(out.size());
      out.push_back(std::move(v[k]));
    }
    std::vector<int>& nr = scratch_ring_;
    nr.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const int a = ring_[i];
      if (idx[static_cast<std::size_t>(a)] >= 0) nr.push_back(idx[static_cast<std::size_t>(a)]);
      for (std::size_t c = 0; c < m; ++c)
        if (cr[c].pos == i) nr.push_back(static_cast<int>(c));
    }
    std::swap(v, out);
    if (v.size() >= 3) std::swap(ring_, nr);
    else ring_.clear();  // a segment or a point: no longer full-dimensional
  }
  int add(const Halfspace<D, NT>& hs) {
    Constraint c{hs, enclose<NT, D>(hs.a), exact::enclose(hs.b)};
    h.push_back(std::move(c));
    return static_cast<int>(h.size()) - 1;
  }
};

}  // namespace kmr::wellspaced
