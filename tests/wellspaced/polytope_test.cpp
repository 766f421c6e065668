// Exact polytope clipping and face distances (§3.2.4), against hand-computed cells.
#include <gtest/gtest.h>

#include "wellspaced/polytope.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace kmr::wellspaced;

TEST(WellspacedPolytope, SquareCutByBisector) {
  Polytope<2> P = Polytope<2>::box({Q(0), Q(0)}, {Q(1), Q(1)});
  QPoint<2> v{Q(1, 4), Q(1, 2)}, u{Q(3, 4), Q(1, 2)};
  P.clip(bisector<2>(v, u));  // x ≤ 1/2
  ASSERT_EQ(P.v.size(), 4u);
  Q m = P.max_dist2(v);  // farthest: (1/2, 0) or (0,0)/(0,1): (1/4)^2+(1/2)^2 = 5/16
  EXPECT_EQ(m, Q(5, 16));
}
TEST(WellspacedPolytope, DegenerateGridCellIsASquare) {
  // v at the centre of a 3x3 grid: 8 neighbours, 4 of them cut only at the cell's corners.
  QPoint<2> v{Q(1, 2), Q(1, 2)};
  Polytope<2> P = Polytope<2>::box({Q(0), Q(0)}, {Q(1), Q(1)});
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      if (i || j) P.clip(bisector<2>(v, {Q(1, 2) + Q(i, 4), Q(1, 2) + Q(j, 4)}));
  EXPECT_EQ(P.v.size(), 4u);
  EXPECT_EQ(P.max_dist2(v), Q(1, 32));  // corners at (±1/8, ±1/8)
}
TEST(WellspacedPolytope, FaceWithinBall3D) {
  QPoint<3> v{Q(0), Q(0), Q(0)};
  Polytope<3> P = Polytope<3>::box({Q(-4), Q(-4), Q(-4)}, {Q(4), Q(4), Q(4)});
  int j = P.clip(bisector<3>(v, {Q(2), Q(0), Q(0)}));  // x ≤ 1: the face is at distance 1
  EXPECT_TRUE(P.face_within(j, v, Q(1), 6));
  EXPECT_FALSE(P.face_within(j, v, Q(99, 100), 6));
  // a second constraint hides the midpoint: y ≥ 1 on the face x = 1 → nearest point (1,1,0), d² = 2
  int k = P.clip(Halfspace<3>{{Q(0), Q(-1), Q(0)}, Q(-1)});
  (void)k;
  EXPECT_FALSE(P.face_within(j, v, Q(199, 100), 6));
  EXPECT_TRUE(P.face_within(j, v, Q(2), 6));
}

// The static double filter (polytope.hpp, double_filter; issue 11 §4): a decided sign must hold at
// EVERY point of the enclosures. Judged with exact rationals at all corners of the enclosures, on
// near-degenerate values (b within a few ulps of a·x, enclosures a few ulps wide) where a too small
// error bound decides wrongly; non-vacuity: well-separated values are decided.
namespace {
double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, 2.0 * (std::fabs(x) + 1));
  for (; k < 0; ++k) x = std::nextafter(x, -2.0 * (std::fabs(x) + 1));
  return x;
}
IntervalNT widen(double x, int down, int up) { return down == 0 && up == 0 ? IntervalNT(x) : IntervalNT::hull(ulps(x, -down), ulps(x, up)); }
// Exact signs of f over the 2^m corners of m enclosures (f gets one endpoint per enclosure).
template <class F>
std::pair<bool, bool> corner_signs(const std::vector<IntervalNT>& e, F&& f, int& sign_seen) {
  bool pos = false, neg = false;
  for (unsigned mask = 0; mask < (1u << e.size()); ++mask) {
    std::vector<Q> c(e.size());
    for (std::size_t i = 0; i < e.size(); ++i) c[i] = Q((mask >> i) & 1u ? e[i].hi() : e[i].lo());
    int s = f(c).sign();
    pos |= s > 0;
    neg |= s < 0;
    if (s == 0) pos = neg = true;  // a zero is never a decided sign
  }
  sign_seen = pos && !neg ? 1 : (neg && !pos ? -1 : 0);
  return {pos, neg};
}
template <std::size_t D>
void double_filter_case(std::uint64_t seed, int trials, int& decided, int& undecided) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_int_distribution<int> W(0, 2), K(-3, 3), Far(0, 3);
  for (int trial = 0; trial < trials; ++trial) {
    const bool far = Far(g) == 0;  // a quarter of the cases: b well away from a·x
    IPoint<D> a, x, c;
    double ad[D], xd[D];
    double dot_d = 0, d2 = 0;
    for (std::size_t i = 0; i < D; ++i) {
      ad[i] = U(g);
      xd[i] = trial % 7 == 0 ? std::ldexp(U(g), -40) : U(g);  // some tiny coordinates
      a[i] = widen(ad[i], W(g) * (trial % 3 == 0), W(g) * (trial % 3 == 0));
      x[i] = widen(xd[i], W(g), W(g));
      c[i] = widen(U(g), W(g) * (trial % 2), W(g) * (trial % 2));
      dot_d += ad[i] * xd[i];
      d2 += (xd[i] - c[i].lo()) * (xd[i] - c[i].lo());
    }
    const IntervalNT b = widen(far ? dot_d + 0.25 * U(g) : ulps(dot_d, K(g)), W(g) * (trial % 5 == 0), 0);
    const IntervalNT r2 = widen(far ? d2 * (1 + 0.5 * U(g)) : ulps(d2, K(g)), 0, W(g) * (trial % 5 == 0));
    // Σ a_i x_i − b
    std::vector<IntervalNT> e;
    for (std::size_t i = 0; i < D; ++i) e.push_back(a[i]);
    for (std::size_t i = 0; i < D; ++i) e.push_back(x[i]);
    e.push_back(b);
    int exact_sign = 0;
    corner_signs(e, [](const std::vector<Q>& q) {
      Q v = -q[2 * D];
      for (std::size_t i = 0; i < D; ++i) v += q[i] * q[D + i];
      return v;
    }, exact_sign);
    int s = double_filter::dot_minus_sign<D>(a, x, b);
    if (s != 0) {
      ASSERT_EQ(s, exact_sign) << "dot, seed " << seed << " trial " << trial;
    }
    (s ? decided : undecided)++;
    // |x − c|² − r2
    e.clear();
    for (std::size_t i = 0; i < D; ++i) e.push_back(x[i]);
    for (std::size_t i = 0; i < D; ++i) e.push_back(c[i]);
    e.push_back(r2);
    corner_signs(e, [](const std::vector<Q>& q) {
      Q v = -q[2 * D];
      for (std::size_t i = 0; i < D; ++i) v += (q[i] - q[D + i]) * (q[i] - q[D + i]);
      return v;
    }, exact_sign);
    s = double_filter::dist2_minus_sign<D>(x, c, r2);
    if (s != 0) {
      ASSERT_EQ(s, exact_sign) << "dist2, seed " << seed << " trial " << trial;
    }
    (s ? decided : undecided)++;
  }
}
}  // namespace

