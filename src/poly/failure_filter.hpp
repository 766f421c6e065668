#pragma once
// A double-precision filter for the next failure interval of a certificate of any degree (issue 8
// §3 for degree ≥ 2: the kinetic hull's orient3d cubics), in front of the exact Sturm path.
//
// Guarantees (tests/poly/failure_filter_test.cpp):
//  * filtered_next_failure(p, approx, bits, a, b) either answers nothing (undecided) or answers
//    exactly what LatticeRootSolver(p, bits).next_failure_after(a·δ, b·δ) answers: the first lattice
//    interval k in [a, b) with sign_before((k+1)δ) ≠ sign_before(kδ), or none.
//  * Proof: lattice index ranges [a, b] are subdivided left to right. A range whose enclosure of
//    p (interval Horner, every operation rounded outward by one ulp, coefficients widened by one ulp
//    for mpz_get_d's truncation) excludes 0 holds no root, hence no failure. A range whose enclosure
//    of p' excludes 0 is one where p is strictly monotone: sign_before is then a monotone step
//    function of the lattice points (sign p, or −sign p' at a root), so the range holds a failure
//    iff its ends differ, found by bisection on exact signs at lattice points (a double evaluation
//    with the rigorous bound of filtered_sign_at, else exact). A single lattice interval that
//    neither test decides (a double root, roots closer than δ, or a bound too wide) makes the
//    whole query undecided: the caller runs the exact path.
//  * No GMP number is created unless a lattice sign falls back to exact arithmetic.
//  * The MachinePolynomial overloads decide exactly as the Polynomial ones on p.to_polynomial().
#include <cstdint>
#include <optional>

#include "poly/machine_polynomial.hpp"
#include "poly/polynomial.hpp"

namespace kmr::poly {

struct FailureFilterResult {
  bool decided = false;
  std::optional<std::int64_t> failure;  // when decided: the first failure interval in [a, b), if any
};

// p ≢ 0, approx = double_coefficients(p), 0 ≤ bits ≤ 62, |a|, |b| < 2^62 (lattice indices): checked,
// ContractError otherwise (approx: its size only). a ≥ b answers decided, no failure.
FailureFilterResult filtered_next_failure(const Polynomial& p, const DoubleCoefficients& approx, int bits,
                                          std::int64_t a, std::int64_t b);

// The same filter for a machine polynomial (its coefficients rounded to nearest); the exact sign
// fallback converts it to a Polynomial. Answers what filtered_next_failure(p.to_polynomial(), …)
// would be allowed to answer: nothing, or LatticeRootSolver's answer.
FailureFilterResult filtered_next_failure(const MachinePolynomial& p, int bits, std::int64_t a, std::int64_t b);

// Cheap first tests (issue 8/9, lazy isolation): each answers true only when p provably has no
// failure interval in the stated range, and false whenever it cannot tell (never a wrong "no").
//  * no_failure_from_zero(p): p(0) ≠ 0 and the nonzero coefficients all have p(0)'s sign
//    (Descartes: no root in [0, ∞)), so sign_before(p, kδ) is the same for every k ≥ 0: no failure
//    interval k ≥ 0 on any lattice. Exact (integer signs).
//  * root_free_until(p, bits, from, last) = w ∈ [from, last]: p has no root in [from·δ, w·δ], so
//    sign_before(p, kδ) = sign p(from·δ) for from ≤ k ≤ w and no failure interval lies in
//    [from, w). w > from needs p(from·δ) ≠ 0 with |p(A)| (a double value and filtered_sign_at's
//    bound) above Σ_{i≥1} U_i·D^i, where U_i majorizes the i-th Taylor coefficient at A = from·δ
//    and D = (w − from)·δ; D is a power of two (in lattice intervals) guessed from the exponents
//    of |p(A)| and U_i, or the rest of the horizon. w = from: nothing proven. Needs
//    0 ≤ from ≤ last < 2^62 (from ≥ 2^53 proves nothing).
bool no_failure_from_zero(const MachinePolynomial& p);
std::int64_t root_free_until(const MachinePolynomial& p, int bits, std::int64_t from, std::int64_t last);

// sign_before(p, kδ) exactly: a double evaluation with filtered_sign_at's bound where p(kδ) ≠ 0
// is certain, else poly::sign_before on p.to_polynomial() (|k| < 2^62, 0 ≤ bits ≤ 62).
int sign_before_lattice(const MachinePolynomial& p, std::int64_t k, int bits);

}  // namespace kmr::poly
