#pragma once
// CGAL's convex_hull_3 (Exact_predicates_inexact_constructions_kernel) as an oracle for the static
// hull, and a polytope comparison that does not depend on how coplanar faces are triangulated.
#include <array>
#include <string>
#include <vector>

namespace kmr_oracle {

using Pt = std::array<double, 3>;
using Tri = std::array<int, 3>;

// Compares a triangulated hull (indices into pts) with CGAL's convex_hull_3 of pts:
//  * vertices == CGAL's hull vertices (named by lowest equal index), minus those lying in a closed
//    triangle of `facets` that they are not a vertex of (CGAL may keep such boundary points);
//  * the face planes agree: for every triangle of either surface, the set of input points on its
//    plane (CGAL::orientation, exact); the two sets of such sets are equal;
//  * per face plane, the projected areas (Epeck, exact) of `facets` sum to those of CGAL's
//    triangles: our triangulation covers each face exactly;
//  * every facet is outward: no input point lies strictly on its positive side.
// Returns "" or a description of the first difference.
std::string compare_with_cgal(const std::vector<Pt>& pts, const std::vector<int>& vertices,
                              const std::vector<Tri>& facets);

}  // namespace kmr_oracle