TEST(WellspacedPolytope, DoubleFilterDecidesOnlyWhatEveryPointOfTheEnclosuresDecides) {
  int decided = 0, undecided = 0;
  double_filter_case<2>(11, 2500, decided, undecided);
  double_filter_case<3>(12, 600, decided, undecided);
  std::printf("double filter: %d decided, %d undecided\n", decided, undecided);
  EXPECT_GT(decided, 1200);    // the separated quarter and more is decided in doubles
  EXPECT_GT(undecided, 500);   // and the near-degenerate cases reach the tiers behind it
  // exact zeros (a point enclosure of a zero value) are never decided by the filter
  IPoint<2> a{IntervalNT(0.5), IntervalNT(0.25)}, x{IntervalNT(0.75), IntervalNT(0.5)};
  EXPECT_EQ(double_filter::dot_minus_sign<2>(a, x, IntervalNT(0.5)), 0);
  EXPECT_EQ(double_filter::dist2_minus_sign<2>(x, a, IntervalNT(0.125)), 0);
}

// The 2D walk of the vertex cycle (Polytope::clip, issue 11 §4) against the combinatorial
// adjacency test (clip_generic, any dimension) on degenerate cells: after every cut both hold the
// same vertices, in the same order, with the same tight sets (so every later decision is the same),
// and the walk's cycle joins consecutive vertices by a common tight constraint.
namespace {
template <class NT>
bool same_vertex(const typename Polytope<2, NT>::Vert& a, const typename Polytope<2, NT>::Vert& b) {
  for (std::size_t i = 0; i < 2; ++i) {
    if constexpr (std::is_same_v<NT, Q>) {
      if (a.x[i] != b.x[i]) return false;
    } else if (a.x[i].lo() != b.x[i].lo() || a.x[i].hi() != b.x[i].hi()) {
      return false;
    }
  }
  return std::vector<int>(a.tight.begin(), a.tight.end()) == std::vector<int>(b.tight.begin(), b.tight.end());
}
// The same halfspace a·x ≤ b and the same enclosures of a and b, endpoint for endpoint.
template <class NT>
bool same_constraint(const typename Polytope<2, NT>::Constraint& c, const typename Polytope<2, NT>::Constraint& d) {
  auto same = [](const auto& x, const auto& y) {
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, IntervalNT>) return x.lo() == y.lo() && x.hi() == y.hi();
    else return x == y;
  };
  for (std::size_t i = 0; i < 2; ++i)
    if (!same(c.h.a[i], d.h.a[i]) || !same(c.ai[i], d.ai[i])) return false;
  return same(c.h.b, d.h.b) && same(c.bi, d.bi);
}
template <class NT>
Halfspace<2, NT> in_nt(const Halfspace<2, Q>& h) {
  Halfspace<2, NT> r;
  for (std::size_t i = 0; i < 2; ++i) r.a[i] = NT(h.a[i].template convert_to<double>());
  r.b = NT(h.b.template convert_to<double>());
  return r;
}
// Clips `cuts` (all with dyadic coefficients, so both number types start from the same values)
// into the box [lo, hi]² both ways; returns the number of cuts that went through the walk.
template <class NT>
int compare_walk(const std::vector<Halfspace<2, Q>>& cuts, double lo, double hi, const char* what) {
  Polytope<2, NT> W = Polytope<2, NT>::box({NT(lo), NT(lo)}, {NT(hi), NT(hi)});
  Polytope<2, NT> G = W;
  int walked = 0;
  for (std::size_t c = 0; c < cuts.size(); ++c) {
    const bool walk = W.ring().size() == W.v.size() && W.v.size() >= 3;
    const Halfspace<2, NT> h = in_nt<NT>(cuts[c]);
    try {
      W.clip(h);
    } catch (const Uncertain&) {
      return walked;  // the interval tier gave up; the exact tier is compared separately
    }
    G.clip_generic(h);
    walked += walk;
    EXPECT_EQ(W.v.size(), G.v.size()) << what << " cut " << c;
    if (W.v.size() != G.v.size()) return walked;
    for (std::size_t k = 0; k < W.v.size(); ++k)
      EXPECT_TRUE(same_vertex<NT>(W.v[k], G.v[k])) << what << " cut " << c << " vertex " << k;
    const auto& r = W.ring();
    if (r.empty()) continue;
    EXPECT_EQ(r.size(), W.v.size()) << what << " cut " << c;
    std::vector<int> seen(r.begin(), r.end());
    std::sort(seen.begin(), seen.end());
    for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], static_cast<int>(k)) << what;
    for (std::size_t k = 0; k < r.size(); ++k) {
      const auto& a = W.v[static_cast<std::size_t>(r[k])].tight;
      const auto& b = W.v[static_cast<std::size_t>(r[(k + 1) % r.size()])].tight;
      bool share = false;
      for (int t : a) share = share || std::find(b.begin(), b.end(), t) != b.end();
      EXPECT_TRUE(share) << what << " cut " << c << ": cycle neighbours share no constraint";
    }
  }
  return walked;
}
Halfspace<2, Q> bisector_q(long ux, long uy, long scale) {  // bisector of the origin and u/scale
  return bisector_of_origin<2, Q>({Q(ux, scale), Q(uy, scale)});
}
}  // namespace

