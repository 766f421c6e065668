// The lattice root solver (src/poly/sturm.hpp) against CGAL's Algebraic_kernel_d_1 (cgal_roots.hpp):
// the number of distinct real roots, which lattice intervals hold roots and how many, whether the
// sign changes across each, and next_failure_after (with and without zero_fails), on hand-picked hard cases and random inputs.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "cgal_roots.hpp"
#include "exact/error.hpp"
#include "poly/sturm.hpp"

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::oracles::first_sign_change;
using kmr::oracles::lattice_intervals;
using kmr::oracles::oracle_real_roots;
using kmr::poly::LatticeRootSolver;
using kmr::poly::Polynomial;

Integer pow2(unsigned e) { return Integer(1) << e; }
Polynomial lin(const Integer& a, const Integer& b) { return Polynomial(std::vector<Integer>{b, a}); }  // a·t + b
Polynomial power(const Polynomial& p, int e) {
  Polynomial r(1);
  for (int i = 0; i < e; ++i) r = r * p;
  return r;
}
Integer lattice_index_ceil(const Dyadic& t, int bits) { return t.shifted(bits).ceil(); }

// Checks every answer of the solver against the oracle on window [from, to); returns the number of
// nonempty intervals compared (so callers can see the case was not vacuous).
std::size_t expect_agrees(const Polynomial& p, int bits, const Dyadic& from, const Dyadic& to) {
  SCOPED_TRACE("p = " + p.to_string() + ", b = " + std::to_string(bits) + ", window [" + from.to_decimal() +
               ", " + to.to_decimal() + ")");
  auto oracle = oracle_real_roots(p.coefficients(), bits);
  LatticeRootSolver solver(p, bits);
  EXPECT_EQ(solver.distinct_real_roots(), oracle.distinct);
  Integer ka = lattice_index_ceil(from, bits), kb = lattice_index_ceil(to, bits);
  auto expected = lattice_intervals(oracle, ka, kb);
  auto got = solver.isolate(from, to);
  EXPECT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < std::min(got.size(), expected.size()); ++i) {
    EXPECT_EQ(got[i].k, expected[i].k) << "interval " << i;
    EXPECT_EQ(got[i].roots, expected[i].distinct) << "interval k=" << got[i].k;
    EXPECT_EQ(got[i].sign_change, expected[i].sign_change()) << "interval k=" << got[i].k;
  }
  // next_failure_after from the window start, then from just after each failure found.
  Integer k = ka;
  for (int guard = 0; guard < 64; ++guard) {
    auto want = first_sign_change(oracle, k, kb);
    auto have = solver.next_failure_after(Dyadic(k, -bits), to);
    EXPECT_EQ(have.has_value(), want.has_value()) << "from k=" << k;
    if (!have || !want) break;
    EXPECT_EQ(*have, *want) << "from k=" << k;
    if (*have != *want) break;
    k = *want + 1;
  }
  // The same walk with zero_fails: an interval starting at a root after the start also fails.
  k = ka;
  for (int guard = 0; guard < 64; ++guard) {
    auto want = kmr::oracles::first_failure_zero_fails(oracle, k, kb);
    auto have = solver.next_failure_after(Dyadic(k, -bits), to, /*zero_fails=*/true);
    EXPECT_EQ(have.has_value(), want.has_value()) << "zero_fails from k=" << k;
    if (!have || !want) break;
    EXPECT_EQ(*have, *want) << "zero_fails from k=" << k;
    if (*have != *want) break;
    k = *want + 1;
  }
  return expected.size();
}

const Dyadic kEverywhereLo = -Dyadic::pow2(800), kEverywhereHi = Dyadic::pow2(800);

