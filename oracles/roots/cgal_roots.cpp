// The only CGAL translation unit of the root oracle (see cgal_roots.hpp for its guarantees).
#include "cgal_roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_BigInt.h>
#include <gmp.h>

#include <iterator>
#include <stdexcept>

namespace kmr::oracles {

namespace {
using AK = CGAL::Algebraic_kernel_d_1<CORE::BigInt>;
using Coefficient = AK::Coefficient;
using Bound = AK::Bound;  // CORE::BigRat

Coefficient to_core(const exact::Integer& x) { return Coefficient(x.backend().data()); }

exact::Integer from_mpz(mpz_srcptr z) {
  exact::Integer r;
  mpz_set(r.backend().data(), z);
  return r;
}

// floor(q·2^b) for a rational q.
exact::Integer floor_scaled(const Bound& q, int b) {
  mpq_t s;
  mpq_init(s);
  mpq_mul_2exp(s, q.get_mp(), static_cast<unsigned long>(b));
  mpz_t f;
  mpz_init(f);
  mpz_fdiv_q(f, mpq_numref(s), mpq_denref(s));
  exact::Integer r = from_mpz(f);
  mpz_clear(f);
  mpq_clear(s);
  return r;
}

// The rational k·2^−b.
Bound lattice_point(const exact::Integer& k, int b) {
  Bound q(to_core(k));
  mpq_div_2exp(q.get_mp(), q.get_mp(), static_cast<unsigned long>(b));
  return q;
}
}  // namespace

OracleRoots oracle_real_roots(const std::vector<exact::Integer>& coefficients, int lattice_bits) {
  if (lattice_bits < 0) throw std::invalid_argument("lattice bits must be >= 0");
  std::vector<Coefficient> cs;
  bool zero = true;
  for (const auto& c : coefficients) {
    cs.push_back(to_core(c));
    zero = zero && c.is_zero();
  }
  if (zero) throw std::invalid_argument("the zero polynomial has no isolated roots");
  AK ak;
  AK::Polynomial_1 p(cs.begin(), cs.end());
  std::vector<std::pair<AK::Algebraic_real_1, AK::Multiplicity_type>> found;
  ak.solve_1_object()(p, std::back_inserter(found));
  OracleRoots out;
  out.distinct = static_cast<int>(found.size());
  for (const auto& [root, mult] : found) {
    // [lo, hi] ∋ root with hi − lo ≤ 2^−(b+2) < δ: k is floor(lo/δ) or floor(hi/δ).
    auto [lo, hi] = ak.approximate_absolute_1_object()(root, lattice_bits + 2);
    exact::Integer klo = floor_scaled(lo, lattice_bits), khi = floor_scaled(hi, lattice_bits);
    exact::Integer k = klo;
    if (khi != klo) {
      if (khi - klo != 1) throw std::logic_error("oracle: approximation wider than the lattice");
      // root ≥ khi·δ exactly?
      k = ak.compare_1_object()(root, lattice_point(khi, lattice_bits)) == CGAL::SMALLER ? klo : khi;
    }
    bool on = ak.compare_1_object()(root, lattice_point(k, lattice_bits)) == CGAL::EQUAL;
    out.roots.push_back(OracleRoot{k, static_cast<int>(mult), on});
  }
  return out;
}

OracleRoots oracle_real_roots(const std::vector<std::string>& decimal_coefficients, int lattice_bits) {
  std::vector<exact::Integer> cs;
  for (const auto& s : decimal_coefficients) cs.push_back(exact::parse_integer(s));
  return oracle_real_roots(cs, lattice_bits);
}

std::vector<OracleInterval> lattice_intervals(const OracleRoots& r, const exact::Integer& k_from,
                                              const exact::Integer& k_to) {
  std::vector<OracleInterval> out;
  for (const auto& root : r.roots) {
    if (root.k < k_from || root.k >= k_to) continue;
    if (out.empty() || out.back().k != root.k) out.push_back(OracleInterval{root.k, 0, 0});
    out.back().distinct += 1;
    out.back().multiplicity_sum += root.multiplicity;
    out.back().starts_at_root = out.back().starts_at_root || root.on_lattice;
  }
  return out;
}

std::optional<exact::Integer> first_sign_change(const OracleRoots& r, const exact::Integer& k_from,
                                                const exact::Integer& k_to) {
  for (const auto& i : lattice_intervals(r, k_from, k_to))
    if (i.sign_change()) return i.k;
  return std::nullopt;
}

std::optional<exact::Integer> first_failure_zero_fails(const OracleRoots& r, const exact::Integer& k_from,
                                                       const exact::Integer& k_to) {
  for (const auto& i : lattice_intervals(r, k_from, k_to))
    if (i.sign_change() || (i.starts_at_root && i.k > k_from)) return i.k;
  return std::nullopt;
}

}  // namespace kmr::oracles