TEST(WellspacedPolytope, PolygonWalkMatchesCombinatorialClipOnDegenerateCells) {
  std::vector<std::pair<std::string, std::vector<Halfspace<2, Q>>>> families;
  {  // grid: the 8 (and 24) neighbours of a grid point; 3 bisectors through each corner
    std::vector<Halfspace<2, Q>> g;
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j)
        if (i || j) g.push_back(bisector_q(i, j, 8));
    families.push_back({"grid", g});
    std::reverse(g.begin(), g.end());
    families.push_back({"grid reversed", g});
  }
  {  // cocircular: the origin and 12 integer points on the circle of radius 5 about (5, 0): every
     // bisector passes through the centre
    std::vector<Halfspace<2, Q>> c;
    for (auto [x, y] : std::vector<std::pair<int, int>>{{10, 0}, {5, 5}, {5, -5}, {1, 3}, {1, -3}, {2, 4},
                                                        {2, -4}, {8, 4}, {8, -4}, {9, 3}, {9, -3}, {9, 0}})
      if (x != 9 || y != 0) c.push_back(bisector_q(x, y, 16));
    // and the 7 other integer points of the circle through the origin about (−1, 2) (radius² 5)
    for (auto [x, y] : std::vector<std::pair<int, int>>{{-2, 4}, {1, 3}, {0, 4}, {-3, 1}, {-3, 3}, {1, 1}, {-2, 0}})
      c.push_back(bisector_q(x, y, 16));
    families.push_back({"cocircular", c});
  }
  {  // collinear: points on a line through the site and on a line beside it (parallel bisectors)
    std::vector<Halfspace<2, Q>> l;
    for (int k = 1; k <= 6; ++k) {
      l.push_back(bisector_q(k, k, 16));
      l.push_back(bisector_q(-k, -k, 16));
      l.push_back(bisector_q(k, 3, 16));
      l.push_back(bisector_q(-k, 3, 16));
    }
    families.push_back({"collinear", l});
  }
  {  // duplicate-plane cuts: the same bisector again, scaled, and cuts through two vertices
    std::vector<Halfspace<2, Q>> d;
    d.push_back(bisector_q(1, 0, 4));
    d.push_back(bisector_q(1, 0, 4));
    Halfspace<2, Q> twice = bisector_q(0, 1, 4);
    d.push_back(twice);
    for (auto& a : twice.a) a *= 2;
    twice.b *= 2;
    d.push_back(twice);
    d.push_back(Halfspace<2, Q>{{Q(1), Q(1)}, Q(1, 4)});   // x + y ≤ 1/4: through (1/8, 1/8)
    d.push_back(Halfspace<2, Q>{{Q(-1), Q(1)}, Q(1, 4)});  // through (1/8, ... ) and a box edge
    d.push_back(bisector_q(-1, 0, 4));
    d.push_back(Halfspace<2, Q>{{Q(1), Q(1)}, Q(1, 4)});
    d.push_back(bisector_q(1, 1, 4));
    d.push_back(Halfspace<2, Q>{{Q(1), Q(0)}, Q(-1, 8)});  // x ≤ −1/8: down to a segment
    d.push_back(Halfspace<2, Q>{{Q(0), Q(1)}, Q(-1, 4)});  // then further (generic only)
    families.push_back({"duplicate planes", d});
  }
  {  // random grid points in random order (seeded), cut into boxes about and beside the site
    std::mt19937_64 g(5);
    std::uniform_int_distribution<int> U(-6, 6);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<Halfspace<2, Q>> r;
      for (int k = 0; k < 30; ++k) {
        int x = U(g), y = U(g);
        if (x || y) r.push_back(bisector_q(x, y, 16));
      }
      families.push_back({"random grid " + std::to_string(trial), r});
    }
  }
  int walked_q = 0, walked_i = 0;
  for (const auto& [name, cuts] : families) {
    walked_q += compare_walk<Q>(cuts, -1, 1, name.c_str());
    walked_q += compare_walk<Q>(cuts, 0, 1, name.c_str());  // the site on a corner of the box
    walked_i += compare_walk<IntervalNT>(cuts, -1, 1, name.c_str());
  }
  std::printf("polygon walk: %d exact and %d interval cuts compared\n", walked_q, walked_i);
  EXPECT_GT(walked_q, 500);  // non-vacuous: the walk ran
  EXPECT_GT(walked_i, 200);
}

