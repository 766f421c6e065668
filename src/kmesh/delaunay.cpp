#include "kmesh/delaunay.hpp"

#include <algorithm>
#include <map>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/construction.hpp"

namespace kmr::kmesh {
namespace {

int orient(const Point2& a, const Point2& b, const Point2& c) { return geometry::orientation<Dyadic>(a, b, c); }

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
  closed = false;
  std::vector<int> out;
  if (cands.empty()) return out;
  const Point2& ps = pos[s];
  int a0 = -1;
  Dyadic bd;
  for (int c : cands) {
    Dyadic d = geometry::squared_distance<2, Dyadic>(ps, pos[c]);
    if (a0 < 0 || d < bd || (d == bd && c < a0)) a0 = c, bd = d;
  }
  // side = +1: the triangle (s, a, b) left of s→a; side = −1: the triangle (s, b, a) right of it.
  auto next = [&](int a, int side) {
    int best = -1;
    for (int c : cands) {
      ++ops;
      if (c == a || orient(ps, pos[a], pos[c]) != side) continue;
      if (best < 0) {
        best = c;
        continue;
      }
      int in = side > 0 ? perturbed_side_of_circle(ps, s, pos[a], a, pos[best], best, pos[c], c)
                        : perturbed_side_of_circle(ps, s, pos[best], best, pos[a], a, pos[c], c);
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
  for (int i = 0; i < N; ++i) pos[i] = S.position(i);
  std::map<std::array<int, 3>, int> seen;
  for (int s = 0; s < N; ++s) {
    Rank l = m.info[s].rank;
    std::vector<int> V;
    for (Rank r = l - 6; r <= l - 3; ++r)
      for (int x : S.neighbors(s, r)) {
        ++S.ops;
        if (within(pos[s], pos[x], 9, l - 2)) V.push_back(x);
      }
    std::sort(V.begin(), V.end());
    V.erase(std::unique(V.begin(), V.end()), V.end());
    bool closed = false;
    std::vector<int> star = delaunay_star(s, V, pos, closed, S.ops);
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
