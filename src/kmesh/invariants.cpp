#include "kmesh/invariants.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "geometry/predicates.hpp"

namespace kmr::kmesh {
namespace {

using geometry::operator-;

Dyadic sqdist(const Point2& p, const Point2& q) { return geometry::squared_distance<2, Dyadic>(p, q); }
std::string str(const Point2& p) { return "(" + p[0].to_decimal() + ", " + p[1].to_decimal() + ")"; }
void add(CheckResult& r, const std::string& s) {
  if (r.violations.size() < 20) r.violations.push_back(s);
}

std::vector<Point2> positions(const Spanner& S) {
  std::vector<Point2> p(S.size());
  for (std::size_t i = 0; i < S.size(); ++i) p[i] = S.position(static_cast<int>(i));
  return p;
}

// Nearest-neighbour squared distance of every point, exact, by a sweep over x-sorted points.
std::vector<Dyadic> nn2(const std::vector<Point2>& p) {
  const std::size_t n = p.size();
  std::vector<std::size_t> ord(n);
  for (std::size_t i = 0; i < n; ++i) ord[i] = i;
  std::sort(ord.begin(), ord.end(), [&](auto a, auto b) { return p[a][0] < p[b][0]; });
  std::vector<Dyadic> best(n);
  std::vector<bool> has(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t i = ord[k];
    for (int dir : {-1, 1}) {
      for (std::ptrdiff_t j = static_cast<std::ptrdiff_t>(k) + dir; j >= 0 && j < static_cast<std::ptrdiff_t>(n); j += dir) {
        Dyadic dx = p[ord[j]][0] - p[i][0];
        if (has[i] && dx * dx > best[i]) break;
        Dyadic d = sqdist(p[i], p[ord[j]]);
        if (!has[i] || d < best[i]) best[i] = d, has[i] = true;
      }
    }
  }
  return best;
}

Rank lowest_neighbor_rank(const Point2& a, const Point2& b) { return min_rank_within(a, b, kC); }

}  // namespace

CheckResult check_spanner(const Spanner& S) {
  CheckResult r{"spanner", {}, 0};
  const int n = static_cast<int>(S.size());
  for (int x = 0; x < n; ++x)
    for (int y = x + 1; y < n; ++y) {
      Dyadic d = sqdist(S.position(x), S.position(y));
      Rank mt = std::min(S.top(x), S.top(y));
      if (d.sign() == 0) {
        add(r, "S1: vertices " + std::to_string(x) + " and " + std::to_string(y) + " coincide");
        continue;
      }
      if (d <= threshold2(1, mt))
        add(r, "S1 separation: " + std::to_string(x) + ", " + std::to_string(y) + " are both " +
                   std::to_string(mt) + "-centers within 2^" + std::to_string(mt));
      // S3: neighbours exactly at the ranks [l0, mt].
      Rank l0 = lowest_neighbor_rank(S.position(x), S.position(y));
      for (Rank l = std::min(l0, mt + 1) - 1; l <= mt; ++l) {
        bool want = l >= l0;
        auto& nx = S.neighbors(x, l);
        auto& ny = S.neighbors(y, l);
        bool hx = std::binary_search(nx.begin(), nx.end(), y), hy = std::binary_search(ny.begin(), ny.end(), x);
        if (hx != want || hy != want)
          add(r, "S3 neighbours: " + std::to_string(x) + ", " + std::to_string(y) + " at rank " + std::to_string(l) +
                     (want ? " missing" : " wrongly listed"));
      }
    }
  // Neighbour lists only name centers at ranks they are centers at.
  for (int x = 0; x < n; ++x)
    for (Rank l = S.top(x) + 1; l <= S.top(x) + 3; ++l)
      if (!S.neighbors(x, l).empty()) add(r, "S3: vertex " + std::to_string(x) + " has neighbours above its top rank");
  // S2 covering and parents; S4 kids.
  std::map<std::pair<int, Rank>, std::vector<int>> kids;
  for (int x = 0; x < n; ++x) {
    if (x == S.root()) {
      if (S.top(x) != S.top_rank()) add(r, "root is not at the top rank");
      continue;
    }
    if (S.top(x) >= S.top_rank()) add(r, "S1: a second vertex at the top rank");
    Rank t = S.top(x) + 1;
    bool covered = false;
    for (int y = 0; y < n && !covered; ++y)
      if (y != x && S.top(y) >= t && within(S.position(x), S.position(y), 1, t)) covered = true;
    if (!covered) add(r, "S2 covering: no " + std::to_string(t) + "-center within 2^" + std::to_string(t) + " of " + std::to_string(x));
    int p = S.parent(x);
    if (p < 0 || p >= n || S.top(p) < t || !within(S.position(x), S.position(p), 1, t))
      add(r, "S2 parent of " + std::to_string(x) + " is not a " + std::to_string(t) + "-center within 2^" + std::to_string(t));
    else
      kids[{p, S.top(x)}].push_back(x);
  }
  for (int y = 0; y < n; ++y)
    for (Rank l = S.top(y) - 80; l < S.top(y); ++l) {
      auto k = S.kids(y, l);
      std::sort(k.begin(), k.end());
      auto& want = kids[{y, l}];
      if (k != want) add(r, "S4 kids of " + std::to_string(y) + " at rank " + std::to_string(l));
    }
  return r;
}

CheckResult check_ball_empty(const Mesh& m) {
  CheckResult r{"L4.2.4", {}, 0};
  const Spanner& S = m.spanner;
  for (auto& c : m.considered) {
    Point2 s = satellite_position(S.position(c.nucleus), c.ray, c.rank);
    bool empty = true;
    for (int x = 0; x < c.existing && empty; ++x)
      if (within(s, S.position(x), 1, c.rank - 2)) empty = false;
    if (empty != c.converted)
      add(r, "satellite (nucleus " + std::to_string(c.nucleus) + ", ray " + std::to_string(c.ray) + ", rank " +
                 std::to_string(c.rank) + "): ball " + (empty ? "empty" : "not empty") + " but " +
                 (c.converted ? "converted" : "not converted"));
  }
  return r;
}

CheckResult check_independent_set(const Mesh& m) {
  CheckResult r{"L4.2.5", {}, 0};
  const Spanner& S = m.spanner;
  std::map<Rank, std::vector<const Considered*>> by_rank;
  for (auto& c : m.considered) by_rank[c.rank].push_back(&c);
  for (auto& [l, cs] : by_rank) {
    int start = cs.front()->existing;  // vertices before the rank's first conversion
    std::vector<Point2> pos;
    std::vector<bool> conv;
    for (auto* c : cs) {
      Point2 s = satellite_position(S.position(c->nucleus), c->ray, c->rank);
      bool empty = true;
      for (int x = 0; x < start && empty; ++x)
        if (within(s, S.position(x), 1, l - 2)) empty = false;
      if (!empty) {
        if (c->converted) add(r, "rank " + std::to_string(l) + ": converted a satellite outside the proximity graph");
        continue;
      }
      pos.push_back(s);
      conv.push_back(c->converted);
    }
    for (std::size_t i = 0; i < pos.size(); ++i) {
      bool blocked = false;
      for (std::size_t j = 0; j < pos.size(); ++j) {
        if (i == j || !within(pos[i], pos[j], 1, l - 2)) continue;
        if (conv[i] && conv[j]) add(r, "rank " + std::to_string(l) + ": two adjacent satellites converted");
        if (conv[j]) blocked = true;
      }
      if (!conv[i] && !blocked) add(r, "rank " + std::to_string(l) + ": not maximal at " + str(pos[i]));
    }
  }
  return r;
}

CheckResult check_empty_balls(const Mesh& m) {
  CheckResult r{"L4.2.6", {}, 0};
  const Spanner& S = m.spanner;
  if (m.size() < 2) return r;
  auto p = positions(S);
  auto d = nn2(p);
  for (std::size_t v = 0; v < p.size(); ++v)
    if (d[v] <= threshold2(1, m.info[v].rank - 2))
      add(r, "vertex " + std::to_string(v) + " of rank " + std::to_string(m.info[v].rank) + " has a vertex within 2^(rank-2)");
  return r;
}

CheckResult check_voronoi_candidates(const Mesh& m) {
  CheckResult r{"L4.2.9", {}, 0};
  const Spanner& S = m.spanner;
  std::set<std::pair<int, int>> edges;
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) edges.insert({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  for (auto [a, b] : edges)
    for (auto [s, v] : {std::pair{a, b}, std::pair{b, a}}) {
      Rank l = m.info[s].rank;
      Rank l0 = lowest_neighbor_rank(S.position(s), S.position(v));
      // v is an r-neighbour of s for r ∈ [l0, min top]; need that range to meet [l−6, l−3].
      Rank hi = std::min({S.top(s), S.top(v), l - 3});
      if (std::max(l0, l - 6) > hi)
        add(r, "Delaunay edge " + std::to_string(s) + "-" + std::to_string(v) + " is not a neighbour pair at ranks l-6..l-3");
    }
  return r;
}

CheckResult check_min_ranks(const Mesh& m) {
  CheckResult r{"L4.2.10", {}, 0};
  const Spanner& S = m.spanner;
  const int n = static_cast<int>(S.size());
  for (int s = 0; s < n; ++s) {
    if (!m.info[s].steiner) continue;
    Rank lam = S.top(s) + 1;
    for (int x = 0; x < n; ++x) {
      if (x == s) continue;
      Rank l0 = lowest_neighbor_rank(S.position(s), S.position(x));
      if (l0 <= std::min(S.top(s), S.top(x))) lam = std::min(lam, l0);
    }
    Rank l = m.info[s].rank;
    if (lam < l - 6 || lam > l - 3)
      add(r, "satellite " + std::to_string(s) + " converted at rank " + std::to_string(l) + " has minimum rank " + std::to_string(lam));
  }
  return r;
}

CheckResult check_delaunay(const Mesh& m) {
  CheckResult r{"delaunay", {}, 0};
  auto p = positions(m.spanner);
  const std::size_t n = p.size();
  if (n < 3) {
    if (!m.triangles.empty()) add(r, "triangles on fewer than 3 vertices");
    return r;
  }
  std::vector<std::size_t> ord(n), where(n);
  for (std::size_t i = 0; i < n; ++i) ord[i] = i;
  std::sort(ord.begin(), ord.end(), [&](auto a, auto b) { return p[a] < p[b]; });
  for (std::size_t k = 0; k < n; ++k) where[ord[k]] = k;
  std::map<std::pair<int, int>, int> directed;
  Dyadic area2(0);
  for (auto& t : m.triangles) {
    const Point2 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    if (geometry::orientation<Dyadic>(a, b, c) <= 0) {
      add(r, "triangle not counter-clockwise");
      continue;
    }
    area2 += geometry::orientation_value<Dyadic>(a, b, c);
    for (int i = 0; i < 3; ++i)
      if (++directed[{t[i], t[(i + 1) % 3]}] > 1) add(r, "a directed edge is used twice");
    // Empty circumcircle: scan x-sorted points near a while |x − a.x| ≤ 2R (exact).
    Point2 bb = b - a, cc = c - a;
    Dyadic D = (bb[0] * cc[1] - bb[1] * cc[0]) * Dyadic(2);
    Dyadic nb = bb[0] * bb[0] + bb[1] * bb[1], nc = cc[0] * cc[0] + cc[1] * cc[1];
    Dyadic ux = cc[1] * nb - bb[1] * nc, uy = bb[0] * nc - cc[0] * nb;  // center = a + U/D
    Dyadic four_r2d2 = (ux * ux + uy * uy) * Dyadic(4);
    for (int dir : {-1, 1})
      for (std::ptrdiff_t j = static_cast<std::ptrdiff_t>(where[t[0]]) + dir; j >= 0 && j < static_cast<std::ptrdiff_t>(n); j += dir) {
        const Point2& q = p[ord[j]];
        Dyadic dx = (q[0] - a[0]) * D;
        if (dx * dx > four_r2d2) break;
        if (geometry::side_of_oriented_circle<Dyadic>(a, b, c, q) > 0) {
          add(r, "vertex " + std::to_string(ord[j]) + " inside the circumcircle of a triangle");
        }
      }
  }
  // Boundary edges (directed edges without their reverse) must be the convex hull, ccw.
  std::vector<std::size_t> hull;  // Andrew's monotone chain with collinear points kept
  {
    std::vector<std::size_t> lower, upper;
    for (std::size_t k = 0; k < n; ++k) {
      auto i = ord[k];
      while (lower.size() >= 2 && geometry::orientation<Dyadic>(p[lower[lower.size() - 2]], p[lower.back()], p[i]) < 0) lower.pop_back();
      lower.push_back(i);
    }
    for (std::size_t k = n; k-- > 0;) {
      auto i = ord[k];
      while (upper.size() >= 2 && geometry::orientation<Dyadic>(p[upper[upper.size() - 2]], p[upper.back()], p[i]) < 0) upper.pop_back();
      upper.push_back(i);
    }
    hull = lower;
    hull.insert(hull.end(), upper.begin() + 1, upper.end() - 1);
  }
  std::set<std::pair<int, int>> boundary, want;
  for (auto& [e, c] : directed)
    if (!directed.count({e.second, e.first})) boundary.insert(e);
  Dyadic hull_area2(0);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    auto a = hull[i], b = hull[(i + 1) % hull.size()];
    want.insert({static_cast<int>(a), static_cast<int>(b)});
    hull_area2 += geometry::orientation_value<Dyadic>(p[hull[0]], p[a], p[b]);
  }
  if (boundary != want) add(r, "the triangles' boundary is not the convex hull (" + std::to_string(boundary.size()) + " boundary edges, hull has " + std::to_string(want.size()) + ")");
  if (area2 != hull_area2) add(r, "the triangles' area differs from the hull's");
  std::vector<bool> used(n, false);
  for (auto& t : m.triangles) used[t[0]] = used[t[1]] = used[t[2]] = true;
  for (std::size_t i = 0; i < n; ++i)
    if (!used[i]) add(r, "vertex " + std::to_string(i) + " is in no triangle");
  return r;
}

CheckResult check_well_spaced(const Mesh& m) {
  CheckResult r{"L4.2.3", {}, 0};
  auto p = positions(m.spanner);
  if (p.size() < 2) return r;
  auto d = nn2(p);
  std::vector<double> worst(p.size(), 0);
  for (auto& t : m.triangles) {
    const Point2 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    Point2 bb = b - a, cc = c - a;
    Dyadic D = (bb[0] * cc[1] - bb[1] * cc[0]) * Dyadic(2);
    Dyadic nb = bb[0] * bb[0] + bb[1] * bb[1], nc = cc[0] * cc[0] + cc[1] * cc[1];
    Dyadic ux = cc[1] * nb - bb[1] * nc, uy = bb[0] * nc - cc[0] * nb;
    for (int v : t) {
      Point2 w = p[v] - a;
      Dyadic ex = w[0] * D - ux, ey = w[1] * D - uy;
      Dyadic lhs = (ex * ex + ey * ey) * Dyadic(4), rhs = d[v] * D * D * Dyadic(81);
      if (lhs > rhs) add(r, "vertex " + std::to_string(v) + " is not 9/2-well-spaced");
      double ratio = std::sqrt((ex * ex + ey * ey).to_double() / (d[v] * D * D).to_double());
      r.measured = std::max(r.measured, ratio);
    }
  }
  return r;
}

CheckResult check_size_conformity(const Mesh& m) {
  CheckResult r{"L4.2.8", {}, 0};
  auto p = positions(m.spanner);
  const std::size_t n = m.n();
  if (n < 2) return r;
  auto d = nn2(p);
  for (std::size_t v = 0; v < p.size(); ++v) {
    // lfs(v): distance to the second-nearest input point.
    double b1 = INFINITY, b2 = INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      double x = sqdist(p[v], p[i]).to_double();
      if (x < b1) b2 = b1, b1 = x;
      else if (x < b2) b2 = x;
    }
    r.measured = std::max(r.measured, std::sqrt(b2 / d[v].to_double()));
  }
  return r;
}

std::vector<CheckResult> check_all(const Mesh& m) {
  return {check_spanner(m.spanner),       check_ball_empty(m), check_independent_set(m), check_empty_balls(m),
          check_voronoi_candidates(m),    check_min_ranks(m),  check_delaunay(m),        check_well_spaced(m),
          check_size_conformity(m)};
}

}  // namespace kmr::kmesh