// Vert::set_enclosures computes |x|² as dot(xi, xi) (issue 11 §4: no subtraction of the origin);
// the endpoints must equal those of dist2(xi, origin) bit for bit (the scan's certificate bounds
// read them): random enclosures of both signs, straddling 0, points, zeros of both signs.
TEST(WellspacedPolytope, VertexNormEnclosureEqualsDist2FromOrigin) {
  std::mt19937_64 g(2026);
  std::uniform_real_distribution<double> U(-1, 1);
  std::uniform_int_distribution<int> W(0, 5);
  int checked = 0;
  for (int k = 0; k < 100000; ++k) {
    Polytope<2, IntervalNT>::Vert x;
    for (std::size_t i = 0; i < 2; ++i) {
      double lo = k % 97 == 0 ? -0.0 : U(g) * std::ldexp(1.0, -W(g) * 10), hi = lo;
      for (int s = W(g); s > 0; --s) hi = std::nextafter(hi, 2.0);  // 0–5 ulps wide
      if (k % 5 == 0) hi = std::fabs(lo) * 0.75;                       // or straddling 0
      x.x[i] = IntervalNT::hull(lo, hi);
    }
    x.set_enclosures();
    const IntervalNT ref = dist2(x.xi, IPoint<2>{});
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.n2i.lo()), std::bit_cast<std::uint64_t>(ref.lo()));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(x.n2i.hi()), std::bit_cast<std::uint64_t>(ref.hi()));
    ++checked;
  }
  EXPECT_EQ(checked, 100000);
}

// Polytope::reset_box (issue 11 §4: the scan and the fill reuse one cell each) must leave nothing
// of the cell it overwrites: one cell R, reset before each run and never rebuilt, is clipped side
// by side with a freshly built box F; after every cut the vertices, tight sets, constraints,
// version and vertex cycle must be equal. R goes through full boxes, boxes flattened to a segment
// (no cycle: the walk must not start from a stale one) and interval runs abandoned mid-clip.
namespace {
template <class NT>
void compare_reused(Polytope<2, NT>& R, const std::vector<Halfspace<2, Q>>& cuts, std::array<double, 2> lo,
                    std::array<double, 2> hi, const std::string& what, int& compared) {
  const typename Polytope<2, NT>::P l{NT(lo[0]), NT(lo[1])}, u{NT(hi[0]), NT(hi[1])};
  R.reset_box(l, u);
  Polytope<2, NT> F = Polytope<2, NT>::box(l, u);
  for (std::size_t c = 0; c <= cuts.size(); ++c) {
    ASSERT_EQ(R.v.size(), F.v.size()) << what << " cut " << c;
    for (std::size_t k = 0; k < R.v.size(); ++k)
      EXPECT_TRUE(same_vertex<NT>(R.v[k], F.v[k])) << what << " cut " << c << " vertex " << k;
    ASSERT_EQ(R.h.size(), F.h.size()) << what << " cut " << c;
    for (std::size_t k = 0; k < R.h.size(); ++k)
      EXPECT_TRUE(same_constraint<NT>(R.h[k], F.h[k])) << what << " cut " << c << " constraint " << k;
    EXPECT_EQ(R.version, F.version) << what << " cut " << c;
    EXPECT_EQ(R.ring(), F.ring()) << what << " cut " << c;
    ++compared;
    if (c == cuts.size()) break;
    const Halfspace<2, NT> h = in_nt<NT>(cuts[c]);
    try {
      F.clip(h);
    } catch (const Uncertain&) {
      try {
        R.clip(h);  // leaves R mid-clip, as an abandoned interval-tier call does
      } catch (const Uncertain&) {
      }
      return;
    }
    R.clip(h);
  }
}
}  // namespace

