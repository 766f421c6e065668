#pragma once
// Judges of the kinetic hull (C2.2-hull-correct): the hull of moving points just before a time t,
// i.e. at every time of (t − ε, t) for ε small enough (the §2.1 outcome rule; a dyadic time that
// close exists strictly inside the lattice interval ending at t).
//
// Guarantees:
//  * static_hull_before(points, t, seed) is the static algorithm of §2.2 (history.hpp and
//    rip_and_tent.hpp, the templates of `kmr hull`) run from scratch with exact predicates: the
//    sign just before t of each certificate polynomial. It shares no code with kinetic_hull.cpp.
//    Its facets are in `kmr hull`'s format. Identically zero predicates are an InputError.
//  * hull_certificate_failure(points, t, facets) is an independent check that needs no hull
//    algorithm: it returns "" iff the facets form a closed oriented surface (every directed edge
//    once, its reverse once) and every point that is not a vertex of a facet lies strictly inside
//    that facet's plane just before t. Just before t no four points are coplanar (identically
//    coplanar ones are refused), so these facets are then exactly the facets of the convex hull.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "exact/dyadic.hpp"
#include "hull/moving_points.hpp"

namespace kmr::hull {

// `present` (empty: all) restricts both to a subset of the points (integrated changes).
std::vector<std::array<int, 3>> static_hull_before(const std::vector<MovingPoint>& points, const exact::Dyadic& t,
                                                   std::uint64_t seed = 2012, const std::vector<bool>& present = {});

std::string hull_certificate_failure(const std::vector<MovingPoint>& points, const exact::Dyadic& t,
                                     const std::vector<std::array<int, 3>>& facets,
                                     const std::vector<bool>& present = {});

}  // namespace kmr::hull
