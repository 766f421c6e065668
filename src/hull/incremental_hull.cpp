// §2.2 steps 1–3, Appendix A's run/incrementalHull/insertVertex, and the output stage.
#include <algorithm>
#include <cmath>
#include <string>

#include "exact/error.hpp"
#include "hull/history.hpp"
#include "hull/hull.hpp"
#include "hull/initial_simplex.hpp"
#include "hull/kernel.hpp"
#include "hull/polytope.hpp"
#include "hull/priorities.hpp"
#include "hull/rip_and_tent.hpp"

namespace kmr::hull {
namespace {

// conv(A_4): the four faces of the tetrahedron a, b, c, d, each counter-clockwise from outside.
template <class Kernel>
void initial_hull(HullState& h, int a, int b, int c, int d, Kernel& k) {
  if (k.orientation(a, b, c, d) > 0) std::swap(b, c);  // now d lies below abc: abc faces outward
  h.root_faces = {h.new_face(a, b, c), h.new_face(a, d, b), h.new_face(b, d, c), h.new_face(c, d, a)};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Face &f = h.faces[i], &g = h.faces[j];
      int shared[2], m = 0;
      for (int u : f.v)
        if (std::count(g.v.begin(), g.v.end(), u)) shared[m++] = u;
      h.set_face_neighbor(i, shared[0], shared[1], j);
    }
}

template <class Kernel>
Hull run(const std::vector<Point3d>& pts, Kernel& k, std::uint64_t seed) {
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i)
    for (double x : pts[i])
      if (!std::isfinite(x)) throw InputError("point " + std::to_string(i) + " has a non-finite coordinate");
  const std::vector<int> order = priority_order(random_priorities(n, seed));
  const auto [a, b, c, d] = initial_simplex(order, k);
  k.set_centre(a, b, c, d);  // the centre point: centroid of conv(A_4)
  HullState h(n);
  initial_hull(h, a, b, c, d, k);

  Hull result;
  result.n = n;
  HullStats& st = result.stats;
  LocationCounts loc;
  st.points = static_cast<std::uint64_t>(n);
  st.inserted = 4;
  for (int x : order) {  // insertVertex, in priority order
    if (x == a || x == b || x == c || x == d) continue;
    const int f = find_associated_face(h, x, k, loc);
    if (f < 0) {
      ++st.discarded;
      st.duplicates += h.duplicate_of[x] >= 0;
      continue;
    }
    tent(h, x, rip(h, x, f, k));
    ++st.inserted;
  }

  // Output: the polytope's facets, each point named by the lowest index among its duplicates.
  std::vector<int> name(n);
  for (int i = 0; i < n; ++i) name[i] = i;
  for (int x = 0; x < n; ++x)
    if (int v = h.duplicate_of[x]; v >= 0) name[v] = std::min(name[v], x);
  for (Triangle t : polytope_facets(h, pts, k)) {
    for (int& v : t) v = name[v];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    result.facets.push_back(t);
    result.vertices.insert(result.vertices.end(), t.begin(), t.end());
  }
  std::sort(result.facets.begin(), result.facets.end());
  std::sort(result.vertices.begin(), result.vertices.end());
  result.vertices.erase(std::unique(result.vertices.begin(), result.vertices.end()), result.vertices.end());
  st.faces_created = h.faces.size();
  st.history_steps = loc.history_steps;
  st.orientation_tests = k.counts().orientation_tests;
  st.exact_fallbacks = k.counts().exact_fallbacks;
  return result;
}

}  // namespace

Hull convex_hull(const std::vector<Point3d>& points, Arithmetic arithmetic, std::uint64_t seed) {
  if (arithmetic == Arithmetic::exact) {
    ExactKernel k(points);
    return run(points, k, seed);
  }
  FloatKernel k(points);
  return run(points, k, seed);
}

}  // namespace kmr::hull