TEST(WellspacedPolytope, ReusedCellEqualsFreshCell) {
  std::vector<std::vector<Halfspace<2, Q>>> families;
  std::mt19937_64 g(14);
  std::uniform_int_distribution<int> U(-6, 6);
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Halfspace<2, Q>> r;
    for (int k = 0; k < 25; ++k) {
      int x = U(g), y = U(g);
      if (x || y) r.push_back(bisector_q(x, y, trial % 3 == 0 ? 64 : 16));  // /64: thin cells, interval ties
    }
    families.push_back(r);
  }
  const std::array<std::pair<std::array<double, 2>, std::array<double, 2>>, 4> boxes = {{
      {{-1, -1}, {1, 1}}, {{0, 0}, {1, 1}}, {{-1, 0}, {1, 0}} /* a segment */, {{-0.5, -0.25}, {0.75, 0.5}}}};
  Polytope<2, Q> Rq;
  Polytope<2, IntervalNT> Ri;
  int compared = 0;
  for (std::size_t f = 0; f < families.size(); ++f)
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      const std::string what = "family " + std::to_string(f) + " box " + std::to_string(b);
      compare_reused<Q>(Rq, families[f], boxes[b].first, boxes[b].second, what + " (exact)", compared);
      compare_reused<IntervalNT>(Ri, families[f], boxes[b].first, boxes[b].second, what + " (intervals)", compared);
    }
  std::printf("reused cells: %d states compared\n", compared);
  EXPECT_GT(compared, 1000);  // non-vacuous
}

// double_filter::meet_lines_2d (the interval tier's new 2D vertices, issue 11 §4) must enclose the
// meeting point of the two lines for EVERY point of the enclosures of their coefficients: judged
// with exact rationals (Cramer's rule in Q, written out here) at all 64 corners, on random lines,
// nearly parallel ones, and enclosures 0–3 ulps wide; non-vacuity: most cases are enclosed (not
// refused), nearly parallel ones are refused, and the enclosures are narrow.
TEST(WellspacedPolytope, MeetLines2DEnclosesTheExactMeetingPointAtEveryCorner) {
  std::mt19937_64 g(17);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_int_distribution<int> W(0, 3);
  int enclosed = 0, refused = 0;
  double widest = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    double a0 = U(g), a1 = U(g), e0 = U(g), e1 = U(g);
    if (trial % 4 == 0) {  // nearly parallel: E = A turned by 2^-k
      const double t = std::ldexp(1.0, -static_cast<int>(g() % 60));
      e0 = a0 - t * a1;
      e1 = a1 + t * a0;
    }
    if (trial % 9 == 0) a0 = std::ldexp(a0, -30);  // a small coefficient
    const std::array<IntervalNT, 2> A{widen(a0, W(g), W(g)), widen(a1, W(g), W(g))};
    const std::array<IntervalNT, 2> E{widen(e0, W(g), W(g)), widen(e1, W(g), W(g))};
    const IntervalNT B = widen(U(g), W(g), W(g)), F = widen(U(g), W(g), W(g));
    std::array<IntervalNT, 2> x;
    try {
      x = double_filter::meet_lines_2d(A, B, E, F);
    } catch (const Uncertain&) {
      ++refused;
      continue;
    }
    const IntervalNT* in[6] = {&A[0], &A[1], &B, &E[0], &E[1], &F};
    for (unsigned mask = 0; mask < 64; ++mask) {
      Q c[6];
      for (int i = 0; i < 6; ++i) c[i] = Q((mask >> i) & 1u ? in[i]->hi() : in[i]->lo());
      const Q det = c[0] * c[4] - c[1] * c[3];
      ASSERT_NE(det, 0) << "trial " << trial << ": an enclosure was given where the lines may be parallel";
      const Q x0 = (c[2] * c[4] - c[1] * c[5]) / det, x1 = (c[0] * c[5] - c[2] * c[3]) / det;
      ASSERT_TRUE(Q(x[0].lo()) <= x0 && x0 <= Q(x[0].hi())) << "trial " << trial << " corner " << mask;
      ASSERT_TRUE(Q(x[1].lo()) <= x1 && x1 <= Q(x[1].hi())) << "trial " << trial << " corner " << mask;
    }
    for (const auto& xi : x) widest = std::max(widest, (xi.hi() - xi.lo()) / std::max(1.0, std::fabs(xi.lo())));
    ++enclosed;
  }
  std::printf("meet_lines_2d: %d enclosed, %d refused, widest relative width %g\n", enclosed, refused, widest);
  EXPECT_GT(enclosed, 1000);
  EXPECT_GT(refused, 20);
}

