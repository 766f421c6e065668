// Fuzz harness (i): dynamic well-spaced point sets (thesis Ch. 3) through the public WellSpacedSet
// API, judged by brute force written here (exact rationals, Boost mpq; no kmr::wellspaced code).
// Input bytes give D ∈ {2, 3}, ρ ∈ {1.5, 2, 3} (β = max(3, 2ρ)), 2..6 input points on a dyadic grid
// (coordinates j/2^g, g ≤ 6: grids, collinear, cocircular and near-duplicate inputs come easily) and
// up to 4 updates. Checks, after construction and after every update:
//  * the output contains every input point exactly once as an input vertex, and nothing else is
//    flagged as input; all vertices lie in [0,1]^D and are distinct;
//  * size-conforming (Lemma 3.3.3): NN_M(v)·c ≥ lfs_N(v) for every output vertex, c = 2ρ/(ρ−1),
//    lfs_N(v) = distance from v to its second-nearest input point (exactly, squared);
//  * ρ-well-spaced: Vor_M(v) ∩ [0,1]^D lies in the closed ball of radius ρ·NN_M(v); D = 2: the unit
//    square clipped by every bisector half-plane (a polygon, exact); D = 3: the unit cube's vertex
//    set clipped by every bisector half-space (vertices with their tight planes, exact);
//  * updates equal from scratch: vertices() and canonical_graph() equal those of a fresh
//    WellSpacedSet on the current input.
// Inputs the library refuses (InputError: points closer than its depth limit, ...) end the case.
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <boost/multiprecision/gmp.hpp>
#include <set>

#include "exact/error.hpp"
#include "fuzz_common.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace {

using Q = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;
using kmr::wellspaced::Point;

template <std::size_t D>
Q dist2(const Point<D>& a, const Point<D>& b) {
  Q s(0);
  for (std::size_t i = 0; i < D; ++i) {
    Q d = Q(a[i]) - Q(b[i]);
    s += d * d;
  }
  return s;
}

// Vor(v) ∩ [0,1]² as a polygon, clipped by the bisector half-planes {x : |x−v|² ≤ |x−q|²}.
bool well_spaced_2d(const std::vector<Point<2>>& M, std::size_t vi, const Q& rho2, std::string& why) {
  const Point<2>& v = M[vi];
  Q vx(v[0]), vy(v[1]);
  std::vector<std::pair<Q, Q>> poly{{Q(0), Q(0)}, {Q(1), Q(0)}, {Q(1), Q(1)}, {Q(0), Q(1)}};
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < M.size(); ++j)
    if (j != vi) order.push_back(j);
  std::vector<Q> d2(M.size());
  for (std::size_t j : order) d2[j] = dist2<2>(v, M[j]);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d2[a] < d2[b]; });
  Q nn2 = d2[order.front()];
  auto radius2 = [&] {
    Q r(0);
    for (auto& [x, y] : poly) r = std::max(r, (x - vx) * (x - vx) + (y - vy) * (y - vy));
    return r;
  };
  Q r2 = radius2();
  for (std::size_t j : order) {
    if (d2[j] >= 4 * r2) break;  // q's bisector is at distance ≥ |q−v|/2 ≥ the polygon's radius: no cut
    Q ax = Q(M[j][0]) - vx, ay = Q(M[j][1]) - vy;  // keep a·x ≤ b, b = (|q|² − |v|²)/2
    Q b = (Q(M[j][0]) * Q(M[j][0]) + Q(M[j][1]) * Q(M[j][1]) - vx * vx - vy * vy) / 2;
    std::vector<std::pair<Q, Q>> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const auto& p = poly[k];
      const auto& q = poly[(k + 1) % poly.size()];
      Q fp = ax * p.first + ay * p.second - b, fq = ax * q.first + ay * q.second - b;
      if (fp <= 0) out.push_back(p);
      if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
        Q t = fp / (fp - fq);
        out.push_back({p.first + t * (q.first - p.first), p.second + t * (q.second - p.second)});
      }
    }
    poly = std::move(out);
    r2 = radius2();
  }
  if (r2 > rho2 * nn2) {
    why = "vertex " + std::to_string(vi) + " has a Voronoi cell of radius² " + r2.str() + " > ρ²·NN² = " + (rho2 * nn2).str();
    return false;
  }
  return true;
}

