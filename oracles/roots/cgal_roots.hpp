#pragma once
// CGAL oracle for the real roots of integer polynomials (oracles only; never included under src/).
//
// Guarantees:
//  * oracle_real_roots(p, b) lists every distinct real root of p (p ≢ 0, integer coefficients of any
//    size) in increasing order with its exact multiplicity and the index k of the lattice interval
//    [kδ, (k+1)δ), δ = 2^−b, that holds it (a root exactly at kδ belongs to interval k). It is computed
//    with CGAL's Algebraic_kernel_d_1 over CORE::BigInt (exact real algebraic numbers), independently
//    of kmr::poly: the only shared code is kmr::exact::Integer, used for input and output.
//  * The lattice index is exact: an absolute approximation of width < δ narrows k to two candidates
//    and an exact comparison of the algebraic root with the rational kδ decides between them.
//  * lattice_intervals / first_sign_change derive from that list, by counting only, the answers the
//    library's LatticeRootSolver must give: the distinct roots per lattice interval, and whether the
//    sign changes across it (the multiplicities of its roots sum to an odd number).
//  * OracleRoot::on_lattice says whether the root equals kδ exactly (an exact comparison), and
//    first_failure_zero_fails adds Chapter 4's rule to first_sign_change: an interval that starts
//    at a root after the start also ends the search (LatticeRootSolver::next_failure_after's
//    zero_fails).
//  * The zero polynomial is refused with std::invalid_argument.
// This header is CGAL-free so that tests including it compile fast; CGAL lives in cgal_roots.cpp.
#include <optional>
#include <string>
#include <vector>

#include "exact/integer.hpp"

namespace kmr::oracles {

struct OracleRoot {
  exact::Integer k;  // the root lies in [kδ, (k+1)δ)
  int multiplicity = 0;
  bool on_lattice = false;  // the root is kδ exactly
};

struct OracleRoots {
  int distinct = 0;               // number of distinct real roots
  std::vector<OracleRoot> roots;  // increasing, one entry per distinct real root
};

// p(t) = c[0] + c[1]·t + ... ; lattice δ = 2^−lattice_bits.
OracleRoots oracle_real_roots(const std::vector<exact::Integer>& coefficients, int lattice_bits);
OracleRoots oracle_real_roots(const std::vector<std::string>& decimal_coefficients, int lattice_bits);

struct OracleInterval {
  exact::Integer k;
  int distinct = 0;        // distinct roots in [kδ, (k+1)δ)
  int multiplicity_sum = 0;
  bool starts_at_root = false;  // one of its roots is kδ
  bool sign_change() const { return multiplicity_sum % 2 == 1; }
};

// The nonempty lattice intervals with k_from ≤ k < k_to, in increasing k.
std::vector<OracleInterval> lattice_intervals(const OracleRoots& r, const exact::Integer& k_from,
                                              const exact::Integer& k_to);
// The first k in [k_from, k_to) whose interval's multiplicities sum to an odd number.
std::optional<exact::Integer> first_sign_change(const OracleRoots& r, const exact::Integer& k_from,
                                                const exact::Integer& k_to);
// The first k in [k_from, k_to) whose interval changes sign, or with k > k_from and a root at kδ.
std::optional<exact::Integer> first_failure_zero_fails(const OracleRoots& r, const exact::Integer& k_from,
                                                       const exact::Integer& k_to);

}  // namespace kmr::oracles
