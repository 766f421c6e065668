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
//  * Each judge reads points either as doubles (std::array<double, D>, the library's Point<D>; every
//    double is an exact dyadic) or as exact rationals (ExactPoint<D>, within the range of doubles: outputs with vertices finer
//    than a double, issue 11 §1, read from kmr's hex-float text by read_hex_float). Both give the
//    same verdict on the same values; the double filters are used only where they are sound.
//  * read_hex_float(s) is exactly the value of a C99 hex float ("%a" text, any number of digits).
#include <array>
#include <boost/multiprecision/gmp.hpp>
#include <cstddef>
#include <string>
#include <vector>

namespace kmr::wsjudge {

using Rational = boost::multiprecision::mpq_rational;
template <std::size_t D>
using ExactPoint = std::array<Rational, D>;

// The exact value of a hex float [+-]0x<hex>[.<hex>]p[+-]<dec> (kmr's output of a coordinate);
// throws std::invalid_argument naming the text otherwise.
Rational read_hex_float(const std::string& s);

template <std::size_t D>
bool is_well_spaced(const std::vector<std::array<double, D>>& M, double rho, std::string* why = nullptr);
template <std::size_t D>
bool is_size_conforming(const std::vector<std::array<double, D>>& N, const std::vector<std::array<double, D>>& M,
                        double rho, std::string* why = nullptr);
// Indices into M, sorted.
template <std::size_t D>
std::vector<std::size_t> clipped_voronoi_neighbors(const std::vector<std::array<double, D>>& M, std::size_t v, double beta);

// The same judges on exact points.
template <std::size_t D>
bool is_well_spaced(const std::vector<ExactPoint<D>>& M, double rho, std::string* why = nullptr);
template <std::size_t D>
bool is_size_conforming(const std::vector<std::array<double, D>>& N, const std::vector<ExactPoint<D>>& M, double rho,
                        std::string* why = nullptr);
template <std::size_t D>
std::vector<std::size_t> clipped_voronoi_neighbors(const std::vector<ExactPoint<D>>& M, std::size_t v, double beta);

}  // namespace kmr::wsjudge
