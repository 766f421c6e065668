#include "hull/hull_at_time.hpp"

#include <algorithm>
#include <map>

#include "exact/error.hpp"
#include "hull/history.hpp"
#include "hull/priorities.hpp"
#include "hull/rip_and_tent.hpp"
#include "poly/polynomial.hpp"

namespace kmr::hull {
namespace {

// The static kernel interface of history.hpp / rip_and_tent.hpp over trajectories: each answer is
// the sign of the certificate polynomial just before t (never 0 unless identically zero: refused).
class TrajectoryKernel {
 public:
  TrajectoryKernel(const std::vector<MovingPoint>& pts, const exact::Dyadic& t) : pts_(pts), t_(t) {}
  int orientation(int p, int q, int r, int s) {
    return sign(orientation_polynomial(pts_[p], pts_[q], pts_[r], pts_[s]), "points", p, q, r, s);
  }
  bool equal(int, int) const { return false; }  // distinct trajectories differ just before any t
  void set_centre(int a, int b, int c, int d) { sum_ = trajectory_sum(pts_[a], pts_[b], pts_[c], pts_[d]); }
  int centre_side(int u, int v, int x) {
    return sign(centre_side_polynomial(pts_[u], pts_[v], pts_[x], sum_), "points and the centre", u, v, x, -1);
  }
  struct ApexFrame {
    TrajectoryKernel& k;
    int apex, x;
    int side_before(int w) { return k.centre_side(w, apex, x); }
    int side_after(int v) { return k.centre_side(apex, v, x); }
  };
  ApexFrame apex_frame(int apex, int x) { return ApexFrame{*this, apex, x}; }

 private:
  int sign(const poly::Polynomial& p, const char* what, int a, int b, int c, int d) {
    if (p.is_zero())
      throw InputError(std::string(what) + " " + std::to_string(a) + ", " + std::to_string(b) + ", " +
                       std::to_string(c) + (d >= 0 ? ", " + std::to_string(d) : std::string()) +
                       " stay coplanar for all time: an identically zero certificate");
    return poly::sign_before(p, t_);
  }
  const std::vector<MovingPoint>& pts_;
  exact::Dyadic t_;
  MovingPoint sum_;
};

}  // namespace

std::vector<std::array<int, 3>> static_hull_before(const std::vector<MovingPoint>& pts, const exact::Dyadic& t,
                                                   std::uint64_t seed, const std::vector<bool>& present) {
  refuse_identical_trajectories(pts);
  const int n = static_cast<int>(pts.size());
  std::vector<int> order;
  for (int x : priority_order(random_priorities(n, seed)))
    if (present.empty() || present[x]) order.push_back(x);
  const auto [a, b0, c0, d] = initial_simplex_of(pts, order);
  int b = b0, c = c0;
  TrajectoryKernel k(pts, t);
  k.set_centre(a, b, c, d);
  HullState h(n);
  if (k.orientation(a, b, c, d) > 0) std::swap(b, c);
  h.root_faces = {h.new_face(a, b, c), h.new_face(a, d, b), h.new_face(b, d, c), h.new_face(c, d, a)};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Face &f = h.faces[i], &g = h.faces[j];
      int shared[2], m = 0;
      for (int u : f.v)
        if (std::count(g.v.begin(), g.v.end(), u)) shared[m++] = u;
      h.set_face_neighbor(i, shared[0], shared[1], j);
    }
  LocationCounts loc;
  for (int x : order) {
    if (x == a || x == b || x == c || x == d) continue;
    const int f = find_associated_face(h, x, k, loc);
    if (f >= 0) tent(h, x, rip(h, x, f, k));
  }
  std::vector<std::array<int, 3>> out;
  for (const Face& f : h.faces) {
    if (f.killer >= 0) continue;
    std::array<int, 3> v = f.v;
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string hull_certificate_failure(const std::vector<MovingPoint>& pts, const exact::Dyadic& t,
                                     const std::vector<std::array<int, 3>>& facets, const std::vector<bool>& present) {
  auto name = [](const std::array<int, 3>& f) {
    return "(" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + ")";
  };
  if (facets.size() < 4) return "fewer than four facets";
  std::map<std::pair<int, int>, int> edges;  // directed edge → count
  for (const auto& f : facets)
    for (int s = 0; s < 3; ++s) ++edges[{f[s], f[(s + 1) % 3]}];
  for (const auto& [e, count] : edges) {
    if (count != 1) return "directed edge " + std::to_string(e.first) + "→" + std::to_string(e.second) + " used twice";
    if (!edges.count({e.second, e.first}))
      return "edge " + std::to_string(e.first) + "–" + std::to_string(e.second) + " has no facet on its other side";
  }
  const int n = static_cast<int>(pts.size());
  for (const auto& f : facets)
    for (int x = 0; x < n; ++x) {
      if (x == f[0] || x == f[1] || x == f[2] || (!present.empty() && !present[x])) continue;
      const poly::Polynomial p = orientation_polynomial(pts[f[0]], pts[f[1]], pts[f[2]], pts[x]);
      if (p.is_zero()) return "point " + std::to_string(x) + " stays on the plane of facet " + name(f);
      if (poly::sign_before(p, t) > 0) return "point " + std::to_string(x) + " lies outside facet " + name(f);
    }
  return "";
}

}  // namespace kmr::hull
