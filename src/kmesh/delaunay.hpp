#pragma once
// IdentifyVoronoiNeighbors (Fig. 4.2, third stage; Lemma 4.2.9) and the Delaunay triangulation of M.
//
// M has many cocircular quadruples (satellites of one nucleus lie on one orbit), so "the" Delaunay
// triangulation is made unique by a symbolic perturbation of the lifting (spec/kmesh.md): vertex i is
// lifted by ε^(N−i), so among four cocircular vertices the one with the largest id lies outside the
// circle of the other three. The result is a Delaunay triangulation of M (every circumcircle is
// empty of vertices in its interior) and depends only on the ids, which are canonical.
// Guarantees (tests/kmesh/delaunay_test.cpp, oracles/kmesh):
//  * perturbed_side_of_circle(...) is never 0 for four distinct points with p, q, r not collinear,
//    equals the exact side_of_oriented_circle whenever that is not 0, and is antisymmetric;
//  * delaunay_star(s, cands) returns the neighbours of s in the perturbed Delaunay triangulation of
//    cands ∪ {s}, counter-clockwise, starting from the nearest candidate (ties: smaller id);
//  * delaunay_from_candidates(mesh) finds each triangle from each of its three corners, or throws
//    ContractError (a broken Lemma 4.2.9); triangles are counter-clockwise, smallest id first, sorted.
#include <array>
#include <vector>

#include "kmesh/satellites.hpp"

namespace kmr::kmesh {

struct Mesh;

// sign of the perturbed in-circle test of t against the oriented circle (p, q, r); ids give ε order.
int perturbed_side_of_circle(const Point2& p, int ip, const Point2& q, int iq, const Point2& r, int ir,
                             const Point2& t, int it);

// The ccw neighbours of s among cands (ids into pos) in the perturbed Delaunay triangulation.
// `closed` is set when the star goes all the way around s (s is not on the hull of cands ∪ {s}).
std::vector<int> delaunay_star(int s, const std::vector<int>& cands, const std::vector<Point2>& pos,
                               bool& closed, std::uint64_t& ops);

struct IPoint;
std::vector<int> delaunay_star(int s, const std::vector<int>& cands, const std::vector<Point2>& pos,
                               const std::vector<IPoint>& enclosures, bool& closed, std::uint64_t& ops);

// The third stage of Fig. 4.2 over a constructed mesh.
std::vector<std::array<int, 3>> delaunay_from_candidates(Mesh& mesh);

}  // namespace kmr::kmesh
