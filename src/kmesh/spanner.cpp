#include "kmesh/spanner.hpp"

#include <algorithm>
#include <cmath>

#include "exact/error.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/filtered.hpp"

namespace kmr::kmesh {
namespace {

const std::vector<int> kEmpty;

Dyadic sqdist(const Point2& p, const Point2& q) { return geometry::squared_distance<2, Dyadic>(p, q); }

void sorted_insert(std::vector<int>& v, int x) {
  auto it = std::lower_bound(v.begin(), v.end(), x);
  if (it == v.end() || *it != x) v.insert(it, x);
}

}  // namespace

Dyadic threshold2(std::int64_t k, Rank l) {
  exact::Integer kl = exact::Integer(k) * kScale;
  return Dyadic(kl * kl, 2 * l);
}

bool within_exact(const Point2& p, const Point2& q, std::int64_t k, Rank l) {
  return sqdist(p, q) <= threshold2(k, l);
}

bool within(const Point2& p, const Point2& q, std::int64_t k, Rank l) {
  return within_filtered(p, enclose(p), q, enclose(q), k, l);
}

Rank min_rank_within(const Point2& p, const Point2& q, std::int64_t k) {
  KMR_CHECK(p != q, "min_rank_within of equal points");
  // A starting guess from doubles (only a guess: the loops below decide exactly).
  double dx = p[0].to_double() - q[0].to_double(), dy = p[1].to_double() - q[1].to_double();
  double g = 0.5 * std::log2(dx * dx + dy * dy) - std::log2(double(k) * double(kScale));
  Rank l;
  if (std::isfinite(g) && std::abs(g) < 1e6) {
    l = static_cast<Rank>(std::ceil(g));
  } else {
    Dyadic d2 = sqdist(p, q);
    std::int64_t lg = exact::bit_length(d2.mantissa()) + d2.exponent();
    std::int64_t lk = exact::bit_length(exact::Integer(k) * k * kScale * kScale);
    l = (lg - lk) / 2 - 2;
  }
  while (!within(p, q, k, l)) ++l;
  while (within(p, q, k, l - 1)) --l;
  return l;
}

const std::vector<int>& Spanner::neighbors(int x, Rank l) const {
  auto it = nodes_[x].nbrs.find(l);
  return it == nodes_[x].nbrs.end() ? kEmpty : it->second;
}

const std::vector<int>& Spanner::kids(int y, Rank l) const {
  auto it = nodes_[y].kids.find(l);
  return it == nodes_[y].kids.end() ? kEmpty : it->second;
}

Rank Spanner::min_rank(int x) const {
  for (auto& [r, v] : nodes_[x].nbrs)
    if (!v.empty()) return r;
  return nodes_[x].top + 1;
}

int Spanner::rep(int x, Rank l) const {
  while (nodes_[x].top < l) {
    KMR_CHECK(nodes_[x].parent >= 0, "rep: walk through a vertex without a parent");
    x = nodes_[x].parent;
  }
  return x;
}

void Spanner::add_kid(int y, Rank l, int x) { nodes_[y].kids[l].push_back(x); }

void Spanner::remove_kid(int y, Rank l, int x) {
  auto& v = nodes_[y].kids[l];
  auto it = std::find(v.begin(), v.end(), x);
  KMR_CHECK(it != v.end(), "remove_kid: not a kid");
  v.erase(it);
}

void Spanner::add_neighbor_pair(int x, int y, Rank l) {
  touched.push_back(x);
  touched.push_back(y);
  sorted_insert(nodes_[x].nbrs[l], y);
  sorted_insert(nodes_[y].nbrs[l], x);
}

std::vector<int> Spanner::centers_near_below(const Point2& p, Rank l, const std::vector<int>& above) const {
  std::vector<int> out;
  IPoint pe = enclose(p);
  auto consider = [&](int y) {
    ++ops;
    if (within_filtered(p, pe, nodes_[y].p, nodes_[y].e, kC, l)) out.push_back(y);
  };
  for (int z : above) {
    consider(z);
    for (int y : kids(z, l)) consider(y);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> Spanner::centers_near(const Point2& p, Rank l, int hint) const {
  KMR_CHECK(nodes_[hint].top >= l + 1, "centers_near: hint is not an (l+1)-center");
  KMR_CHECK(within_filtered(p, enclose(p), nodes_[hint].p, nodes_[hint].e, 15, l), "centers_near: hint is farther than 15·2^l");
  std::vector<int> family = neighbors(hint, l + 1);
  family.push_back(hint);
  return centers_near_below(p, l, family);
}

Spanner Spanner::build(const std::vector<Point2>& pts, Rank extra_top) {
  Spanner s;
  const int n = static_cast<int>(pts.size());
  KMR_CHECK(n >= 1, "Spanner::build of no points");
  s.nodes_.resize(n);
  s.alive_count_ = static_cast<std::size_t>(n);
  for (int i = 0; i < n; ++i) s.nodes_[i].p = pts[i], s.nodes_[i].e = enclose(pts[i]);
  Rank big = 0;
  for (int w = 1; w < n; ++w) big = (w == 1) ? min_rank_within(pts[0], pts[w], 1)
                                             : std::max(big, min_rank_within(pts[0], pts[w], 1));
  s.lambda_ = big;
  s.top_rank_ = big + extra_top;
  s.nodes_[0].top = s.top_rank_;
  if (n == 1) return s;
  std::vector<int> remaining, anchor(n, 0), centers{0};
  for (int w = 1; w < n; ++w) remaining.push_back(w);
  for (Rank l = big - 1;; --l) {
    // Greedy discretization at rank l (§4.1.2): w joins M_l unless an l-center is 2^l close.
    std::vector<int> still;
    for (int w : remaining) {
      int a = anchor[w], best = -1;
      std::vector<int> family = s.neighbors(a, l + 1);
      family.push_back(a);
      for (int z : family) {
        auto look = [&](int x) {
          ++s.ops;
          if (!within_filtered(pts[w], s.nodes_[w].e, pts[x], s.nodes_[x].e, 1, l)) return;
          int c = best < 0 ? -1 : compare_distance(pts[w], s.nodes_[w].e, pts[x], s.nodes_[x].e, pts[best], s.nodes_[best].e);
          if (best < 0 || c < 0 || (c == 0 && x < best)) best = x;
        };
        look(z);
        for (int x : s.kids(z, l)) look(x);
      }
      if (best >= 0) {
        anchor[w] = best;
        still.push_back(w);
      } else {
        s.nodes_[w].top = l;
        s.nodes_[w].parent = a;
        s.add_kid(a, l, w);
        centers.push_back(w);
      }
    }
    remaining = std::move(still);
    std::sort(centers.begin(), centers.end());
    // Neighbour edges at rank l, found among cousins.
    bool any = false;
    for (int x : centers) {
      int r = s.rep(x, l + 1);
      std::vector<int> family = s.neighbors(r, l + 1);
      family.push_back(r);
      for (int z : family) {
        auto look = [&](int y) {
          ++s.ops;
          if (y > x && within_filtered(pts[x], s.nodes_[x].e, pts[y], s.nodes_[y].e, kC, l)) s.add_neighbor_pair(x, y, l), any = true;
        };
        look(z);
        for (int y : s.kids(z, l)) look(y);
      }
    }
    if (remaining.empty() && !any) break;
  }
  return s;
}

int Spanner::insert(const Point2& p, Rank top, const std::map<Rank, std::vector<int>>& nbrs, int parent,
                    int proxy) {
  int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node{p, enclose(p), top, parent, {}, {}});
  ++alive_count_;
  for (auto& [r, list] : nbrs) {
    KMR_CHECK(r <= top, "insert: neighbours above the top rank");
    for (int y : list) add_neighbor_pair(id, y, r);
  }
  add_kid(parent >= 0 ? parent : proxy, top, id);
  return id;
}

void Spanner::set_parent(int x, int parent, int proxy) {
  KMR_CHECK(nodes_[x].parent < 0, "set_parent: already has a parent");
  remove_kid(proxy, nodes_[x].top, x);
  nodes_[x].parent = parent;
  add_kid(parent, nodes_[x].top, x);
}

void Spanner::promote(int x, const std::vector<int>& nbrs, int parent, int proxy, int old_proxy) {
  KMR_CHECK(nodes_[x].parent < 0, "promote: vertex has a parent");
  remove_kid(old_proxy, nodes_[x].top, x);
  Rank l = ++nodes_[x].top;
  for (int y : nbrs) add_neighbor_pair(x, y, l);
  nodes_[x].parent = parent;
  add_kid(parent >= 0 ? parent : proxy, l, x);
}

void Spanner::move_to(const std::vector<Point2>& positions) {
  KMR_CHECK(positions.size() == nodes_.size(), "move_to: wrong number of positions");
  for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i].p = positions[i], nodes_[i].e = enclose(positions[i]);
}

}  // namespace kmr::kmesh
