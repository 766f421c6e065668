#include "kmesh/delaunay.hpp"

#include <algorithm>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/filtered.hpp"

namespace kmr::kmesh {
namespace {

int orient(const Point2& a, const Point2& b, const Point2& c) { return geometry::orientation<Dyadic>(a, b, c); }

// The exact in-circle test, perturbed (spec/kmesh.md) when the four points are cocircular.
int perturbed(const Point2& p, const Point2& q, const Point2& r, const Point2& t, bool p_max, bool q_max,
              bool r_max) {
  int s = geometry::side_of_oriented_circle<Dyadic>(p, q, r, t);
  if (s != 0) return s;
  // Cocircular: the highest lifted vertex is outside the circle of the other three. By antisymmetry
  // of the lifted determinant: t highest → −orient(p,q,r); r → orient(p,q,t); q → orient(p,t,r);
  // p → orient(t,q,r).
  if (r_max) return orient(p, q, t);
  if (q_max) return orient(p, t, r);
  if (p_max) return orient(t, q, r);
  return -orient(p, q, r);
}

// Filtered forms over the spanner's vertex ids, with its cached enclosures.
struct Geo {
  const Spanner& S;
  const LiftOrder& lower;
  const Point2& p(int i) const { return S.position(i); }
  const IPoint& e(int i) const { return S.enclosure(i); }
  bool below(int a, int b) const { return lower ? lower(a, b) : a < b; }
  int orient(int a, int b, int c) const { return orientation_filtered(p(a), e(a), p(b), e(b), p(c), e(c)); }
  int incircle(int a, int b, int c, int t) const {
    int s = side_of_circle_filtered(p(a), e(a), p(b), e(b), p(c), e(c), p(t), e(t));
    if (s != 0) return s;
    int m = a;
    for (int x : {b, c, t})
      if (below(m, x)) m = x;
    return perturbed(p(a), p(b), p(c), p(t), m == a, m == b, m == c);
  }
};

// The ccw neighbours of s among cands in the perturbed Delaunay triangulation of cands ∪ {s}.
VoronoiStar star_of(const Geo& g, int s, const std::vector<int>& cands) {
  VoronoiStar out;
  if (cands.empty()) return out;
  int a0 = -1;
  for (int c : cands) {
    if (a0 < 0) {
      a0 = c;
      continue;
    }
    int d = compare_distance(g.p(s), g.e(s), g.p(c), g.e(c), g.p(a0), g.e(a0));
    if (d < 0 || (d == 0 && g.below(c, a0))) a0 = c;
  }
  // side = +1: the triangle (s, a, b) left of s→a; side = −1: the triangle (s, b, a) right of it.
  auto next = [&](int a, int side) {
    int best = -1;
    for (int c : cands) {
      ++g.S.ops;
      if (c == a || g.orient(s, a, c) != side) continue;
      if (best < 0) {
        best = c;
        continue;
      }
      int in = side > 0 ? g.incircle(s, a, best, c) : g.incircle(s, best, a, c);
      if (in > 0) best = c;
    }
    return best;
  };
  std::vector<int>& ring = out.ring;
  ring.push_back(a0);
  for (int a = a0;;) {
    int b = next(a, +1);
    if (b < 0) break;
    if (b == a0) {
      out.closed = true;
      return out;
    }
    KMR_CHECK(ring.size() <= cands.size(), "voronoi_star: the walk does not close");
    ring.push_back(b);
    a = b;
  }
  // s is on the hull: walk clockwise from a0 as well.
  std::vector<int> cw;
  for (int a = a0;;) {
    int b = next(a, -1);
    if (b < 0) break;
    KMR_CHECK(cw.size() <= cands.size(), "voronoi_star: the clockwise walk does not end");
    cw.push_back(b);
    a = b;
  }
  std::reverse(cw.begin(), cw.end());
  cw.insert(cw.end(), ring.begin(), ring.end());
  ring = std::move(cw);
  return out;
}

}  // namespace

int perturbed_side_of_circle(const Point2& p, int ip, const Point2& q, int iq, const Point2& r, int ir,
                             const Point2& t, int it) {
  int m = std::max({ip, iq, ir, it});
  return perturbed(p, q, r, t, m == ip, m == iq, m == ir);
}

VoronoiStar voronoi_star(const Spanner& S, int s, Rank l, const LiftOrder& lower) {
  std::vector<int> V;
  const Point2& ps = S.position(s);
  const IPoint& es = S.enclosure(s);
  for (Rank r = l - 6; r <= l - 3; ++r)
    for (int x : S.neighbors(s, r)) {
      ++S.ops;
      if (within_filtered(ps, es, S.position(x), S.enclosure(x), 9, l - 2)) V.push_back(x);
    }
  std::sort(V.begin(), V.end());
  V.erase(std::unique(V.begin(), V.end()), V.end());
  return star_of(Geo{S, lower}, s, V);
}

std::vector<std::array<int, 3>> triangles_from_stars(const VoronoiStars& stars, const std::vector<int>& new_id) {
  auto id = [&](int x) { return new_id.empty() ? x : new_id[x]; };
  std::vector<std::array<int, 3>> all;
  for (std::size_t s = 0; s < stars.size(); ++s) {
    const std::vector<int>& ring = stars[s].ring;
    const std::size_t k = ring.size();
    for (std::size_t i = 0; i + 1 < k || (stars[s].closed && i < k); ++i) {
      std::array<int, 3> t{id(static_cast<int>(s)), id(ring[i]), id(ring[(i + 1) % k])};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      all.push_back(t);
    }
  }
  std::sort(all.begin(), all.end());
  std::vector<std::array<int, 3>> out;
  for (std::size_t i = 0; i < all.size(); i += 3) {
    KMR_CHECK(i + 2 < all.size() && all[i] == all[i + 2] && (i + 3 == all.size() || all[i + 3] != all[i]),
              "IdentifyVoronoiNeighbors: a triangle is not found from all its corners (Lemma 4.2.9)");
    out.push_back(all[i]);
  }
  return out;
}

VoronoiStars voronoi_stars(const Mesh& m) {
  const Spanner& S = m.spanner;
  VoronoiStars stars(S.size());
  for (int s = 0; s < static_cast<int>(S.size()); ++s) stars[s] = voronoi_star(S, s, m.info[s].rank);
  return stars;
}

}  // namespace kmr::kmesh
