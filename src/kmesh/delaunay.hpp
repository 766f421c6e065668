#pragma once
// IdentifyVoronoiNeighbors (Fig. 4.2, third stage; Lemma 4.2.9) and the Delaunay triangulation of M,
// from scratch (the construction) or repaired locally (the update of Fig. 4.5, kmesh/update.hpp).
//
// M has many cocircular quadruples (satellites of one nucleus lie on one orbit), so "the" Delaunay
// triangulation is made unique by a symbolic perturbation of the lifting (spec/kmesh.md): vertex i is
// lifted by ε^(N−i), so among four cocircular vertices the one with the largest id lies outside the
// circle of the other three. The result is a Delaunay triangulation of M (every circumcircle is
// empty of vertices in its interior) and depends only on the ids, which are canonical. The update
// keeps its own ids, so it passes the canonical order of its vertices as a LiftOrder instead.
// Guarantees (tests/kmesh/construction_test.cpp, kds_test.cpp, oracles/kmesh):
//  * perturbed_side_of_circle(...) is never 0 for four distinct points with p, q, r not collinear,
//    equals the exact side_of_oriented_circle whenever that is not 0, and is antisymmetric;
//  * voronoi_star(S, s, ℓ) is the ccw ring of the neighbours of s in the perturbed Delaunay
//    triangulation of its candidates (the ℓ′-neighbours of s, ℓ′ = ℓ−6 … ℓ−3, within 9·2^(ℓ−2))
//    and s, starting from the nearest candidate (ties: the lower in the lift order); by Lemma 4.2.9
//    it is the star of s in the Delaunay triangulation of M, so it depends only on M and the order;
//  * triangles_from_stars finds each triangle from each of its three corners, or throws
//    ContractError (a broken Lemma 4.2.9 or a stale star); triangles are counter-clockwise in the
//    new ids, smallest id first, sorted;
//  * voronoi_stars(mesh) is every star of a constructed mesh (the construction keeps them in
//    Mesh::stars; the update repairs them locally).
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "kmesh/spanner.hpp"

namespace kmr::kmesh {

struct Mesh;

// sign of the perturbed in-circle test of t against the oriented circle (p, q, r); ids give ε order.
int perturbed_side_of_circle(const Point2& p, int ip, const Point2& q, int iq, const Point2& r, int ir,
                             const Point2& t, int it);

// The Voronoi neighbours of one vertex: its Delaunay star, counter-clockwise; `closed` when it goes
// all the way around (the vertex is not on the hull of M). An empty ring: no star (a dead vertex).
struct VoronoiStar {
  std::vector<int> ring;
  bool closed = false;
};
using VoronoiStars = std::vector<VoronoiStar>;  // by vertex id of the spanner

// lower(a, b): a is lifted less than b (a comes first in the canonical numbering). Empty: id order.
using LiftOrder = std::function<bool(int, int)>;

// IdentifyVoronoiNeighbors for the vertex s of rank ℓ (its activation or conversion rank) of S.
VoronoiStar voronoi_star(const Spanner& S, int s, Rank l, const LiftOrder& lower = {});

// The triangles of the stars (ids of the spanner), renumbered by new_id (identity when empty).
std::vector<std::array<int, 3>> triangles_from_stars(const VoronoiStars& stars, const std::vector<int>& new_id = {});

// The third stage of Fig. 4.2 over a constructed mesh: the star of every vertex.
VoronoiStars voronoi_stars(const Mesh& mesh);

}  // namespace kmr::kmesh
