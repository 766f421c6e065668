#pragma once
// §2.2 step 3(c), Appendix A's rip and tent.
//
// rip(p, f): starting from the visible face f, marks every face of the current hull visible from p
// (orientation > 0, strictly: a face whose plane contains p stays) with killer p, and returns the
// horizon: pairs (invisible neighbour g, edge e of the ripped face shared with g), e oriented as in
// the ripped face, sorted by (e.u, e.v) (Appendix A sorts the boundary by edge id for stability).
// Appendix A's ripFace/ripLoop recurse; this walks the same faces with an explicit stack (no stack
// overflow on large visible regions); the sorted horizon is the same.
//
// tent(p, horizon): one new face (p, e.u, e.v) per horizon edge, linked to g across e and to its
// two new neighbours across (p, e.u) and (p, e.v) through last_point/last_face (processEdgeVertex).
//
// Why strict visibility keeps the surface valid: a kept face g whose plane contains p meets the
// ripped region only along edges e where the ripped neighbour is strictly visible, so p lies
// strictly on the far side of e within g's plane and the tent face (p, e) is a non-degenerate
// triangle coplanar with g. The surface stays a closed triangulation of conv(A_{i+1}); its vertex
// set may include boundary points that are not extreme (polytope.hpp removes them on output).
#include <algorithm>
#include <utility>
#include <vector>

#include "exact/error.hpp"
#include "hull/hull_state.hpp"

namespace kmr::hull {

struct Border {
  int nbr;  // the invisible neighbour
  Edge e;   // the shared edge, oriented as in the ripped face
};

template <class Kernel>
std::vector<Border> rip(HullState& h, int p, int f, Kernel& k) {
  std::vector<Border> boundary;
  std::vector<int> stack{f};
  h.faces[f].killer = p;  // setFaceKiller
  while (!stack.empty()) {  // ripFace
    const int r = stack.back();
    stack.pop_back();
    for (int s = 0; s < 3; ++s) {  // ripLoop over the three neighbours
      const Face& face = h.faces[r];
      const int g = face.nbr[s];
      KMR_CHECK(g >= 0, "hull: a face without a neighbour (inconsistent predicates)");
      if (h.faces[g].killer >= 0) continue;  // ripped by p already
      const Face& gf = h.faces[g];
      if (k.orientation(gf.v[0], gf.v[1], gf.v[2], p) > 0) {
        h.faces[g].killer = p;
        stack.push_back(g);
      } else {
        boundary.push_back({g, {face.v[s], face.v[(s + 1) % 3]}});
      }
    }
  }
  std::sort(boundary.begin(), boundary.end(),
            [](const Border& a, const Border& b) { return std::pair(a.e.u, a.e.v) < std::pair(b.e.u, b.e.v); });
  return boundary;
}

inline void tent(HullState& h, int p, const std::vector<Border>& boundary) {
  auto process_edge_vertex = [&](int q, int f) {
    if (h.last_point[q] == p) {
      h.set_face_neighbor(f, p, q, h.last_face[q]);
    } else {
      h.last_point[q] = p;
      h.last_face[q] = f;
    }
  };
  h.first_face[p] = static_cast<int>(h.faces.size());
  h.face_count[p] = static_cast<int>(boundary.size());
  for (const Border& b : boundary) {  // createFace
    const int f = h.new_face(p, b.e.u, b.e.v);
    h.set_face_neighbor(f, b.e.u, b.e.v, b.nbr);
    process_edge_vertex(b.e.u, f);
    process_edge_vertex(b.e.v, f);
  }
}

}  // namespace kmr::hull
