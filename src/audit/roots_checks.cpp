// Audit checks of the lattice root solver (§2.1, A.1.2) on polynomials with planted roots: the
// expected lattice intervals come from the planted rationals, not from the solver.
#include <chrono>
#include <map>
#include <random>
#include <sstream>

#include "audit/audit.hpp"
#include "poly/sturm.hpp"

namespace kmr::audit {

namespace {

using exact::Dyadic;
using exact::Integer;
using poly::Polynomial;

struct Planted {
  Polynomial p;
  std::map<Integer, std::pair<int, int>> intervals;  // k → (distinct roots, multiplicity sum)
  int distinct = 0;
};

Integer floor_div(const Integer& a, const Integer& b) {  // b > 0
  Integer q = a / b;
  if (q * b > a) q -= 1;
  return q;
}

// Random roots p/q (some exactly on lattice points, some within 2^-14 of each other), random
// multiplicities 1..3, times a root-free factor t² + c.
Planted plant(std::mt19937_64& rng, int bits) {
  Planted out;
  out.p = Polynomial(1);
  std::uniform_int_distribution<int> count(0, 5), mult(1, 3), kind(0, 3);
  std::uniform_int_distribution<long long> num(-(1LL << 40), 1LL << 40), den(1, 1LL << 20);
  std::map<std::pair<Integer, Integer>, int> roots;  // reduced (p, q) → multiplicity
  Integer last_p(0), last_q(1);
  for (int i = count(rng); i > 0; --i) {
    Integer p, q;
    switch (kind(rng)) {
      case 0: p = num(rng); q = Integer(1) << static_cast<unsigned>(bits); break;  // on the lattice
      case 1: p = last_p * (Integer(1) << 14) + 1; q = last_q << 14; break;      // near the last root
      default: p = num(rng); q = den(rng); break;
    }
    Integer g = boost::multiprecision::gcd(p, q);
    p /= g, q /= g;
    roots[{p, q}] += mult(rng);
    last_p = p, last_q = q;
  }
  for (auto& [r, m] : roots) {
    for (int j = 0; j < m; ++j) out.p = out.p * Polynomial(std::vector<Integer>{-r.first, r.second});
    Integer k = floor_div(r.first << static_cast<unsigned>(bits), r.second);
    out.intervals[k].first += 1;
    out.intervals[k].second += m;
  }
  out.distinct = static_cast<int>(roots.size());
  out.p = out.p * Polynomial(std::vector<Integer>{Integer(1 + (num(rng) & 0xffff)), 0, 1});
  return out;
}

Verdict lattice_isolation(const Options& options, bool failures_only) {
  std::mt19937_64 rng(options.seed);
  const int bits = 10, trials = options.quick ? 200 : 2000;
  const Dyadic lo(-(1LL << 41)), hi(1LL << 41);
  Verdict v;
  v.pass = true;
  long long queries = 0, max_degree = 0, max_bits = 0, failures_checked = 0;
  auto start = std::chrono::steady_clock::now();
  for (int t = 0; t < trials && v.pass; ++t) {
    Planted pl = plant(rng, bits);
    poly::LatticeRootSolver solver(pl.p, bits);
    max_degree = std::max<long long>(max_degree, pl.p.degree());
    for (const auto& c : pl.p.coefficients()) max_bits = std::max<long long>(max_bits, exact::bit_length(c));
    std::ostringstream why;
    if (!failures_only) {
      auto got = measured(options, "A2.1-lattice-isolation intervals", solver.isolate(lo, hi));
      std::vector<poly::LatticeInterval> want;
      for (auto& [k, c] : pl.intervals) want.push_back({k, c.first, c.second % 2 == 1});
      if (got != want || solver.distinct_real_roots() != pl.distinct) why << "isolation differs from the planted roots";
    } else {
      // next_failure_after from a few start times: the first planted interval with odd multiplicity sum.
      for (const auto& [k0, unused] : pl.intervals) {
        Dyadic from(k0, -bits);
        std::optional<Integer> want;
        for (auto& [k, c] : pl.intervals)
          if (k >= k0 && c.second % 2 == 1) { want = k; break; }
        ++failures_checked;
        if (measured(options, "A2.1-next-failure interval", solver.next_failure_after(from, hi)) != want)
          why << "next_failure_after(" << from.to_decimal() << ") wrong";
      }
    }
    queries += solver.sturm_queries;
    if (!why.str().empty()) {
      v.pass = false;
      v.summary = why.str() + " for p = " + pl.p.to_string();
    }
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (v.pass)
    v.summary = std::to_string(trials) + " planted-root polynomials (lattice points, clusters closer than δ, multiplicities ≤ 3)";
  v.figure("max degree", std::to_string(max_degree));
  v.figure("max coefficient bits", std::to_string(max_bits));
  v.figure("Sturm queries per polynomial", fmt(static_cast<double>(queries) / trials));
  if (failures_only) v.figure("start times checked", std::to_string(failures_checked));
  v.figure("seconds", fmt(seconds));
  return v;
}

}  // namespace

std::vector<Check> roots_checks() {
  return {
      {"A2.1-lattice-isolation", "lattice root solver reports exactly the planted roots' intervals",
       [](const Options& o) { return lattice_isolation(o, false); }},
      {"A2.1-next-failure", "next_failure_after finds the first interval whose sign changes",
       [](const Options& o) { return lattice_isolation(o, true); }},
  };
}

}  // namespace kmr::audit