TEST(RootsOracle, A2_1_LatticeIsolation_HandPicked) {
  RecordProperty("claim", "A2.1-lattice-isolation");
  Polynomial t = Polynomial::identity();
  // Roots exactly on lattice points, with multiplicities 2 and 3.
  Polynomial p1 = power(t - Polynomial(1), 2) * power(t - Polynomial(2), 3);
  for (int b : {0, 1, 5, 10}) EXPECT_EQ(expect_agrees(p1, b, kEverywhereLo, kEverywhereHi), 2u);
  // Window ends: the root at T0 = 1 is included, the root at T1 = 2 is not.
  EXPECT_EQ(expect_agrees(p1, 10, Dyadic(1), Dyadic(2)), 1u);
  EXPECT_EQ(expect_agrees(p1, 10, Dyadic(1) + Dyadic::pow2(-10), Dyadic(2) + Dyadic::pow2(-10)), 1u);
  // A cluster: roots 2^-20 and 3·2^-20 share lattice interval 0 for δ = 2^-10; a third root at 5.
  Polynomial p2 = lin(pow2(20), Integer(-1)) * lin(pow2(20), Integer(-3)) * (t - Polynomial(5));
  EXPECT_EQ(expect_agrees(p2, 10, kEverywhereLo, kEverywhereHi), 2u);
  EXPECT_EQ(expect_agrees(p2, 30, kEverywhereLo, kEverywhereHi), 3u);
  // Roots just below and just above a lattice point, by 2^-600, with 600-bit coefficients.
  Integer k7 = Integer(7) << 590;  // 7·2^-10 = k7·2^-600
  Polynomial p3 = lin(pow2(600), -(k7 - 1)) * lin(pow2(600), -(k7 + 1)) * power(lin(pow2(600), -k7), 2);
  EXPECT_EQ(expect_agrees(p3, 10, kEverywhereLo, kEverywhereHi), 2u);
  EXPECT_EQ(expect_agrees(p3, 10, Dyadic(7, -10), Dyadic(8, -10)), 1u);
  // Irrational roots and a root-free factor with 520-bit constant: (t² − 2)(t² + 2^520 + 1)(3t − 1)³.
  Polynomial p4 = (t * t - Polynomial(2)) * (t * t + Polynomial(pow2(520) + 1)) * power(lin(Integer(3), Integer(-1)), 3);
  for (int b : {0, 3, 10, 40}) expect_agrees(p4, b, kEverywhereLo, kEverywhereHi);
  // Mignotte-like: t^16 − 2(2^40·t − 1)² has two real roots within ~2^-100 of each other near 2^-40.
  Polynomial m = power(t, 16) - Integer(2) * power(lin(pow2(40), Integer(-1)), 2);
  for (int b : {10, 40, 60, 90}) expect_agrees(m, b, kEverywhereLo, kEverywhereHi);
  // Degree 16 with every root on the lattice of δ = 1/4; with δ = 1/2 pairs share intervals.
  Polynomial w(1);
  for (int i = -8; i < 8; ++i) w = w * lin(Integer(4), Integer(-i));
  for (int b : {0, 1, 2, 3}) expect_agrees(w, b, kEverywhereLo, kEverywhereHi);
  EXPECT_EQ(expect_agrees(w, 2, Dyadic(-1), Dyadic(1)), 8u);
  // The sign trap: negative leading coefficient, odd degree, odd degree differences.
  Polynomial trap = -(t - Polynomial(3)) * (t + Polynomial(1)) * (t * t * t - Polynomial(2) * t + Polynomial(7));
  for (int b : {0, 4, 10}) expect_agrees(trap, b, kEverywhereLo, kEverywhereHi);
  // Abnormal remainder sequences, where a degree drops by 2 and the divisor's leading coefficient is
  // negative: t^4 + t − 1 gives p2 = −(3/4)t + 1, and prem(p1, p2) carries lc(p2)^3 < 0.
  for (int c : {-1, -3, 1}) {
    Polynomial q = power(t, 4) + t + Polynomial(c);
    for (int b : {0, 4, 10}) expect_agrees(q, b, kEverywhereLo, kEverywhereHi);
  }
  EXPECT_EQ(LatticeRootSolver(power(t, 4) + t - Polynomial(1), 0).distinct_real_roots(), 2);
  Polynomial q6 = power(t, 6) - Integer(5) * t * t + t + Polynomial(1);
  for (int b : {0, 4, 10}) expect_agrees(q6, b, kEverywhereLo, kEverywhereHi);
  // Constants have no roots.
  EXPECT_EQ(expect_agrees(Polynomial(7), 10, kEverywhereLo, kEverywhereHi), 0u);
  EXPECT_EQ(expect_agrees(Polynomial(-pow2(600)), 10, kEverywhereLo, kEverywhereHi), 0u);
  // Even-multiplicity roots are no failures; an odd cluster (1 + 2 in one interval) is.
  Polynomial p5 = power(t - Polynomial(3), 4) * lin(pow2(20), -(Integer(3) << 20) - 1) *
                  power(lin(pow2(20), -(Integer(3) << 20) - 2), 2);
  EXPECT_EQ(expect_agrees(p5, 10, kEverywhereLo, kEverywhereHi), 1u);
  EXPECT_EQ(expect_agrees(p5, 30, kEverywhereLo, kEverywhereHi), 3u);
}

TEST(RootsOracle, A2_1_SturmCount_Chebyshev) {
  RecordProperty("claim", "A2.1-sturm-count");
  // Chebyshev T_n: n simple roots in (−1, 1), crowding near ±1.
  Polynomial t = Polynomial::identity(), a(1), b = t;
  for (int n = 2; n <= 16; ++n) {
    Polynomial c = Integer(2) * t * b - a;
    a = b;
    b = c;
    auto oracle = oracle_real_roots(b.coefficients(), 4);
    EXPECT_EQ(oracle.distinct, n);
    EXPECT_EQ(LatticeRootSolver(b, 4).distinct_real_roots(), n);
    for (int bits : {0, 2, 4, 8}) expect_agrees(b, bits, kEverywhereLo, kEverywhereHi);
  }
}

