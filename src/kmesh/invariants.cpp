#include "kmesh/invariants.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "geometry/predicates.hpp"
#include "kmesh/filtered.hpp"

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

// Vertices sorted by x, for exact window scans: every vertex within k·2^l of s has |x − s.x| ≤ k·2^l.
struct XIndex {
  std::vector<std::pair<Dyadic, int>> v;
  explicit XIndex(const Spanner& S) {
    for (std::size_t i = 0; i < S.size(); ++i) v.push_back({S.position(static_cast<int>(i))[0], static_cast<int>(i)});
    std::sort(v.begin(), v.end());
  }
  // Calls f(id) for every vertex with |x − p.x| ≤ k·2^l, in x order.
  template <class F>
  void window(const Point2& p, std::int64_t k, Rank l, F f) const {
    Dyadic r(exact::Integer(k) * kScale, l);
    auto it = std::lower_bound(v.begin(), v.end(), std::pair<Dyadic, int>{p[0] - r, -1});
    Dyadic hi = p[0] + r;
    for (; it != v.end() && it->first <= hi; ++it) f(it->second);
  }
};

}  // namespace

CheckResult check_spanner(const Spanner& S) {
  CheckResult r{"spanner", {}, 0};
  const int n = static_cast<int>(S.size());
  // S1 and the expected number of (rank, neighbour) entries of every vertex, pair by pair.
  std::vector<std::size_t> expected(n, 0), stored(n, 0);
  for (int x = 0; x < n; ++x)
    for (int y = x + 1; y < n; ++y) {
      if (!S.alive(x) || !S.alive(y)) continue;  // removed vertices (spanner_repair) are in no list
      Rank mt = std::min(S.top(x), S.top(y));
      if (!within_filtered(S.position(x), S.enclosure(x), S.position(y), S.enclosure(y), kC, mt)) continue;
      if (S.position(x) == S.position(y)) {
        add(r, "S1: vertices " + std::to_string(x) + " and " + std::to_string(y) + " coincide");
        continue;
      }
      if (within_filtered(S.position(x), S.enclosure(x), S.position(y), S.enclosure(y), 1, mt))
        add(r, "S1 separation: " + std::to_string(x) + ", " + std::to_string(y) + " are both " +
                   std::to_string(mt) + "-centers within 2^" + std::to_string(mt));
      Rank l0 = lowest_neighbor_rank(S.position(x), S.position(y));
      expected[x] += static_cast<std::size_t>(mt - l0 + 1);
      expected[y] += static_cast<std::size_t>(mt - l0 + 1);
    }
  // S3: every stored entry is right (a center pair within c·2^l, no repeat); with the counts equal,
  // the lists are exactly the brute-force ones.
  for (int x = 0; x < n; ++x)
    for (auto& [l, list] : S.all_neighbors(x))
      for (std::size_t i = 0; i < list.size(); ++i) {
        int y = list[i];
        if ((i > 0 && list[i - 1] >= y) || y == x || y < 0 || y >= n || !S.alive(x) || !S.alive(y) || S.top(x) < l || S.top(y) < l ||
            !within(S.position(x), S.position(y), kC, l)) {
          add(r, "S3 neighbours: vertex " + std::to_string(x) + " lists " + std::to_string(y) + " wrongly at rank " + std::to_string(l));
          continue;
        }
        ++stored[x];
      }
  for (int x = 0; x < n; ++x)
    if (stored[x] != expected[x])
      add(r, "S3 neighbours: vertex " + std::to_string(x) + " lists " + std::to_string(stored[x]) + " (rank, neighbour) pairs, brute force finds " + std::to_string(expected[x]));
  // S2 covering and parents; S4 kids.
  std::map<std::pair<int, Rank>, std::vector<int>> kids;
  for (int x = 0; x < n; ++x) {
    if (!S.alive(x)) continue;
    if (x == S.root()) {
      if (S.top(x) != S.top_rank()) add(r, "root is not at the top rank");
      continue;
    }
    if (S.top(x) >= S.top_rank()) add(r, "S1: a second vertex at the top rank");
    Rank t = S.top(x) + 1;
    bool covered = false;
    for (int y = 0; y < n && !covered; ++y)
      if (y != x && S.alive(y) && S.top(y) >= t && within(S.position(x), S.position(y), 1, t)) covered = true;
    if (!covered) add(r, "S2 covering: no " + std::to_string(t) + "-center within 2^" + std::to_string(t) + " of " + std::to_string(x));
    int p = S.parent(x);
    if (p < 0 || p >= n || !S.alive(p) || S.top(p) < t || !within(S.position(x), S.position(p), 1, t))
      add(r, "S2 parent of " + std::to_string(x) + " is not a " + std::to_string(t) + "-center within 2^" + std::to_string(t));
    else
      kids[{p, S.top(x)}].push_back(x);
  }
  std::size_t listed = 0;
  for (int y = 0; y < n; ++y)
    for (auto& [l, k0] : S.all_kids(y)) {
      auto k = k0;
      std::sort(k.begin(), k.end());
      listed += k.size();
      if (!k.empty() && k != kids[{y, l}]) add(r, "S4 kids of " + std::to_string(y) + " at rank " + std::to_string(l));
    }
  const std::size_t live = S.alive_count();
  if (listed != live - 1) add(r, "S4: " + std::to_string(listed) + " kids listed for " + std::to_string(live - 1) + " non-root vertices");
  return r;
}