// D = 3: Vor(v) ∩ [0,1]³ as a vertex set, clipped by the bisector half-spaces {x : a·x ≤ b} one at a
// time. Each vertex carries the planes tight at it (0..5 the cube's faces, then the bisectors in the
// order cut). A new vertex of a cut lies on an old edge: two old vertices on opposite sides that
// share two tight planes (distinct planes tight at one point meet in a line, so the segment between
// them lies on that line inside the cell, and its crossing of the cut is a point of the new cell on
// three independent planes). Extra points of this kind are harmless (they are in the cell, and the
// farthest point of a polytope from v is a vertex); none is missed (every new vertex is the crossing
// of an edge whose ends are old vertices). So the radius is exact.
// Arithmetic: every double of M times 2^S is an integer (S from frexp), so planes have integer
// coefficients and vertices are primitive homogeneous integer vectors (X, Y, Z, W), W > 0 (unique,
// so equal points have equal vectors); no rationals, one gcd per new vertex.
using Z = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;
using H = std::array<Z, 4>;  // X, Y, Z, W
struct Vertex3 {
  H x;
  std::vector<int> tight;  // sorted plane ids
};
struct Plane3 {
  std::array<Z, 3> a;
  Z b;
  Z eval(const H& x) const { return a[0] * x[0] + a[1] * x[1] + a[2] * x[2] - b * x[3]; }
};

