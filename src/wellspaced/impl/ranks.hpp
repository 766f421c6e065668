#pragma once
// Ranks, ℓ(r) and colours (§3.2.1–3.2.2, Lemma 3.3.12), decided exactly; the refusal of ρ too
// close to 1 (issue 11).
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
auto WellSpacedSet<D>::Impl::set_params(const Params& p) -> void {
  if (!(std::isfinite(p.rho) && p.rho > 1.0)) throw InputError("rho must be a finite number > 1");
  if (!(std::isfinite(p.beta) && p.beta > p.rho)) throw InputError("beta must be a finite number > rho");
  if (p.rho > 64 || p.beta > 256) throw InputError("rho/beta too large (rho ≤ 64, beta ≤ 256)");
  params = p;
  refuse_out_of_reach(0);  // r_max = ⌊log_ρ √D⌋ alone can be out of reach
  rho2 = Q(p.rho) * Q(p.rho);
  beta2 = Q(p.beta) * Q(p.beta);
  kappa = static_cast<int>(std::floor(1.0 + 6.0 * p.beta * p.rho * std::sqrt(double(D)) * (1 + 1e-12))) + 1;
  rmax = rank_of(Q(static_cast<long long>(D)));
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::rpow(int r) -> const Q& {
  auto it = rho_pow2.find(r);
  if (it != rho_pow2.end()) return it->second;
  Q base = r >= 0 ? rho2 : Q(1) / rho2;
  Q x = 1;
  for (int i = 0; i < std::abs(r); ++i) x *= base;
  return rho_pow2.emplace(r, x).first->second;
}

// ⌊log_ρ sqrt(d2)⌋, exactly.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::rank_of(const Q& d2) -> int {
  double dd = d2.template convert_to<double>();
  int r = static_cast<int>(std::floor(std::log(dd) / (2 * std::log(params.rho))));
  while (rpow(r + 1) <= d2) ++r;
  while (rpow(r) > d2) --r;
  return r;
}

// ⌊log_ρ |ab|⌋, exactly: decided on intervals when they suffice, else in rationals.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::rank_between(const Pt& a, const Pt& b) -> int {
  try {
    return rank_in<IntervalNT>(dist2(point_in<IntervalNT, D>(a), point_in<IntervalNT, D>(b)));
  } catch (const Uncertain&) {
    return rank_of(dist2(to_q<D>(a), to_q<D>(b)));
  }
}

// ⌊log_ρ sqrt(d2)⌋ in NT (Uncertain when intervals do not decide it).
template <std::size_t D>
template <class NT>
auto WellSpacedSet<D>::Impl::rank_in(const NT& d2) -> int {
  if constexpr (!is_interval_v<NT>) {
    return rank_of(d2);
  } else {
    int r = static_cast<int>(std::floor(std::log(d2.approx()) / (2 * std::log(params.rho))));
    while (rpow_i(r + 1) <= d2) ++r;
    while (rpow_i(r) > d2) --r;
    return r;
  }
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::rpow_i(int r) -> const IntervalNT& {
  auto it = rho_pow2_i.find(r);
  if (it != rho_pow2_i.end()) return it->second;
  return rho_pow2_i.emplace(r, exact::enclose(rpow(r))).first->second;
}

// ℓ(r): the largest power of two 2^e with 2^{2e}·D < ρ^{2r} (so ℓ(r) < ρ^r/√D).
template <std::size_t D>
auto WellSpacedSet<D>::Impl::ell(int r) -> int {
  auto it = ell_exp.find(r);
  if (it != ell_exp.end()) return it->second;
  const Q& target = rpow(r);
  int e = static_cast<int>(std::floor(r * std::log2(params.rho) - 0.5 * std::log2(double(D)))) + 2;
  auto ok = [&](int ee) {  // 2^{2ee}·D < ρ^{2r}
    Q p2 = 1;
    Q b = ee >= 0 ? Q(4) : Q(1, 4);
    for (int i = 0; i < std::abs(ee); ++i) p2 *= b;
    return p2 * Q(static_cast<long long>(D)) < target;
  };
  while (!ok(e)) --e;
  while (ok(e + 1)) ++e;
  return ell_exp.emplace(r, e).first->second;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::color(const Pt& w, int r) -> std::int64_t {
  int e = ell(r);
  std::int64_t c = 0;
  for (std::size_t i = 0; i < D; ++i) {
    if (!w.is_double()) {  // ⌊w_i / 2^e⌋ mod κ of the exact dyadic
      exact::Integer f = w.coord(i).shifted(-e).floor() % kappa;
      c = c * kappa + f.template convert_to<std::int64_t>();
      continue;
    }
    double f = std::floor(std::ldexp(w.below()[i], -e));
    auto ci = static_cast<std::int64_t>(std::fmod(f, double(kappa)));
    c = c * kappa + ci;
  }
  return c;
}

// Refuses (InputError) a run whose exact rank thresholds are out of reach. Ranks run from
// ⌊log_ρ NN_min⌋ to r_max, and the thresholds ρ^{2r} are exact rationals of 2|r|·b bits (b = the
// significant bits of the double ρ). With the smallest leaf 2^-L (leaves are Θ(lfs), Lemma 3.1.5),
// the ranks span about log_ρ(2^L·√D) (the size constant c = 2ρ/(ρ−1) of Lemma 3.3.3 would widen
// this by log_ρ c; the measured runs did not need it). The measured cost grows
// faster than linearly in 2|r|·b (3 points, 2D: 18k bits 0.45 s, 83k 2.7 s, 207k 37 s; issue 11:
// ρ = 1.0000001 ran for minutes silently), so more than 2^17 bits is refused with a message.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::refuse_out_of_reach(int depth) const -> void {
  int ex = 0;
  const double m = std::frexp(params.rho, &ex);  // ρ = m·2^ex, m ∈ [0.5, 1)
  std::uint64_t mant = static_cast<std::uint64_t>(std::ldexp(m, 53));
  int bits = 53;
  while (bits > 1 && !(mant & 1)) {
    mant >>= 1;
    --bits;
  }
  const double ranks = (depth * std::log(2.0) + 0.5 * std::log(double(D))) / std::log(params.rho);
  const double work = 2 * ranks * bits;
  if (work > 0x1p17) {
    char msg[400];
    std::snprintf(msg, sizeof msg,
                  "rho = %.17g is too close to 1 for this input: about %.0f ranks between the smallest "
                  "square and the domain, with exact rank thresholds rho^(2r) of about %.0f bits (limit 131072); "
                  "use a larger rho or one with fewer significant bits (e.g. 1 + 2^-k)",
                  params.rho, ranks, work);
    throw InputError(msg);
  }
}

}  // namespace kmr::wellspaced