// double_filter::solve_rows (issue 11 §5: the new vertices of a 3D/4D clip from their D tight
// constraints): the enclosure must hold the exact solution for EVERY point of the enclosures of
// the rows. Judged with rationals (Gaussian elimination of its own) at 40 points of each case's
// enclosures: 30 random corners and 10 random interior points (k/7 of the way across each);
// cases: random rows, rows nearly dependent (one row = another turned by 2^-k), tiny rows (the
// bisectors of points 2^-30 apart), exactly dependent rows (must be refused); widths 0–3 ulps,
// or up to 2^-30 relative.
// Non-vacuity: most cases are enclosed, tightly (relative width < 2^-40 on the well-conditioned).
namespace {
template <std::size_t D>
std::optional<std::array<Q, D>> solve_q(std::array<std::array<Q, D + 1>, D> m) {
  for (std::size_t c = 0; c < D; ++c) {
    std::size_t p = c;
    while (p < D && m[p][c] == 0) ++p;
    if (p == D) return std::nullopt;
    std::swap(m[p], m[c]);
    for (std::size_t r = 0; r < D; ++r) {
      if (r == c || m[r][c] == 0) continue;
      const Q f = m[r][c] / m[c][c];
      for (std::size_t k = c; k <= D; ++k) m[r][k] -= f * m[c][k];
    }
  }
  std::array<Q, D> x;
  for (std::size_t i = 0; i < D; ++i) x[i] = m[i][D] / m[i][i];
  return x;
}
template <std::size_t D>
void solve_rows_case(std::uint64_t seed, int trials, int& enclosed, int& refused, int& tight) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::uniform_int_distribution<int> W(0, 3), Pick(0, 6);
  for (int trial = 0; trial < trials; ++trial) {
    const int kind = trial % 5;  // 0–1 random, 2 nearly dependent, 3 tiny, 4 dependent
    double ad[D][D], bd[D];
    for (std::size_t k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < D; ++i) ad[k][i] = kind == 3 ? std::ldexp(U(g), -30) : U(g);
      bd[k] = kind == 3 ? std::ldexp(U(g), -61) : U(g);
    }
    if (kind == 2) {  // row 1 = row 0 turned by 2^-t in the plane of axes 0, 1
      const double t = std::ldexp(1.0, -static_cast<int>(g() % 50));
      for (std::size_t i = 0; i < D; ++i) ad[1][i] = ad[0][i];
      ad[1][0] = ad[0][0] - t * ad[0][1];
      ad[1][1] = ad[0][1] + t * ad[0][0];
    }
    if (kind == 4)
      for (std::size_t i = 0; i < D; ++i) ad[D - 1][i] = ad[0][i];
    std::array<IPoint<D>, D> A;
    std::array<IntervalNT, D> B;
    // widths: 0–3 ulps of the coefficients in two thirds of the cases, else up to 2^-30 relative
    // (then the width terms of the bound dominate its rounding terms)
    const int wide = trial % 3;
    auto width = [&](double x) {
      if (wide != 2) return widen(x, wide * W(g), wide * W(g));
      const double d = std::ldexp(std::fabs(x), -30);
      return IntervalNT::hull(x - d * double(g() % 8) / 8, x + d * double(g() % 8) / 8);
    };
    for (std::size_t k = 0; k < D; ++k) {
      for (std::size_t i = 0; i < D; ++i) A[k][i] = width(ad[k][i]);
      B[k] = widen(bd[k], W(g), W(g));
    }
    std::array<const IPoint<D>*, D> ra;
    std::array<const IntervalNT*, D> rb;
    for (std::size_t k = 0; k < D; ++k) {
      ra[k] = &A[k];
      rb[k] = &B[k];
    }
    IPoint<D> x;
    if (!double_filter::solve_rows<D>(ra, rb, x)) {
      ++refused;
      continue;
    }
    ASSERT_NE(kind, 4) << "trial " << trial << ": dependent rows were given an enclosure";
    auto at = [&](const IntervalNT& e, int corner_or_frac) {
      if (corner_or_frac < 0) return Q(corner_or_frac == -1 ? e.lo() : e.hi());
      return Q(e.lo()) + (Q(e.hi()) - Q(e.lo())) * Q(corner_or_frac, 7);
    };
    for (int sample = 0; sample < 40; ++sample) {
      const bool corner = sample < 30;
      std::array<std::array<Q, D + 1>, D> m;
      for (std::size_t k = 0; k < D; ++k) {
        for (std::size_t i = 0; i < D; ++i) m[k][i] = at(A[k][i], corner ? -1 - int(g() % 2) : Pick(g));
        m[k][D] = at(B[k], corner ? -1 - int(g() % 2) : Pick(g));
      }
      const auto q = solve_q<D>(m);
      ASSERT_TRUE(q.has_value()) << "trial " << trial << ": an enclosure was given where the rows may be dependent";
      for (std::size_t i = 0; i < D; ++i)
        ASSERT_TRUE(Q(x[i].lo()) <= (*q)[i] && (*q)[i] <= Q(x[i].hi()))
            << D << "D trial " << trial << " sample " << sample << " coordinate " << i;
    }
    ++enclosed;
    if (kind <= 1 && wide != 2) {
      double w = 0;
      for (const auto& xi : x) w = std::max(w, (xi.hi() - xi.lo()) / std::max(std::fabs(xi.lo()), std::fabs(xi.hi())));
      tight += w < 0x1p-40;
    }
  }
}
}  // namespace

