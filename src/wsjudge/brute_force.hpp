#pragma once
// Exact brute-force judges of Chapter 3's outputs (no quadtree, no scan), for the tests, the CGAL
// oracle's cross-check and the audit. They share no code or arithmetic with src/wellspaced (this
// layer includes nothing of kmr): GMP rationals, their own dot products, their own halfspace
// algorithms — Seidel's incremental minimum-norm point for faces, and vertex enumeration by lines
// for cells — instead of the library's Polytope::clip / face_within.
// Guarantees (tests/wellspaced/wellspaced_test.cpp, oracles/wellspaced/ws_judge_test.cpp):
//  * is_well_spaced(M, ρ): exactly "Vor_M(v) ∩ [0,1]^D ⊆ closed ball(v, ρ·NN_M(v)) for all v".
//  * is_size_conforming(N, M, ρ): exactly "NN_M(v) ≥ lfs_N(v)/c, c = 2ρ/(ρ−1)" (Lemma 3.3.3).
//  * clipped_voronoi_neighbors(M, v, β): exactly the u with a point x on the face of Vor_M(M[v])
//    (unclipped by the domain) on the bisector of M[v], M[u] and |x − M[v]| ≤ β·NN_M(M[v]).
// Points are std::array<double, D> (the library's Point<D>); every double is an exact dyadic.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace kmr::wsjudge {

template <std::size_t D>
bool is_well_spaced(const std::vector<std::array<double, D>>& M, double rho, std::string* why = nullptr);
template <std::size_t D>
bool is_size_conforming(const std::vector<std::array<double, D>>& N, const std::vector<std::array<double, D>>& M,
                        double rho, std::string* why = nullptr);
// Indices into M, sorted.
template <std::size_t D>
std::vector<std::size_t> clipped_voronoi_neighbors(const std::vector<std::array<double, D>>& M, std::size_t v, double beta);

}  // namespace kmr::wsjudge