bool well_spaced_3d(const std::vector<Point<3>>& M, std::size_t vi, const Q& rho2, std::string& why) {
  int S = 0;
  for (const auto& p : M)
    for (double c : p)
      if (c != 0) {
        int e;
        std::frexp(c, &e);
        S = std::max(S, 53 - e);
      }
  auto scaled = [&](double c) {
    Z z;
    mpz_set_d(z.backend().data(), std::ldexp(c, S));  // exact: an integral double
    return z;
  };
  std::vector<std::array<Z, 3>> P;
  for (const auto& p : M) P.push_back({scaled(p[0]), scaled(p[1]), scaled(p[2])});
  const auto& v = P[vi];
  const Z L = Z(1) << static_cast<unsigned>(S);
  std::vector<Plane3> planes;
  for (int k = 0; k < 3; ++k) {  // −x_k ≤ 0 (id 2k), x_k ≤ L (id 2k + 1)
    Plane3 lo{{Z(0), Z(0), Z(0)}, Z(0)}, hi{{Z(0), Z(0), Z(0)}, L};
    lo.a[static_cast<std::size_t>(k)] = -1;
    hi.a[static_cast<std::size_t>(k)] = 1;
    planes.push_back(lo);
    planes.push_back(hi);
  }
  std::vector<Vertex3> cell;
  for (int c = 0; c < 8; ++c) {
    Vertex3 w;
    w.x[3] = 1;
    for (int k = 0; k < 3; ++k) {
      int bit = (c >> k) & 1;
      w.x[static_cast<std::size_t>(k)] = bit ? L : Z(0);
      w.tight.push_back(2 * k + bit);
    }
    std::sort(w.tight.begin(), w.tight.end());
    cell.push_back(w);
  }
  auto d2 = [&](const std::array<Z, 3>& q) {
    Z s(0);
    for (std::size_t k = 0; k < 3; ++k) s += (q[k] - v[k]) * (q[k] - v[k]);
    return s;
  };
  std::vector<std::size_t> order;
  for (std::size_t j = 0; j < M.size(); ++j)
    if (j != vi) order.push_back(j);
  std::vector<Z> dist(M.size());
  for (std::size_t j : order) dist[j] = d2(P[j]);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return dist[a] < dist[b]; });
  const Z nn2 = dist[order.front()];
  auto radius2 = [&] {  // max |w − v|² as num / den
    Z num(0), den(1);
    for (const auto& w : cell) {
      Z s(0);
      for (std::size_t k = 0; k < 3; ++k) s += (w.x[k] - v[k] * w.x[3]) * (w.x[k] - v[k] * w.x[3]);
      Z dd = w.x[3] * w.x[3];
      if (s * den > num * dd) num = s, den = dd;
    }
    return std::pair<Z, Z>{num, den};
  };
  auto r2 = radius2();
  for (std::size_t j : order) {
    if (dist[j] * r2.second >= 4 * r2.first) break;  // the bisector is at distance ≥ |q−v|/2 ≥ the cell's radius
    Plane3 h;
    Z qq(0), vv(0);
    for (std::size_t k = 0; k < 3; ++k) {
      h.a[k] = 2 * (P[j][k] - v[k]);
      qq += P[j][k] * P[j][k];
      vv += v[k] * v[k];
    }
    h.b = qq - vv;
    int id = static_cast<int>(planes.size());
    planes.push_back(h);
    std::vector<Z> f;
    for (const auto& w : cell) f.push_back(h.eval(w.x));
    std::vector<Vertex3> out;
    for (std::size_t p = 0; p < cell.size(); ++p)
      if (f[p] <= 0) {
        out.push_back(cell[p]);
        if (f[p] == 0) out.back().tight.push_back(id);  // id is the largest: still sorted
      }
    const std::size_t kept = out.size();
    for (std::size_t p = 0; p < cell.size(); ++p) {
      if (f[p] >= 0) continue;
      for (std::size_t q = 0; q < cell.size(); ++q) {
        if (f[q] <= 0) continue;
        std::vector<int> common;
        std::set_intersection(cell[p].tight.begin(), cell[p].tight.end(), cell[q].tight.begin(), cell[q].tight.end(),
                              std::back_inserter(common));
        if (common.size() < 2) continue;
        Vertex3 w;  // f_q·p − f_p·q: on the cut, W > 0 (f_q > 0 > f_p)
        for (std::size_t k = 0; k < 4; ++k) w.x[k] = f[q] * cell[p].x[k] - f[p] * cell[q].x[k];
        Z g = w.x[3];
        for (std::size_t k = 0; k < 3; ++k) g = boost::multiprecision::gcd(g, w.x[k]);
        for (auto& c : w.x) c /= g;
        auto same = std::find_if(out.begin(), out.end(), [&](const Vertex3& o) { return o.x == w.x; });
        if (same != out.end()) continue;  // already a vertex
        out.push_back(w);
      }
    }
    // The new vertices' exact tight sets among the planes of the new cell's faces (degenerate
    // vertices lie on more than three): a face other than the cut keeps one of its old vertices,
    // whose tight set names it. (Kept vertices keep theirs, plus the cut if they lie on it.)
    std::set<int> faces{id};
    for (std::size_t p = 0; p < cell.size(); ++p)
      if (f[p] <= 0) faces.insert(cell[p].tight.begin(), cell[p].tight.end());
    for (std::size_t i = kept; i < out.size(); ++i) {
      auto& w = out[i];
      w.tight.clear();
      for (int k : faces)
        if (planes[static_cast<std::size_t>(k)].eval(w.x) == 0) w.tight.push_back(k);
    }
    cell = std::move(out);
    r2 = radius2();
  }
  // radius² = num / den (scaled by 4^S like nn2); well-spaced iff num·q ≤ p·nn2·den for ρ² = p/q.
  Z pn(boost::multiprecision::numerator(rho2).str()), pd(boost::multiprecision::denominator(rho2).str());
  if (r2.first * pd > pn * nn2 * r2.second) {
    why = "vertex " + std::to_string(vi) + " has a Voronoi cell of radius² " + Q(r2.first.str() + "/" + r2.second.str()).str() +
          " > ρ²·NN² = " + Q((pn * nn2).str() + "/" + pd.str()).str() + " (both ×4^" + std::to_string(S) + ")";
    return false;
  }
  return true;
}

