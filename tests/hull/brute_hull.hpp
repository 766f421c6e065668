#pragma once
// A brute-force exact 3D hull judge for the tests, sharing no code with src/hull or
// geometry/predicates.hpp: determinants written out here over exact::Dyadic.
//
// judge_hull(points) enumerates every plane through three non-collinear points (O(n^3) planes,
// O(n) test each); a plane with all points weakly on one side supports a face; the points on it
// form the face; its corners (points not inside a triangle or on a segment of other points of the
// face) are the extreme points. check_hull(points, vertices, facets) then verifies an output:
//  * the vertex set equals the extreme points named by their lowest index among equal points;
//  * every facet lies in the plane of one face, uses only its corners, and is outward
//    (counter-clockwise from outside): the remaining points are on its negative side;
//  * every directed edge of the facets appears once and its reverse once (a closed surface);
//  * per face, the projected areas of its facets sum to the face polygon's projected area
//    (with the two above: each face is covered exactly once).
// It returns "" on success or a description of the first difference.
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "exact/dyadic.hpp"

namespace hull_judge {

using kmr::exact::Dyadic;
using P = std::array<Dyadic, 3>;

inline P sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline P cross(const P& a, const P& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Dyadic dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline bool is_zero(const P& a) { return a[0].is_zero() && a[1].is_zero() && a[2].is_zero(); }
// sign of (b−a)×(c−a)·(d−a): > 0 iff d is on the side from which a, b, c look counter-clockwise.
inline int orient(const P& a, const P& b, const P& c, const P& d) {
  return dot(cross(sub(b, a), sub(c, a)), sub(d, a)).sign();
}

struct Face {
  std::vector<int> on;       // indices (unique points) on the plane, increasing
  std::vector<int> corners;  // its extreme points
  P normal;                  // outward
  int a;                     // a point on the plane
};

struct Judge {
  std::vector<P> p;          // exact coordinates
  std::vector<int> name;     // lowest index of an equal point
  std::vector<int> unique;   // indices with name[i] == i
  std::vector<Face> faces;
  std::set<int> extreme;     // names
  bool degenerate = false;   // fewer than 4 affinely independent points
};

inline Judge judge_hull(const std::vector<std::array<double, 3>>& pts) {
  Judge j;
  const int n = static_cast<int>(pts.size());
  for (auto& q : pts) j.p.push_back({Dyadic::from_double(q[0]), Dyadic::from_double(q[1]), Dyadic::from_double(q[2])});
  j.name.resize(n);
  for (int i = 0; i < n; ++i) {
    j.name[i] = i;
    for (int k = 0; k < i; ++k)
      if (j.p[k] == j.p[i]) {
        j.name[i] = j.name[k];
        break;
      }
    if (j.name[i] == i) j.unique.push_back(i);
  }
  const auto& u = j.unique;
  const int m = static_cast<int>(u.size());
  std::set<std::vector<int>> seen;
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      for (int c = b + 1; c < m; ++c) {
        P nrm = cross(sub(j.p[u[b]], j.p[u[a]]), sub(j.p[u[c]], j.p[u[a]]));
        if (is_zero(nrm)) continue;
        int pos = 0, neg = 0;
        std::vector<int> on;
        for (int i : u) {
          int s = dot(nrm, sub(j.p[i], j.p[u[a]])).sign();
          pos += s > 0, neg += s < 0;
          if (s == 0) on.push_back(i);
        }
        if (pos && neg) continue;
        if (!pos && !neg) continue;  // all coplanar
        if (!seen.insert(on).second) continue;
        Face f;
        f.on = on;
        f.a = u[a];
        f.normal = pos ? P{-nrm[0], -nrm[1], -nrm[2]} : nrm;
        // corners: not on a segment or in a triangle of other points of the face
        for (int q : on) {
          bool inside = false;
          for (std::size_t x = 0; x < on.size() && !inside; ++x)
            for (std::size_t y = x + 1; y < on.size() && !inside; ++y) {
              int r = on[x], s = on[y];
              if (r == q || s == q) continue;
              P d1 = sub(j.p[r], j.p[q]), d2 = sub(j.p[s], j.p[q]);
              if (is_zero(cross(d1, d2)) && dot(d1, d2).sign() < 0) inside = true;  // q strictly between r, s
              for (std::size_t z = y + 1; z < on.size() && !inside; ++z) {
                int t = on[z];
                if (t == q) continue;
                // q in the closed triangle r s t (coplanar): the three normals agree in sign or vanish
                P n1 = cross(sub(j.p[s], j.p[r]), sub(j.p[q], j.p[r]));
                P n2 = cross(sub(j.p[t], j.p[s]), sub(j.p[q], j.p[s]));
                P n3 = cross(sub(j.p[r], j.p[t]), sub(j.p[q], j.p[t]));
                P tn = cross(sub(j.p[s], j.p[r]), sub(j.p[t], j.p[r]));
                if (is_zero(tn)) continue;
                if (dot(n1, tn).sign() >= 0 && dot(n2, tn).sign() >= 0 && dot(n3, tn).sign() >= 0) inside = true;
              }
            }
          if (!inside) f.corners.push_back(q);
        }
        for (int q : f.corners) j.extreme.insert(q);
        j.faces.push_back(std::move(f));
      }
  j.degenerate = j.faces.empty();
  return j;
}

// Twice the signed area of triangle a b c projected along axis k (drop coordinate k).
inline Dyadic projected_area(const P& a, const P& b, const P& c, int k) {
  int x = (k + 1) % 3, y = (k + 2) % 3;
  return (b[x] - a[x]) * (c[y] - a[y]) - (b[y] - a[y]) * (c[x] - a[x]);
}

inline std::string check_hull(const Judge& j, const std::vector<int>& vertices,
                              const std::vector<std::array<int, 3>>& facets) {
  std::vector<int> want(j.extreme.begin(), j.extreme.end());
  if (vertices != want) {
    std::string s = "vertices differ: want [";
    for (int v : want) s += std::to_string(v) + " ";
    s += "] got [";
    for (int v : vertices) s += std::to_string(v) + " ";
    return s + "]";
  }
  std::map<std::pair<int, int>, int> edges;
  std::vector<Dyadic> covered(j.faces.size(), Dyadic(0));
  for (const auto& t : facets) {
    auto tri = "facet [" + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "]";
    for (int v : t)
      if (!j.extreme.count(v)) return tri + " uses a non-vertex " + std::to_string(v);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return tri + " is degenerate";
    int fi = -1;
    for (std::size_t f = 0; f < j.faces.size() && fi < 0; ++f) {
      const auto& on = j.faces[f].on;
      if (std::count(on.begin(), on.end(), t[0]) && std::count(on.begin(), on.end(), t[1]) &&
          std::count(on.begin(), on.end(), t[2]))
        fi = static_cast<int>(f);
    }
    if (fi < 0) return tri + " lies on no face of the hull";
    const Face& f = j.faces[fi];
    P nrm = cross(sub(j.p[t[1]], j.p[t[0]]), sub(j.p[t[2]], j.p[t[0]]));
    if (dot(nrm, f.normal).sign() <= 0) return tri + " is not counter-clockwise from outside";
    int k = 0;
    while (f.normal[k].is_zero()) ++k;
    Dyadic ar = projected_area(j.p[t[0]], j.p[t[1]], j.p[t[2]], k);
    covered[fi] += f.normal[k].sign() > 0 ? ar : -ar;
    for (int e = 0; e < 3; ++e) ++edges[{t[e], t[(e + 1) % 3]}];
  }
  for (auto& [e, c] : edges) {
    if (c != 1) return "directed edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " appears " + std::to_string(c) + " times";
    auto it = edges.find({e.second, e.first});
    if (it == edges.end()) return "edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " has no reverse";
  }
  for (std::size_t fi = 0; fi < j.faces.size(); ++fi) {
    const Face& f = j.faces[fi];
    int k = 0;
    while (f.normal[k].is_zero()) ++k;
    // polygon area: corners sorted around corners[0] (all others lie in a half-plane from it)
    std::vector<int> c = f.corners;
    int c0 = c[0];
    std::sort(c.begin() + 1, c.end(), [&](int a, int b) { return dot(cross(sub(j.p[a], j.p[c0]), sub(j.p[b], j.p[c0])), f.normal).sign() > 0; });
    Dyadic area(0);
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
      Dyadic ar = projected_area(j.p[c0], j.p[c[i]], j.p[c[i + 1]], k);
      area += f.normal[k].sign() > 0 ? ar : -ar;
    }
    if (!(area == covered[fi])) return "face " + std::to_string(fi) + " is covered " + covered[fi].to_decimal() + " vs area " + area.to_decimal();
  }
  return "";
}

}  // namespace hull_judge
