#pragma once
// The output stage: from the alive faces of the incremental surface to the polytope's facets.
//
// Adjacent alive faces in one plane (exact coplanarity) form a group: a face of the polytope. The
// boundary of a group of several triangles is walked as a cycle; a cycle vertex collinear with its
// two neighbours lies in the relative interior of an edge and is dropped, as are vertices interior
// to the group; what is left is the face's convex polygon, triangulated as a fan from its
// lexicographically smallest point. Single-triangle groups are kept as they are.
// Guarantees: every vertex of the result is an extreme point (a corner of each face polygon it
// lies on); the triangles cover each face exactly once; orientations are preserved.
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "exact/error.hpp"
#include "hull/hull_state.hpp"

namespace kmr::hull {

using Triangle = std::array<int, 3>;

template <class Kernel, class Points>
std::vector<Triangle> polytope_facets(const HullState& h, const Points& pts, Kernel& k) {
  const int m = static_cast<int>(h.faces.size());
  std::vector<int> group(m, -1);
  std::vector<Triangle> out;
  std::vector<int> members;
  auto third = [](const Face& g, int a, int b) {
    for (int v : g.v)
      if (v != a && v != b) return v;
    throw ContractError("hull: degenerate face");
  };
  for (int f0 = 0; f0 < m; ++f0) {
    if (h.faces[f0].killer >= 0 || group[f0] >= 0) continue;
    members.assign(1, f0);
    group[f0] = f0;
    const Face& base = h.faces[f0];
    for (std::size_t i = 0; i < members.size(); ++i) {
      const Face& f = h.faces[members[i]];
      for (int s = 0; s < 3; ++s) {
        int g = f.nbr[s];
        KMR_CHECK(g >= 0 && h.faces[g].killer < 0, "hull: alive face with a dead or missing neighbour");
        if (group[g] >= 0) continue;
        int w = third(h.faces[g], f.v[s], f.v[(s + 1) % 3]);
        if (k.orientation(base.v[0], base.v[1], base.v[2], w) == 0) {
          group[g] = f0;
          members.push_back(g);
        }
      }
    }
    if (members.size() == 1) {
      out.push_back(base.v);
      continue;
    }
    // Boundary edges of the group, oriented as in its faces; walk them as one cycle.
    std::vector<std::pair<int, int>> next;  // (from, to)
    for (int fi : members) {
      const Face& f = h.faces[fi];
      for (int s = 0; s < 3; ++s)
        if (group[f.nbr[s]] != f0) next.emplace_back(f.v[s], f.v[(s + 1) % 3]);
    }
    std::sort(next.begin(), next.end());
    auto successor = [&](int a) {
      auto it = std::lower_bound(next.begin(), next.end(), std::pair(a, -1));
      KMR_CHECK(it != next.end() && it->first == a && (it + 1 == next.end() || (it + 1)->first != a),
                "hull: the boundary of a coplanar face is not a simple cycle");
      return it->second;
    };
    std::vector<int> cycle{next.front().first};
    for (int v = successor(cycle[0]); v != cycle[0]; v = successor(v)) {
      cycle.push_back(v);
      KMR_CHECK(cycle.size() <= next.size(), "hull: the boundary of a coplanar face does not close");
    }
    KMR_CHECK(cycle.size() == next.size(), "hull: a coplanar face has more than one boundary cycle");
    std::vector<int> corners;
    const std::size_t c = cycle.size();
    for (std::size_t i = 0; i < c; ++i)
      if (!k.collinear(cycle[(i + c - 1) % c], cycle[i], cycle[(i + 1) % c])) corners.push_back(cycle[i]);
    KMR_CHECK(corners.size() >= 3, "hull: a face polygon with fewer than three corners");
    std::size_t lo = 0;
    for (std::size_t i = 1; i < corners.size(); ++i)
      if (pts[corners[i]] < pts[corners[lo]]) lo = i;
    std::rotate(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(lo), corners.end());
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
  }
  return out;
}

}  // namespace kmr::hull