CheckResult check_ball_empty(const Mesh& m) {
  CheckResult r{"L4.2.4", {}, 0};
  const Spanner& S = m.spanner;
  XIndex X(S);
  for (auto& c : m.considered) {
    Point2 s = satellite_position(S.position(c.nucleus), c.ray, c.rank);
    bool empty = true;
    X.window(s, 1, c.rank - 2, [&](int x) {
      if (x < c.existing && within(s, S.position(x), 1, c.rank - 2)) empty = false;
    });
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
  XIndex X(S);
  std::map<Rank, std::vector<const Considered*>> by_rank;
  for (auto& c : m.considered) by_rank[c.rank].push_back(&c);
  for (auto& [l, cs] : by_rank) {
    int start = cs.front()->existing;  // vertices before the rank's first conversion (the smallest)
    for (auto* c : cs) start = std::min(start, c->existing);
    std::vector<Point2> pos;
    std::vector<bool> conv;
    for (auto* c : cs) {
      Point2 s = satellite_position(S.position(c->nucleus), c->ray, c->rank);
      bool empty = true;
      X.window(s, 1, l - 2, [&](int x) {
        if (x < start && within(s, S.position(x), 1, l - 2)) empty = false;
      });
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
      Rank mt = std::min(S.top(s), S.top(x));
      if (!within_filtered(S.position(s), S.enclosure(s), S.position(x), S.enclosure(x), kC, mt)) continue;
      lam = std::min(lam, lowest_neighbor_rank(S.position(s), S.position(x)));
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
        if (side_of_circle_filtered(a, m.spanner.enclosure(t[0]), b, m.spanner.enclosure(t[1]), c,
                                    m.spanner.enclosure(t[2]), q, m.spanner.enclosure(ord[j])) > 0) {
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

CheckResult check_active_per_ball(const Mesh& m) {
  CheckResult r{"L4.3.3", {}, 0};
  // The vertices active at each rank: the nuclei of the satellites considered there (U1).
  std::map<Rank, std::vector<std::pair<Dyadic, int>>> active;  // rank → (x, nucleus)
  for (auto& c : m.considered) active[c.rank].push_back({m.spanner.position(c.nucleus)[0], c.nucleus});
  for (auto& [l, at] : active) {
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    const Dyadic radius(exact::Integer(kScale), l - 3);
    for (auto& [x, v] : at) {
      const Point2& c = m.spanner.position(v);
      std::size_t count = 0;  // active vertices u with |uc| ≤ 2^(ℓ−3), scanned by x window
      auto it = std::lower_bound(at.begin(), at.end(), std::pair<Dyadic, int>{x - radius, -1});
      for (; it != at.end() && it->first <= x + radius; ++it) count += within_exact(m.spanner.position(it->second), c, 1, l - 3);
      r.measured = std::max(r.measured, double(count));
      if (count > kActivePerBall)
        add(r, std::to_string(count) + " vertices active at rank " + std::to_string(l) + " within 2^(rank-3) of vertex " +
                   std::to_string(v) + " (bound " + std::to_string(kActivePerBall) + ")");
    }
  }
  return r;
}

CheckResult check_rigid_boundary(const Mesh& m) {
  CheckResult r{"L4.3.1 (rigid boundary)", {}, 0};
  if (m.triangles.empty()) return r;
  std::set<std::pair<int, int>> directed;
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) directed.insert({t[i], t[(i + 1) % 3]});
  std::set<int> boundary;
  for (auto& e : directed)
    if (!directed.count({e.second, e.first})) boundary.insert(e.first);
  bool any = false;
  Rank top = 0;  // the highest rank of a Steiner vertex
  for (auto& in : m.info)
    if (in.steiner) top = any ? std::max(top, in.rank) : in.rank, any = true;
  std::map<int, int> count;  // boundary vertices per nucleus: the most frequent one is the reference
  for (int v : boundary) ++count[m.info[static_cast<std::size_t>(v)].nucleus];
  int nucleus = count.begin()->first;
  for (auto& [x, c] : count)
    if (c > count[nucleus]) nucleus = x;
  std::string want = "the 12 satellites of rank " + std::to_string(top) + " of one nucleus";
  if (boundary.size() != 12) add(r, "the boundary has " + std::to_string(boundary.size()) + " vertices, not " + want);
  for (int v : boundary) {
    const VertexInfo& in = m.info[static_cast<std::size_t>(v)];
    if (!in.steiner || in.rank != top || in.nucleus != nucleus)
      add(r, "boundary vertex " + std::to_string(v) + (in.steiner ? " (rank " + std::to_string(in.rank) + ", nucleus " + std::to_string(in.nucleus) + ")" : " (an input vertex)") +
                 " is not one of " + want + " " + std::to_string(nucleus) + ": no certificate watches the boundary's convexity");
  }
  return r;
}

std::vector<CheckResult> check_all(const Mesh& m) {
  return {check_spanner(m.spanner),       check_ball_empty(m), check_independent_set(m), check_empty_balls(m),
          check_voronoi_candidates(m),    check_min_ranks(m),  check_delaunay(m),        check_well_spaced(m),
          check_size_conformity(m),       check_active_per_ball(m), check_rigid_boundary(m)};
}

CheckResult check_active_satellites(const Mesh& m) {
  CheckResult r{"U1", {}, 0};
  std::map<std::pair<int, Rank>, int> count, conv;
  for (auto& c : m.considered) {
    ++count[{c.nucleus, c.rank}];
    conv[{c.nucleus, c.rank}] += c.converted;
  }
  std::size_t expected_total = 0;
  for (int v = 0; v < static_cast<int>(m.n()) && m.n() >= 2; ++v) {
    Rank rho = m.info[v].rank;
    for (Rank l = rho; l <= m.highest; ++l) {
      bool act = l == rho || conv[{v, l - 1}] > 0;
      if (!act) break;
      expected_total += 12;
      if (count[{v, l}] != 12)
        add(r, "vertex " + std::to_string(v) + " active at rank " + std::to_string(l) + " has " +
                   std::to_string(count[{v, l}]) + " satellites considered");
    }
  }
  if (m.considered.size() != expected_total)
    add(r, std::to_string(m.considered.size()) + " satellites considered, " + std::to_string(expected_total) +
               " belong to active vertices");
  return r;
}

std::vector<CheckResult> check_all_updated(const Mesh& m) {
  return {check_spanner(m.spanner),    check_active_satellites(m), check_independent_set(m), check_empty_balls(m),
          check_voronoi_candidates(m), check_min_ranks(m),         check_delaunay(m),        check_well_spaced(m),
          check_size_conformity(m),    check_active_per_ball(m),   check_rigid_boundary(m)};
}

}  // namespace kmr::kmesh