template <std::size_t D>
void judge(const kmr::wellspaced::WellSpacedSet<D>& ws, const std::set<Point<D>>& input, double rho, const std::string& what) {
  auto verts = ws.vertices();
  std::vector<Point<D>> M;
  std::set<Point<D>> seen_input, all;
  for (const auto& v : verts) {
    for (double x : v.x) FUZZ_CHECK(x >= 0 && x <= 1, what + ": vertex outside [0,1]^D");
    FUZZ_CHECK(all.insert(v.x).second, what + ": duplicate vertex");
    if (!v.is_steiner) FUZZ_CHECK(input.count(v.x) && seen_input.insert(v.x).second, what + ": bad input vertex");
    M.push_back(v.x);
  }
  FUZZ_CHECK(seen_input.size() == input.size(), what + ": an input point is missing from the output");
  FUZZ_CHECK(std::vector<Point<D>>(input.begin(), input.end()) == ws.input(), what + ": input() differs");
  Q r(rho), c2 = (2 * r) * (2 * r) / ((r - 1) * (r - 1));  // c² = (2ρ/(ρ−1))²
  for (std::size_t i = 0; i < M.size(); ++i) {
    Q nn2(-1), l1(-1), l2(-1);
    for (std::size_t j = 0; j < M.size(); ++j)
      if (j != i && (nn2 < 0 || dist2<D>(M[i], M[j]) < nn2)) nn2 = dist2<D>(M[i], M[j]);
    for (const auto& p : input) {  // the two smallest distances to input points
      Q d = dist2<D>(M[i], p);
      if (l1 < 0 || d < l1) l2 = l1, l1 = d;
      else if (l2 < 0 || d < l2) l2 = d;
    }
    FUZZ_CHECK(nn2 * c2 >= l2, what + ": not size-conforming at vertex " + std::to_string(i));
  }
  std::string why;
  for (std::size_t i = 0; i < M.size(); ++i) {
    if constexpr (D == 2) FUZZ_CHECK(well_spaced_2d(M, i, r * r, why), what + ": " + why);
    else FUZZ_CHECK(well_spaced_3d(M, i, r * r, why), what + ": " + why);
  }
}

template <std::size_t D>
void run(kmr_fuzz::ByteReader& in) {
  static const double rhos[] = {1.5, 2.0, 3.0};
  kmr::wellspaced::Params params;
  params.rho = rhos[in.byte() % 3];
  params.beta = std::max(3.0, 2 * params.rho);
  int g = in.byte() % 7;  // grid 2^-g
  auto coord = [&] { return static_cast<double>(in.byte() % ((1 << g) + 1)) / (1 << g); };
  auto point = [&] {
    Point<D> p;
    for (auto& x : p) x = coord();
    return p;
  };
  int n = 2 + in.byte() % 5;
  std::set<Point<D>> input;
  for (int i = 0; i < n; ++i) input.insert(point());
  if (input.size() < 2) return;
  std::vector<Point<D>> start(input.begin(), input.end());
  std::unique_ptr<kmr::wellspaced::WellSpacedSet<D>> ws;
  try {
    ws = std::make_unique<kmr::wellspaced::WellSpacedSet<D>>(start, params);
  } catch (const kmr::InputError&) {
    return;
  }
  judge<D>(*ws, input, params.rho, "construction");
  int updates = in.byte() % 5;
  for (int u = 0; u < updates && !in.empty(); ++u) {
    Point<D> p = point();
    bool erase = input.count(p) > 0;
    if (erase && input.size() <= 2) continue;
    try {
      if (erase) ws->erase(p);
      else ws->insert(p);
    } catch (const kmr::InputError&) {
      return;
    }
    if (erase) input.erase(p);
    else input.insert(p);
    std::string what = "update " + std::to_string(u);
    judge<D>(*ws, input, params.rho, what);
    kmr::wellspaced::WellSpacedSet<D> fresh(ws->input(), params);
    auto a = ws->vertices(), b = fresh.vertices();
    FUZZ_CHECK(a.size() == b.size(), what + ": vertex count differs from scratch");
    for (std::size_t i = 0; i < a.size(); ++i)
      FUZZ_CHECK(a[i].x == b[i].x && a[i].is_steiner == b[i].is_steiner, what + ": vertices differ from scratch");
    FUZZ_CHECK(ws->canonical_graph() == fresh.canonical_graph(), what + ": computation graph differs from scratch");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kmr_fuzz::ByteReader in(data, size);
  if (in.byte() % 2 == 0) run<2>(in);
  else run<3>(in);
  return 0;
}
