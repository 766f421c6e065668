#pragma once
// Chapter 4 oracle (CGAL, exact kernel Epeck; the CGAL code is in kmesh_oracle_cgal.cpp only).
// judge_mesh(M, n, triangles) checks, sharing no code with src/kmesh:
//  * Delaunay: every given triangle is ccw and its circumcircle has no vertex of M strictly inside
//    (CGAL's nearest_vertex of the circumcenter is not closer than the circumradius); the number of
//    triangles equals CGAL's number of finite faces (the same for every triangulation of M); every
//    CGAL face whose three neighbours' apexes are strictly outside its circle (a face every Delaunay
//    triangulation has) is among the given triangles, and the given triangles are distinct. Without
//    cocircular quadruples this is equality with CGAL's Delaunay triangulation.
//  * 9/2-well-spacedness (L4.2.3, L4.2.7): for every vertex v, |v c| ≤ 9/2·NN_M(v) for every Voronoi
//    vertex c of v (the circumcenters of CGAL's finite faces at v); for a hull vertex its domain is
//    the convex hull of its Voronoi vertices and itself (spec/kmesh.md). Measured: max |vc|/NN(v).
//  * size conformity (L4.2.8): measured max lfs(v)/NN_M(v), lfs(v) = distance from v to its second
//    nearest input point (the first n points of M are the input).
#include <array>
#include <string>
#include <vector>

#include "exact/dyadic.hpp"

namespace kmr::oracle::kmesh {

struct Report {
  std::vector<std::string> violations;
  double max_well_spaced = 0;   // max over v and its Voronoi vertices c of |vc| / NN(v)
  double max_size_ratio = 0;    // max lfs(v) / NN_M(v)
  std::size_t cgal_faces = 0;
  bool ok() const { return violations.empty(); }
};

Report judge_mesh(const std::vector<std::array<exact::Dyadic, 2>>& M, std::size_t n_input,
                  const std::vector<std::array<int, 3>>& triangles);

}  // namespace kmr::oracle::kmesh