// Random coefficients: degree 0..16, magnitudes up to 520 bits.
Integer random_integer(std::mt19937_64& rng, unsigned max_bits) {
  unsigned bits = std::uniform_int_distribution<unsigned>(0, max_bits)(rng);
  Integer x(0);
  for (unsigned i = 0; i < bits; i += 32) x = (x << 32) + Integer(static_cast<std::uint32_t>(rng()));
  if (bits % 32) x >>= (32 - bits % 32);
  return rng() % 2 ? Integer(-x) : x;
}

TEST(RootsOracle, A2_1_LatticeIsolation_RandomCoefficients) {
  RecordProperty("claim", "A2.1-lattice-isolation");
  std::mt19937_64 rng(20121);
  for (int iter = 0; iter < 300; ++iter) {
    int degree = static_cast<int>(rng() % 17);
    unsigned bits = iter % 3 == 0 ? 520 : (iter % 3 == 1 ? 64 : 8);
    std::vector<Integer> c;
    bool sparse = iter % 2 == 1;  // many zero coefficients: abnormal remainder sequences
    for (int i = 0; i <= degree; ++i) c.push_back(sparse && rng() % 2 ? Integer(0) : random_integer(rng, bits));
    if (c.back().is_zero()) c.back() = 1;
    Polynomial p(c);
    int b = static_cast<int>(rng() % 16);
    expect_agrees(p, b, kEverywhereLo, kEverywhereHi);
    Dyadic from(Integer(static_cast<long long>(rng() % 64)) - 32, -static_cast<int>(rng() % 6));
    expect_agrees(p, b, from, from + Dyadic(Integer(static_cast<long long>(rng() % 64 + 1)), -2));
  }
}

// Planted structure: products of (q·t − p)^m with roots on, next to and between lattice points,
// clusters closer than δ, and a root-free factor t² + c; optionally scaled by a huge constant.
TEST(RootsOracle, A2_1_NextFailure_PlantedRandom) {
  RecordProperty("claim", "A2.1-next-failure");
  std::mt19937_64 rng(42);
  Polynomial t = Polynomial::identity();
  for (int iter = 0; iter < 150; ++iter) {
    int b = static_cast<int>(rng() % 12);
    Polynomial p(1);
    int degree = 0;
    while (degree < 14 && rng() % 5 != 0) {
      int m = 1 + static_cast<int>(rng() % 3);
      if (degree + m > 14) break;
      Integer k = Integer(static_cast<long long>(rng() % 41)) - 20;
      Polynomial f;
      switch (rng() % 4) {
        case 0: f = lin(pow2(static_cast<unsigned>(b)), -k); break;  // on the lattice point kδ
        case 1: {                                                     // kδ ± 2^-e, e up to 200
          unsigned e = static_cast<unsigned>(b) + 1 + static_cast<unsigned>(rng() % 200);
          Integer num = (k << (e - static_cast<unsigned>(b))) + (rng() % 2 ? 1 : -1);
          f = lin(pow2(e), -num);
          break;
        }
        case 2: f = lin(Integer(static_cast<long long>(rng() % 9 + 3)), -k); break;  // k/q, q in 3..11
        default: f = lin(random_integer(rng, 300) * 2 + 1, random_integer(rng, 300)); break;
      }
      if (f.degree() < 1) continue;
      p = p * power(f, m);
      degree += m;
    }
    if (rng() % 2) p = p * (t * t + Polynomial(random_integer(rng, 100) * random_integer(rng, 100) + 1));
    if (rng() % 3 == 0) p = random_integer(rng, 500) * p;
    if (p.is_zero()) p = Polynomial(1);
    expect_agrees(p, b, kEverywhereLo, kEverywhereHi);
    expect_agrees(p, b, Dyadic(-5), Dyadic(5));
    expect_agrees(p, b, Dyadic(Integer(static_cast<long long>(rng() % 20)) - 10, -b), Dyadic(Integer(3), 0));
  }
}

TEST(RootsOracle, RefusesZeroPolynomial) {
  EXPECT_THROW(oracle_real_roots(std::vector<std::string>{"0", "0"}, 3), std::invalid_argument);
  EXPECT_THROW((void)LatticeRootSolver(Polynomial(), 3), kmr::InputError);
  // The string form parses decimal coefficients of any size: 10^200·t − 10^200 has the root 1.
  std::string big = "1" + std::string(200, '0');
  auto r = oracle_real_roots(std::vector<std::string>{"-" + big, big}, 10);
  ASSERT_EQ(r.distinct, 1);
  EXPECT_EQ(r.roots[0].k, Integer(1024));
  EXPECT_EQ(r.roots[0].multiplicity, 1);
}

}  // namespace
