#pragma once
// Sturm sequences and the lattice root solver of §2.1 (thesis Appendix A.1.2).
//
// Guarantees:
//  * SturmSequence(p) is built from the square-free part of p, so it counts *distinct* real
//    roots. Its members are positive multiples of the classical sequence p, p', −rem(p, p'), ...:
//    a Knuth pseudo-remainder carries the factor lc^(d+1), whose sign we undo when lc < 0 and
//    d+1 is odd, so sign variations equal those of the true Sturm sequence.
//  * Sign evaluations go through a double-precision filter with exact fallback
//    (filtered_sign_at in polynomial.hpp), so every sign, and hence every count, is exact.
//  * count_roots(lo, hi) = number of distinct real roots in [lo, hi), exactly, for dyadic lo < hi.
//  * LatticeRootSolver with lattice δ = 2^−b reports, for a window [T0, T1), every lattice interval
//    [kδ, (k+1)δ) with T0 ≤ kδ < T1 that holds a real root, with its number of distinct roots,
//    in increasing k. It bisects only down to lattice resolution: roots closer than δ are never
//    separated (§2.1), and roots exactly at lattice points belong to the interval they start.
//  * next_failure_after(t): the first lattice interval [kδ, (k+1)δ) with kδ ≥ t across which the
//    sign changes, i.e. sign_before((k+1)δ) ≠ sign_before(kδ); an even-multiplicity root is no
//    failure, and neither is a cluster of roots whose multiplicities sum to an even number.
//    With zero_fails, an interval whose start kδ > t is a root also ends the search (for a
//    certificate violated where it vanishes: a root of even multiplicity at a lattice time).
//  * Identically-zero polynomials are refused with an InputError.
#include <optional>
#include <vector>

#include "poly/polynomial.hpp"

namespace kmr::poly {

class SturmSequence {
 public:
  explicit SturmSequence(const Polynomial& p);  // p ≢ 0
  const std::vector<Polynomial>& members() const { return seq_; }
  const Polynomial& square_free() const { return seq_.front(); }

  // Sign variations of the sequence at t (zeros skipped), at −∞ and at +∞.
  int variations_at(const Integer& m, long long s) const;  // at t = m / 2^s
  int variations_at(const Dyadic& t) const;
  int variations_at_minus_infinity() const { return v_minus_inf_; }
  int variations_at_plus_infinity() const { return v_plus_inf_; }

  int distinct_real_roots() const { return v_minus_inf_ - v_plus_inf_; }
  // Number of distinct real roots < t (a "Sturm query", §2.1).
  int roots_below(const Integer& m, long long s) const;
  int roots_below(const Dyadic& t) const;
  int count_roots(const Dyadic& lo, const Dyadic& hi) const { return roots_below(hi) - roots_below(lo); }

 private:
  void build(const Polynomial& first);  // the remainder sequence from `first` (stops at a zero remainder)
  std::vector<Polynomial> seq_;
  std::vector<DoubleCoefficients> approx_;  // seq_ rounded to doubles, for the sign filter
  int v_minus_inf_ = 0, v_plus_inf_ = 0;
};

struct LatticeInterval {
  Integer k;          // the interval is [kδ, (k+1)δ)
  int roots = 0;      // distinct real roots in it (≥ 1)
  bool sign_change;   // sign_before((k+1)δ) ≠ sign_before(kδ)
  friend bool operator==(const LatticeInterval&, const LatticeInterval&) = default;
};

class LatticeRootSolver {
 public:
  // p ≢ 0; lattice δ = 2^−lattice_bits (lattice_bits ≥ 0).
  LatticeRootSolver(const Polynomial& p, int lattice_bits);

  const Polynomial& polynomial() const { return p_; }
  int lattice_bits() const { return bits_; }
  Dyadic lattice_point(const Integer& k) const { return Dyadic(k, -bits_); }
  int distinct_real_roots() const { return sturm().distinct_real_roots(); }
  int count_roots(const Dyadic& lo, const Dyadic& hi) const { return sturm().count_roots(lo, hi); }

  std::vector<LatticeInterval> isolate(const Dyadic& from, const Dyadic& to) const;
  std::optional<Integer> next_failure_after(const Dyadic& t, const Dyadic& horizon, bool zero_fails = false) const;

  // Distinct real roots < m / 2^s: one Sturm query (counted), for refinement below the lattice.
  int roots_below(const Integer& m, long long s) const {
    ++sturm_queries;
    return sturm().roots_below(m, s);
  }

  // Lattice-indexed helpers: sign of p just before kδ, and whether interval k changes sign.
  int sign_before_lattice(const Integer& k) const;
  bool sign_changes_across(const Integer& k) const;

  // Statistics of the last queries (for benchmarks): Sturm evaluations performed.
  mutable long long sturm_queries = 0;

 private:
  int roots_below_lattice(const Integer& k) const;
  // Finds the intervals in lattice index range [a, b) given roots_below at a and b; stops early
  // once `stop` says so (used by next_failure_after to search leftmost-first).
  template <class Visit>
  bool scan(const Integer& a, const Integer& b, int ca, int cb, Visit& visit) const;
  // Lattice index range [lo, hi) that can hold roots, intersected with the Cauchy root bound.
  std::pair<Integer, Integer> clamp_range(const Integer& lo, const Integer& hi) const;

  Polynomial p_;
  DoubleCoefficients p_approx_;
  int bits_;
  // Built on first use (a certificate whose failures the double filter decides never needs it);
  // so a solver is not safe to share between threads.
  const SturmSequence& sturm() const;
  mutable std::optional<SturmSequence> sturm_;
  mutable Integer root_bound_k_;  // every real root r has |r| < root_bound_k_·δ (set with sturm_)
};

// Lattice index helpers: the first k with kδ ≥ t, for δ = 2^−bits.
Integer lattice_ceil(const Dyadic& t, int bits);

}  // namespace kmr::poly