TEST(WellspacedPolytope, SolveRowsEnclosesTheExactVertexAtSampledPointsOfTheEnclosures) {
  int enclosed = 0, refused = 0, tight = 0;
  solve_rows_case<3>(31, 400, enclosed, refused, tight);
  solve_rows_case<4>(32, 400, enclosed, refused, tight);
  std::printf("solve_rows: %d enclosed (%d tight), %d refused\n", enclosed, tight, refused);
  EXPECT_GE(refused, 160);  // at least the 160 dependent cases
  EXPECT_GT(enclosed, 560);  // random, tiny and most nearly dependent ones
  EXPECT_GT(tight, 180);     // of the 213 random ones with widths of a few ulps
}

// clip_combinatorial's bit rows (issue 11 §5, ws12), differentially: 3D cells with more than 64
// vertices (two words per row) and a vertex with 12 tight constraints (the apex of a cone; more
// than 8, so the "try every outside vertex" branch runs when it is inside, and its rows mask the
// other vertices' partners when it is cut off). After each cut the vertices and their tight sets
// must equal a brute-force enumeration that shares no code with Polytope: every triple of the
// (integer) constraints solved by Cramer's rule in 128-bit integers, kept if it satisfies all
// constraints, its tight set recomputed by exact integer evaluation of every constraint.
namespace {
struct IntPlane {  // a·x ≤ b, small integers
  std::array<std::int64_t, 3> a;
  std::int64_t b;
};
using I128 = __int128;
struct IntVertex {  // x = num / den, den > 0; tight: the constraints with a·x = b
  std::array<I128, 3> num;
  I128 den;
  std::vector<int> tight;
};
I128 det3(const std::array<std::array<I128, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
std::vector<IntVertex> brute_vertices(const std::vector<IntPlane>& H) {
  std::vector<IntVertex> out;
  const std::size_t m = H.size();
  auto side = [&](const IntPlane& h, const IntVertex& x) {  // sign of a·x − b (den > 0)
    I128 s = -static_cast<I128>(h.b) * x.den;
    for (int i = 0; i < 3; ++i) s += static_cast<I128>(h.a[i]) * x.num[i];
    return (s > 0) - (s < 0);
  };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        std::array<std::array<I128, 3>, 3> A;
        const IntPlane* r[3] = {&H[i], &H[j], &H[k]};
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) A[a][b] = r[a]->a[b];
        I128 d = det3(A);
        if (d == 0) continue;
        IntVertex x;
        for (int c = 0; c < 3; ++c) {
          auto Ac = A;
          for (int a = 0; a < 3; ++a) Ac[a][c] = r[a]->b;
          x.num[c] = det3(Ac);
        }
        x.den = d;
        if (d < 0) {
          x.den = -d;
          for (auto& n : x.num) n = -n;
        }
        bool feasible = true;
        for (const IntPlane& h : H)
          if (side(h, x) > 0) {
            feasible = false;
            break;
          }
        if (!feasible) continue;
        bool seen = false;  // the same point from another triple
        for (const IntVertex& y : out) {
          bool same = true;
          for (int c = 0; c < 3; ++c) same = same && x.num[c] * y.den == y.num[c] * x.den;
          if (same) seen = true;
        }
        if (seen) continue;
        for (std::size_t t = 0; t < m; ++t)
          if (side(H[t], x) == 0) x.tight.push_back(static_cast<int>(t));
        out.push_back(std::move(x));
      }
  return out;
}
}  // namespace

