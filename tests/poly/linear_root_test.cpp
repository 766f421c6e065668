// The machine path for linear certificates (src/poly/linear_root.hpp) against exact GMP arithmetic
// computed here (floor of the rational root, Taylor signs at lattice points) on adversarial inputs:
// roots exactly on lattice points, roots within 2^-40 (and one ulp) of a lattice point, quotients
// that round onto an integer, coefficients at the filter's and the machine path's limits.
#include <gtest/gtest.h>

#include <random>

#include "poly/linear_root.hpp"
#include "poly/sturm.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::poly::Polynomial;

struct Case {
  std::int64_t c0, c1;
};

Integer floor_div(const Integer& a, const Integer& b) {  // exact floor(a / b), b ≠ 0
  Integer q = a / b;
  if ((q * b > a && b > 0) || (q * b < a && b < 0)) q -= 1;
  return q;
}

// Adversarial certificates for lattice bits `bits`, all with |c| < 2^62.
std::vector<Case> adversarial(int bits, std::mt19937_64& rng) {
  std::vector<Case> out;
  auto uniform = [&](std::int64_t lo, std::int64_t hi) { return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng); };
  const std::int64_t two53 = std::int64_t{1} << 53, limit = (std::int64_t{1} << 62) - 1;
  for (int i = 0; i < 300; ++i) {
    std::int64_t u = uniform(1, 1 << 20) * (uniform(0, 1) ? 1 : -1), m = uniform(-(1 << 20), 1 << 20);
    int j = static_cast<int>(uniform(0, std::min(bits, 20)));
    // Root exactly on the lattice point m·2^−j (j ≤ bits).
    out.push_back({-u * m, u << j});
    // Roots 1 and 2 units of 2^−40 on either side of m·2^−j: c1 = u·2^40 needs |u| < 2^21.
    std::int64_t v = u >> 1 ? u >> 1 : 1;
    for (std::int64_t d : {-2, -1, 1, 2}) out.push_back({-(v * m * (std::int64_t{1} << (40 - j))) + v * d, v << 40});
    // Quotients near 2^52 that round onto (or just off) an integer: q = −c0·2^b/c1 with c1 = 3, 5, 7.
    if (bits <= 1) {
      std::int64_t c1 = 3 + 2 * uniform(0, 2), c0 = -(uniform(two53 / 4, two53 / 2) >> bits);
      for (std::int64_t d : {-1, 0, 1}) out.push_back({c0 + d, c1});
    }
    // Large quotients (2^47..2^52, ulp up to 1/2) whose double often rounds onto an integer.
    if (bits >= 10 && bits <= 50) {
      std::int64_t c0 = uniform(std::int64_t{1} << 49, std::int64_t{1} << 50) * (uniform(0, 1) ? 1 : -1);
      out.push_back({c0, uniform(std::int64_t{1} << (bits - 2), std::int64_t{1} << (bits + 1)) | 1});
    }
    // Coefficients at the filter's limit (2^53) and the machine limit (2^62 − 1).
    out.push_back({two53 - uniform(0, 2), -(two53 - uniform(0, 2))});
    out.push_back({two53 + uniform(1, 3), two53 - 1});
    out.push_back({limit - uniform(0, 5), -(limit - uniform(0, 5))});
    out.push_back({-(limit - uniform(0, 5)), uniform(1, 1000)});
    // Random.
    out.push_back({uniform(-limit, limit) >> uniform(0, 60), uniform(-limit, limit) >> uniform(0, 60)});
  }
  std::erase_if(out, [](const Case& c) { return c.c1 == 0; });
  return out;
}

TEST(LinearRoot, A2_1_FilterAndExactIntervalEqualTheRationalRootsLatticeInterval) {
  RecordProperty("claim", "A2.1-machine-filter");
  std::mt19937_64 rng(2012);
  long long answered = 0, declined = 0, rounded_onto_integer = 0, on_lattice = 0;
  for (int bits : {0, 1, 10, 30, 62}) {
    double scale = std::ldexp(1.0, bits);
    for (const Case& c : adversarial(bits, rng)) {
      SCOPED_TRACE(std::to_string(c.c0) + " + " + std::to_string(c.c1) + "·t, bits = " + std::to_string(bits));
      Integer want = floor_div(-(Integer(c.c0) << bits), Integer(c.c1));
      __int128 exact = kmr::poly::linear_root_interval_exact(c.c0, c.c1, bits);
      EXPECT_EQ(Integer(static_cast<long long>(exact >> 64)) * (Integer(1) << 64) +
                    Integer(static_cast<unsigned long long>(exact & ~std::uint64_t{0})),
                want);
      bool root_on_lattice = (Integer(c.c0) << bits) % Integer(c.c1) == 0;
      on_lattice += root_on_lattice;
      auto filtered = kmr::poly::linear_root_interval_filtered(c.c0, c.c1, scale);
      if (filtered) {
        ++answered;
        EXPECT_EQ(Integer(*filtered), want);
      } else {
        ++declined;
      }
      // A quotient whose double rounds onto an integer though the root is not on the lattice: the
      // case a filter without its "q̃ ∉ ℤ" test would get wrong.
      double q = (-static_cast<double>(c.c0) * scale) / static_cast<double>(c.c1);
      if (std::fabs(q) < 0x1p52 && std::floor(q) == q && !root_on_lattice && std::fabs(c.c0) <= 0x1p53 &&
          std::fabs(c.c1) <= 0x1p53)
        ++rounded_onto_integer;
      // Signs just before the lattice points around the root, against sign_before of the polynomial.
      Polynomial p(std::vector<Integer>{Integer(c.c0), Integer(c.c1)});
      for (Integer k : {want - 1, want, want + 1, want + 2, Integer(0)}) {
        if (abs(k) >= (Integer(1) << 62)) continue;
        EXPECT_EQ(kmr::poly::linear_sign_before(c.c0, c.c1, bits, static_cast<std::int64_t>(k)),
                  kmr::poly::sign_before(p, Dyadic(k, -bits)))
            << "k = " << k;
      }
    }
  }
  // Not vacuous: both branches and the dangerous roundings occur.
  EXPECT_GT(answered, 1000);
  EXPECT_GT(declined, 1000);
  EXPECT_GT(rounded_onto_integer, 20);
  EXPECT_GT(on_lattice, 1000);
}

}  // namespace
