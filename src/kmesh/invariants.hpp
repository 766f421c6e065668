#pragma once
// Brute-force checks of the invariants and lemmas of §4.1.2 and §4.2, written independently of the
// searches they check (no spanner pointer is used to find a vertex; every vertex is scanned).
// Each check returns its violations as readable strings (empty = holds) and the measured constant
// where the claim is a bound.
//  * spanner (S1–S4 of kmesh/spanner.hpp): separation, covering/parents, neighbours, pointers;
//  * L4.2.4  a satellite was converted iff its closed ball B(s, 2^(ℓ−2)) held no earlier vertex;
//  * L4.2.5  per rank, the converted satellites are a maximal independent subset of the proximity
//            graph (satellites with empty balls at the start of the rank, edges at distance ≤ 2^(ℓ−2));
//  * L4.2.6  no other vertex of M within 2^(ℓ−2) of a vertex of rank ℓ (activation or conversion);
//  * L4.2.9  both ends of every Delaunay edge are spanner neighbours at a rank ℓ−6 … ℓ−3 of one end;
//  * L4.2.10 λ_s ∈ [ℓ−6, ℓ−3] for every satellite converted at rank ℓ;
//  * delaunay: every triangle is ccw with no vertex strictly inside its circumcircle, and the
//    triangles form a disc whose boundary is the convex hull of M, with the hull's area;
//  * wellspaced: |v c| ≤ 9/2·NN(v) for every circumcenter c of a triangle at v (the domain of a hull
//    vertex is the convex hull of its Voronoi vertices and itself, spec/kmesh.md);
//  * size conformity (L4.2.8): max lfs(v)/NN_M(v) reported (lfs = distance to the second-nearest
//    input point), a measured constant;
//  * rigid boundary (L4.3.1): the triangulation's boundary is the 12 satellites of one nucleus at
//            the highest Steiner rank (no certificate watches its convexity; below);
//  * L4.3.3  at every rank ℓ, a closed ball of radius 2^(ℓ−3) centred at an active vertex holds at most
//            kActivePerBall active vertices (the packing bound of the lemma's proof, derived in
//            spec/kmesh.md); the largest count is reported.
#include <string>
#include <vector>

#include "kmesh/construction.hpp"

namespace kmr::kmesh {

struct CheckResult {
  std::string claim;
  std::vector<std::string> violations;
  double measured = 0;  // the measured constant, where the claim is a bound
  bool ok() const { return violations.empty(); }
};

CheckResult check_spanner(const Spanner& S);
CheckResult check_ball_empty(const Mesh& m);         // L4.2.4
CheckResult check_independent_set(const Mesh& m);    // L4.2.5
CheckResult check_empty_balls(const Mesh& m);        // L4.2.6
CheckResult check_voronoi_candidates(const Mesh& m); // L4.2.9
CheckResult check_min_ranks(const Mesh& m);          // L4.2.10
CheckResult check_delaunay(const Mesh& m);
CheckResult check_well_spaced(const Mesh& m);        // L4.2.3 / L4.2.7, measured max |vc|/NN(v)
CheckResult check_size_conformity(const Mesh& m);    // L4.2.8, measured max lfs/NN
// L4.3.3's constant for balls of radius 2^(ℓ−3): at most 1 vertex active by its activation rank ℓ
// (L4.2.6: pairwise > 2^(ℓ−2)) plus, per ray of rank ℓ−1, at most 5 nuclei of converted satellites
// (L4.2.6: pairwise > 2^(ℓ−3), and at most 5 points pairwise farther than r fit in a closed disc of
// radius r): 1 + 12·5.
inline constexpr std::size_t kActivePerBall = 61;
CheckResult check_active_per_ball(const Mesh& m);    // L4.3.3, measured max count
// L4.3.1's certificates watch every triangle's orientation and every interior edge, not the
// convexity of M's boundary. None is needed while the boundary is the 12 satellites of one nucleus
// at the highest rank of M: they move rigidly with their nucleus (a fixed convex 12-gon). A
// construction always has such a boundary, and Fig. 4.5 keeps it by re-deciding the whole top rank
// when it falls (Updater::recompute_highest; spec/kmesh.md). Checked, not assumed: in check_all and
// check_all_updated. A mesh without triangles passes.
CheckResult check_rigid_boundary(const Mesh& m);
std::vector<CheckResult> check_all(const Mesh& m);
// U1 of kmesh/update.hpp: the considered satellites are exactly the 12 per rank of the active
// vertices (ρ_v ≤ ℓ ≤ Λ+4, and ℓ = ρ_v or v has a converted (ℓ−1)-satellite).
CheckResult check_active_satellites(const Mesh& m);
// After a Fig. 4.5 update: check_all without L4.2.4 (which reads the construction's order), with U1;
// L4.2.5 then reads as L4.3.2 (a maximal independent subset per rank of the up-to-date graph).
std::vector<CheckResult> check_all_updated(const Mesh& m);

}  // namespace kmr::kmesh
