#pragma once
// The static randomized incremental 3D convex hull of §2.2 (Appendix A's MkIHull3DAdaptive run as
// a static program), exact or in plain doubles.
//
// Guarantees (Arithmetic::exact; tests in tests/hull, proptests/hull, oracles/hull, fuzz):
//  * vertices are exactly the extreme points of the input, each named by the lowest index among
//    equal input points, increasing; a point in the relative interior of a face or an edge is
//    never a vertex.
//  * facets triangulate the boundary of the hull: each facet is counter-clockwise seen from outside
//    (outward normal by the right-hand rule), uses only vertices, is rotated so its smallest index
//    comes first, and the list is sorted. A polygonal face with more than three vertices is
//    triangulated as a fan from its lexicographically smallest point (x, then y, then z), so the
//    output depends only on the point set (not on the seed or the input order, up to renaming).
//  * fewer than four affinely independent points: InputError.
//  * deterministic: a pure function of (points, seed).
// Arithmetic::floating answers the same questions in plain doubles: not robust (wrong or failed
// answers on near-degenerate input, a ContractError on an inconsistent surface); the Fig. 2.4
// baseline only.
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/filtered_orientation.hpp"

namespace kmr::hull {

using Point3d = geometry::Point3d;

enum class Arithmetic { exact, floating };

inline constexpr std::uint64_t kDefaultSeed = 2012;

struct HullStats {
  std::uint64_t points = 0;
  std::uint64_t inserted = 0;    // points that changed the hull (the four initial ones included)
  std::uint64_t discarded = 0;   // points found inside or on the current hull
  std::uint64_t duplicates = 0;  // discarded points equal to a surface vertex
  std::uint64_t faces_created = 0;
  std::uint64_t history_steps = 0;
  std::uint64_t orientation_tests = 0;
  std::uint64_t exact_fallbacks = 0;
};

struct Hull {
  int n = 0;
  std::vector<int> vertices;
  std::vector<std::array<int, 3>> facets;
  HullStats stats;
};

Hull convex_hull(const std::vector<Point3d>& points, Arithmetic arithmetic = Arithmetic::exact,
                 std::uint64_t seed = kDefaultSeed);

}  // namespace kmr::hull