TEST(WellspacedPolytope, ClipCombinatorialMatchesBruteForceEnumerationOnLargeDegenerateCells) {
  const unsigned seed = 20261203;
  std::printf("seed %u (replay: the seed is fixed in the test)\n", seed);
  std::mt19937 rng(seed);
  std::vector<IntPlane> H;
  for (int i = 0; i < 3; ++i) {  // the box [-4, 4]^3 in Polytope::box's constraint order
    IntPlane up{{0, 0, 0}, 4}, dn{{0, 0, 0}, 4};
    up.a[i] = 1;
    dn.a[i] = -1;
    H.push_back(up);
    H.push_back(dn);
  }
  Polytope<3> P = Polytope<3>::box({Q(-4), Q(-4), Q(-4)}, {Q(4), Q(4), Q(4)});
  auto to_q = [](const IntPlane& h) {
    Halfspace<3, Q> q;
    for (int i = 0; i < 3; ++i) q.a[i] = Q(h.a[i]);
    q.b = Q(h.b);
    return q;
  };
  int checked = 0, checked_big = 0, apex_inside = 0, apex_cut_off = 0;
  std::size_t most_tight = 0;
  auto cut = [&](const IntPlane& h, bool check) {
    // the state before the cut: more than 64 vertices, a vertex with more than 8 tight constraints
    std::size_t before_tight = 0;
    for (const auto& x : P.v) before_tight = std::max(before_tight, x.tight.size());
    const bool big = P.v.size() > 64 && before_tight > 8;
    const unsigned version = P.version;
    H.push_back(h);
    P.clip(to_q(h));
    if (!check) return;
    ++checked;
    if (big && P.version != version) ++checked_big;  // clip_combinatorial ran on the big cell
    std::vector<IntVertex> want = brute_vertices(H);
    ASSERT_EQ(P.v.size(), want.size()) << "cut " << H.size() - 1 << ": vertex count";
    for (const auto& x : P.v) {
      most_tight = std::max(most_tight, x.tight.size());
      auto it = std::find_if(want.begin(), want.end(), [&](const IntVertex& y) {
        for (int c = 0; c < 3; ++c)
          if (x.x[c] * Q(static_cast<long long>(y.den)) != Q(static_cast<long long>(y.num[c]))) return false;
        return true;
      });
      ASSERT_NE(it, want.end()) << "cut " << H.size() - 1 << ": a vertex of the clip is not a vertex of the cell";
      std::vector<int> got(x.tight.begin(), x.tight.end());
      EXPECT_EQ(got, it->tight) << "cut " << H.size() - 1 << ": tight set";
    }
  };
  // the cone with apex (0, 0, 2): 12 planes a·x + b·y + 5z ≤ 10, (a, b) the integer points of the
  // circle of radius 5 (in convex position, so each is a facet and all are tight at the apex)
  for (auto [a, b] : std::vector<std::pair<int, int>>{{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0},
                                                      {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}})
    cut({{a, b, 5}, 10}, true);
  // random planes n·x ≤ ⌊3|n|⌋ (about 3 from the centre) below the apex's height until the cell
  // has more than 70 vertices; they leave the apex strictly inside
  std::uniform_int_distribution<int> coef(-6, 6);
  auto random_plane = [&](double dist) {
    IntPlane h{{0, 0, 0}, 0};
    while (h.a[0] == 0 && h.a[1] == 0 && h.a[2] == 0)
      for (auto& c : h.a) c = coef(rng);
    h.a[2] = -std::abs(h.a[2]);  // facing down: keeps the apex inside
    const double len = std::sqrt(double(h.a[0] * h.a[0] + h.a[1] * h.a[1] + h.a[2] * h.a[2]));
    h.b = static_cast<std::int64_t>(std::floor(dist * len));
    return h;
  };
  for (int guard = 0; P.v.size() <= 70 && guard < 200; ++guard) cut(random_plane(3), false);
  ASSERT_GT(P.v.size(), 70u) << "the cell did not grow past 64 vertices";
  cut({{0, 0, -1}, 4}, true);  // a duplicate of a box plane: a second constraint tight on a face
  // checked cuts on the big cell: random ones (the apex, with 12 tight, inside), one through the
  // apex (apex tight, not cut), then ones cutting the apex off (it is outside with 12 tight)
  for (int i = 0; i < 10; ++i) {
    ++apex_inside;
    cut(random_plane(2.8), true);
  }
  cut({{1, 1, 0}, 0}, true);  // x + y ≤ 0 passes through the apex
  for (auto [a, b, c, d] : std::vector<std::array<int, 4>>{{0, 0, 1, 1}, {1, 0, 2, 3}, {0, 0, 1, 0}}) {
    ++apex_cut_off;
    cut({{a, b, c}, d}, true);
  }
  std::printf("%d cuts checked, %d of them on cells with > 64 vertices and a vertex with > 8 tight; most tight %zu\n",
              checked, checked_big, most_tight);
  EXPECT_GE(checked_big, 8) << "the big degenerate cell was not cut often enough to test the bit rows";
  EXPECT_GT(most_tight, 8u);
  (void)apex_inside;
  (void)apex_cut_off;
}
