#include "kmesh/delaunay.hpp"

#include <algorithm>
#include <map>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/filtered.hpp"

namespace kmr::kmesh {
namespace {

int orient(const Point2& a, const Point2& b, const Point2& c) { return geometry::orientation<Dyadic>(a, b, c); }

// Filtered forms over vertex ids with cached enclosures.
struct Geo {
  const std::vector<Point2>& p;
  const std::vector<IPoint>& e;
  int orient(int a, int b, int c) const { return orientation_filtered(p[a], e[a], p[b], e[b], p[c], e[c]); }
  int incircle(int a, int b, int c, int t) const {
    int s = side_of_circle_filtered(p[a], e[a], p[b], e[b], p[c], e[c], p[t], e[t]);
    return s != 0 ? s : perturbed_side_of_circle(p[a], a, p[b], b, p[c], c, p[t], t);
  }
};

}  // namespace

int perturbed_side_of_circle(const Point2& p, int ip, const Point2& q, int iq, const Point2& r, int ir,
                             const Point2& t, int it) {
  int s = geometry::side_of_oriented_circle<Dyadic>(p, q, r, t);
  if (s != 0) return s;
  // Cocircular: the largest id is lifted highest, i.e. it is outside the circle of the other three.
  // By antisymmetry of the lifted determinant: t largest → −orient(p,q,r); r → orient(p,q,t);
  // q → orient(p,t,r); p → orient(t,q,r).
  int m = std::max({ip, iq, ir, it});
  if (m == it) return -orient(p, q, r);
  if (m == ir) return orient(p, q, t);
  if (m == iq) return orient(p, t, r);
  return orient(t, q, r);
}

std::vector<int> delaunay_star(int s, const std::vector<int>& cands, const std::vector<Point2>& pos,
                               bool& closed, std::uint64_t& ops) {
  std::vector<IPoint> e(pos.size());
  for (int c : cands) e[c] = enclose(pos[c]);
  e[s] = enclose(pos[s]);
  return delaunay_star(s, cands, pos, e, closed, ops);
}

std::vector<int> delaunay_star(int s, const std::vector<int>& cands, const std::vector<Point2>& pos,
                               const std::vector<IPoint>& enc, bool& closed, std::uint64_t& ops) {
  Geo g{pos, enc};
  closed = false;
  std::vector<int> out;
  if (cands.empty()) return out;
  const Point2& ps = pos[s];
  int a0 = -1;
  for (int c : cands)  // cands sorted: ties keep the smaller id
    if (a0 < 0 || compare_distance(ps, enc[s], pos[c], enc[c], pos[a0], enc[a0]) < 0) a0 = c;
  // side = +1: the triangle (s, a, b) left of s→a; side = −1: the triangle (s, b, a) right of it.
  auto next = [&](int a, int side) {
    int best = -1;
    for (int c : cands) {
      ++ops;
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
  out.push_back(a0);
  for (int a = a0;;) {
    int b = next(a, +1);
    if (b < 0) break;
    if (b == a0) {
      closed = true;
      return out;
    }
    KMR_CHECK(out.size() <= cands.size(), "delaunay_star: the walk does not close");
    out.push_back(b);
    a = b;
  }
  // s is on the hull: walk clockwise from a0 as well.
  std::vector<int> cw;
  for (int a = a0;;) {
    int b = next(a, -1);
    if (b < 0) break;
    KMR_CHECK(cw.size() <= cands.size(), "delaunay_star: the clockwise walk does not end");
    cw.push_back(b);
    a = b;
  }
  std::reverse(cw.begin(), cw.end());
  cw.insert(cw.end(), out.begin(), out.end());
  return cw;
}

std::vector<std::array<int, 3>> delaunay_from_candidates(Mesh& m) {
  const Spanner& S = m.spanner;
  const int N = static_cast<int>(S.size());
  std::vector<Point2> pos(N);
  std::vector<IPoint> enc(N);
  for (int i = 0; i < N; ++i) pos[i] = S.position(i), enc[i] = S.enclosure(i);
  std::map<std::array<int, 3>, int> seen;
  for (int s = 0; s < N; ++s) {
    Rank l = m.info[s].rank;
    std::vector<int> V;
    for (Rank r = l - 6; r <= l - 3; ++r)
      for (int x : S.neighbors(s, r)) {
        ++S.ops;
        if (within_filtered(pos[s], enc[s], pos[x], enc[x], 9, l - 2)) V.push_back(x);
      }
    std::sort(V.begin(), V.end());
    V.erase(std::unique(V.begin(), V.end()), V.end());
    bool closed = false;
    std::vector<int> star = delaunay_star(s, V, pos, enc, closed, S.ops);
    std::size_t k = star.size();
    for (std::size_t i = 0; i + 1 < k || (closed && i < k); ++i) {
      std::array<int, 3> t{s, star[i], star[(i + 1) % k]};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      ++seen[t];
    }
  }
  std::vector<std::array<int, 3>> out;
  for (auto& [t, c] : seen) {
    KMR_CHECK(c == 3, "IdentifyVoronoiNeighbors: a triangle is not found from all its corners (Lemma 4.2.9)");
    out.push_back(t);
  }
  return out;
}

}  // namespace kmr::kmesh
