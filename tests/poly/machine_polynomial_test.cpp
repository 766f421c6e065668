// MachinePolynomial (poly/machine_polynomial.hpp) against Polynomial, which shares no arithmetic
// with it: the same operations give the same polynomial or are refused (never a wrapped value);
// its failure filter and lattice signs decide as the exact path on the converted Polynomial.
#include <gtest/gtest.h>

#include <random>

#include "exact/error.hpp"
#include "poly/failure_filter.hpp"
#include "poly/machine_polynomial.hpp"
#include "poly/sturm.hpp"

namespace kmr::poly {
namespace {

using M = MachinePolynomial;

// A random value of up to `bits` bits, as __int128 and as Integer (built independently: decimal text).
__int128 random_value(std::mt19937_64& rng, int bits) {
  unsigned __int128 u = (static_cast<unsigned __int128>(rng()) << 64) | rng();
  int b = static_cast<int>(rng() % static_cast<unsigned>(bits + 1));
  __int128 v = b == 0 ? 0 : static_cast<__int128>(u >> (128 - b));  // 0 ≤ v < 2^b ≤ 2^126
  return rng() % 2 ? -v : v;
}
Integer reference(__int128 v) {
  bool neg = v < 0;
  unsigned __int128 m = neg ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  std::string digits;
  do {
    digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(m % 10)));
    m /= 10;
  } while (m);
  return Integer((neg ? "-" : "") + digits);
}
Polynomial reference(const std::vector<__int128>& c) {
  std::vector<Integer> v;
  for (__int128 x : c) v.push_back(reference(x));
  return Polynomial(v);
}
M machine(const std::vector<__int128>& c) {
  M p;
  for (std::size_t i = 0; i < c.size(); ++i) {
    M term(c[i]);
    for (std::size_t k = 0; k < i; ++k) term = term * M::linear(0, 1);
    p = p + term;
  }
  return p;
}

TEST(MachinePolynomial, ToIntegerAtTheExtremes) {
  const __int128 max = static_cast<__int128>((static_cast<unsigned __int128>(1) << 127) - 1);
  EXPECT_EQ(to_integer(max), (Integer(1) << 127) - 1);
  EXPECT_EQ(to_integer(-max - 1), -(Integer(1) << 127));
  EXPECT_EQ(to_integer(0), Integer(0));
  EXPECT_EQ(to_integer(-1), Integer(-1));
  EXPECT_EQ(to_integer(static_cast<__int128>(1) << 64), Integer(1) << 64);
  std::mt19937_64 rng(1);
  for (int i = 0; i < 2000; ++i) {
    __int128 v = random_value(rng, 126);
    ASSERT_EQ(to_integer(v), reference(v));
  }
}

// approximations() rounds each coefficient to nearest (issue 9: a 64-bit conversion when it fits):
// judged by the 128-bit library conversion, and below 2^63 also by long double (64-bit mantissa:
// exact, then one rounding), around the 2^53 and 2^63 boundaries and on random magnitudes.
TEST(MachinePolynomial, ApproximationsRoundToNearest) {
  auto check = [](__int128 v) {
    const double got = M::to_double(v);
    ASSERT_EQ(got, static_cast<double>(v)) << static_cast<long double>(v);
    if (v > -(static_cast<__int128>(1) << 63) && v < (static_cast<__int128>(1) << 63))
      ASSERT_EQ(got, static_cast<double>(static_cast<long double>(static_cast<long long>(v))));
  };
  for (int e : {52, 53, 54, 62, 63, 64, 100, 126})
    for (int d = -3; d <= 3; ++d) {
      const __int128 b = (static_cast<__int128>(1) << e) + d;
      check(b), check(-b), check(b - 1 + (static_cast<__int128>(1) << (e - 1)));  // halfway-ish
    }
  check((static_cast<__int128>(1) << 53) + 1);  // a tie: rounds to even (2^53)
  EXPECT_EQ(M::to_double((static_cast<__int128>(1) << 53) + 1), 0x1p53);
  EXPECT_EQ(M::to_double((static_cast<__int128>(1) << 53) + 3), 0x1p53 + 4);
  // Ties and near-ties far above 2^64 (the sticky bit): (2^53 + 1)·2^k is a tie (rounds to even),
  // one more is above it, one less below; the same with an odd mantissa 2^53 + 3.
  for (int k = 1; k <= 73; ++k)
    for (__int128 m : {(static_cast<__int128>(1) << 53) + 1, (static_cast<__int128>(1) << 53) + 3})
      for (int d = -1; d <= 1; ++d) check((m << k) + d), check(-((m << k) + d));
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) check(random_value(rng, 1 + static_cast<int>(rng() % 126)));
  const __int128 max = static_cast<__int128>((static_cast<unsigned __int128>(1) << 127) - 1);
  check(max), check(-max), check(-max - 1);
  const M p = M::cubic_terms(static_cast<__int128>(1) << 100, -((static_cast<__int128>(1) << 53) + 1)) + M::linear(5, -7);
  const auto a = p.approximations();
  EXPECT_EQ(a[0], 5.0);
  EXPECT_EQ(a[1], -7.0);
  EXPECT_EQ(a[2], 0x1p100);
  EXPECT_EQ(a[3], -0x1p53);
}

TEST(MachinePolynomial, ArithmeticIsPolynomialArithmetic) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 3000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 40);  // triple products stay below 2^123
    auto coeffs = [&](std::size_t n) {
      std::vector<__int128> c;
      for (std::size_t k = 0; k < n; ++k) c.push_back(random_value(rng, bits));
      return c;
    };
    auto a = coeffs(1 + rng() % 2), b = coeffs(1 + rng() % 2);  // degree ≤ 1: products of degree ≤ 2
    M ma = machine(a), mb = machine(b);
    Polynomial pa = reference(a), pb = reference(b);
    ASSERT_EQ(ma.to_polynomial(), pa);
    ASSERT_EQ((ma + mb).to_polynomial(), pa + pb);
    ASSERT_EQ((ma - mb).to_polynomial(), pa - pb);
    ASSERT_EQ((ma * mb).to_polynomial(), pa * pb);
    auto c = coeffs(2);
    ASSERT_EQ((ma * mb * machine(c)).to_polynomial(), pa * pb * reference(c));
    ASSERT_EQ((ma - ma).is_zero(), true);
    ASSERT_EQ((ma - ma).degree(), -1);
    std::vector<__int128> wide{random_value(rng, 125), random_value(rng, 125)}, wide2{random_value(rng, 125)};
    ASSERT_EQ((machine(wide) + machine(wide2)).to_polynomial(), reference(wide) + reference(wide2));
    ASSERT_EQ((machine(wide) - machine(wide2)).to_polynomial(), reference(wide) - reference(wide2));
  }
}

// The cubic fast path (the hull's orient3d cubics) against the generic sum it replaces and
// against Polynomial: the same coefficients and degree, zero coefficients (trimmed) included.
TEST(MachinePolynomial, CubicIsTheGenericSum) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 20000; ++i) {
    std::vector<__int128> c(4);
    for (auto& x : c) x = rng() % 3 == 0 ? 0 : random_value(rng, 1 + static_cast<int>(rng() % 123));
    const M fast = M::cubic(c[0], c[1], c[2], c[3]);
    const M generic = M::linear(c[0], c[1]) + M::cubic_terms(c[2], c[3]);
    ASSERT_EQ(fast, generic);
    ASSERT_EQ(fast.degree(), generic.degree());
    ASSERT_EQ(fast.to_polynomial(), reference(c));
    ASSERT_EQ(fast.is_zero(), c == std::vector<__int128>(4, 0));
  }
}

TEST(MachinePolynomial, OverflowAndHighDegreeAreRefused) {
  const M big(static_cast<__int128>(1) << 100);
  EXPECT_THROW(big * big, ContractError);
  const __int128 max = static_cast<__int128>((static_cast<unsigned __int128>(1) << 127) - 1);
  EXPECT_THROW(M(max) + M(1), ContractError);
  EXPECT_THROW(M(-max) - M(2), ContractError);
  const M t = M::linear(0, 1);
  EXPECT_THROW(t * t * t * t, ContractError);
  EXPECT_NO_THROW(t * t * t);
  // Just inside: 2^63 · 2^63 = 2^126 fits.
  EXPECT_EQ((M(static_cast<__int128>(1) << 63) * M(static_cast<__int128>(1) << 63)).to_polynomial(), Polynomial(Integer(1) << 126));
}

TEST(MachinePolynomial, FilterAndSignsDecideAsTheExactPath) {
  std::mt19937_64 rng(3);
  long long decided = 0, undecided = 0;
  for (int i = 0; i < 1500; ++i) {
    const int bits = static_cast<int>(rng() % 12);
    M p;
    Polynomial P;
    if (i % 3 == 0) {  // roots on lattice points and double roots: (4t − q1)(4t − q2)(4t − q3)·s
      std::uniform_int_distribution<long long> q(-40, 40);
      long long q1 = q(rng), q2 = rng() % 3 ? q(rng) : q1, q3 = q(rng);
      p = M::linear(-q1, 4) * M::linear(-q2, 4) * M::linear(-q3, 4) * M(rng() % 2 ? 1 : -(static_cast<__int128>(1) << 60));
    } else {
      std::vector<__int128> c;
      for (int k = 0; k < 4; ++k) c.push_back(random_value(rng, 40 + static_cast<int>(rng() % 80)));
      p = machine(c);
    }
    if (p.is_zero()) continue;
    P = p.to_polynomial();
    const std::int64_t a = static_cast<std::int64_t>(rng() % 4096) - 2048;
    const std::int64_t b = a + static_cast<std::int64_t>(rng() % (std::int64_t{1} << (4 + rng() % 34)));
    FailureFilterResult f = filtered_next_failure(p, bits, a, b);
    if (f.decided) {
      ++decided;
      LatticeRootSolver exact(P, bits);
      std::optional<Integer> e = exact.next_failure_after(Dyadic(Integer(a), -bits), Dyadic(Integer(b), -bits));
      ASSERT_EQ(f.failure.has_value(), e.has_value()) << P.to_string() << " bits " << bits;
      if (e) ASSERT_EQ(Integer(*f.failure), *e) << P.to_string() << " bits " << bits;
    } else {
      ++undecided;
    }
    for (std::int64_t k : {a, b, a + (b - a) / 2, std::int64_t{0}}) ASSERT_EQ(sign_before_lattice(p, k, bits), sign_before(P, Dyadic(Integer(k), -bits)));
  }
  EXPECT_GT(decided, 10 * undecided) << decided << " decided, " << undecided << " undecided";
}


// The lazy tests of failure_filter.hpp (issue 8/9) against Sturm counts on the converted Polynomial:
// root_free_until never claims a range [from·δ, w·δ] that holds a root or ends on one, and
// no_failure_from_zero never claims a polynomial with a root in [0, ∞). Families: random
// coefficients (40–122 bits), products of linear factors with roots at, just after and within a
// few 2^−e of from·δ (simple and double), and the same scaled to coefficients near 2^122.
TEST(MachinePolynomial, LazyTestsNeverClaimARootFreeRangeThatHoldsARoot) {
  std::mt19937_64 rng(2026);
  long long windows = 0, none = 0, descartes = 0, descartes_checked = 0;
  for (int i = 0; i < 6000; ++i) {
    const int bits = static_cast<int>(rng() % 16);
    const std::int64_t from = rng() % 4 == 0 ? 0 : static_cast<std::int64_t>(rng() % (std::uint64_t{1} << (rng() % 40)));
    M p;
    if (i % 2 == 0) {
      std::vector<__int128> c;
      for (int k = 0; k < 4; ++k) c.push_back(random_value(rng, 40 + static_cast<int>(rng() % 83)));
      p = machine(c);
    } else {  // roots near from·δ: (2^e·t − (from·2^(e−bits) + d)), e − bits ≤ 12
      const int factors = 1 + static_cast<int>(rng() % 3);
      p = M(1);
      for (int j = 0; j < factors; ++j) {
        const int e = bits + static_cast<int>(rng() % 13);
        const __int128 num = (static_cast<__int128>(from) << (e - bits)) + static_cast<__int128>(rng() % 9) - 2;
        M f = M::linear(-num, static_cast<__int128>(1) << e);
        if (!M::fits(num, 38) || p.degree() + 1 > 3) break;  // keeps every product below 2^120
        p = p * f;
      }
      if (rng() % 3 == 0 && p.degree() < 3) p = p * M::linear(static_cast<__int128>(rng() % 1000) + 1, 1);  // a negative root
      if (rng() % 4 == 0) {  // scale towards 2^122
        __int128 top = 0;
        for (int k = 0; k <= p.degree(); ++k) top = std::max(top, p[k] < 0 ? -p[k] : p[k]);
        int b = 0;
        while (b < 126 && (static_cast<__int128>(1) << b) <= top) ++b;
        if (b < 120) p = p * M((static_cast<__int128>(1) << (120 - b)) - static_cast<__int128>(rng() % 3));
      }
    }
    if (p.is_zero()) continue;
    const Polynomial P = p.to_polynomial();
    LatticeRootSolver exact(P, bits);
    const std::int64_t last = from + static_cast<std::int64_t>(rng() % (std::uint64_t{1} << (1 + rng() % 40)));
    const std::int64_t w = root_free_until(p, bits, from, last);
    ASSERT_GE(w, from);
    ASSERT_LE(w, last);
    if (w > from) {
      ++windows;
      const Dyadic lo(Integer(from), -bits), hi(Integer(w), -bits);
      ASSERT_EQ(exact.count_roots(lo, hi), 0) << P.to_string() << " bits " << bits << " [" << from << ", " << w << "]";
      ASSERT_NE(P.sign_at(hi), 0) << P.to_string() << " bits " << bits << " [" << from << ", " << w << "]";
      ASSERT_FALSE(exact.next_failure_after(lo, hi)) << P.to_string();
    } else {
      ++none;
    }
    if (no_failure_from_zero(p)) {
      ++descartes;
      ASSERT_NE(P.sign_at(Dyadic(0)), 0) << P.to_string();
      ASSERT_EQ(exact.count_roots(Dyadic(0), Dyadic(Integer(1), 200)), 0) << P.to_string();  // every root is < 2^130
    }
    ++descartes_checked;
  }
  // Tests that never prove anything would pass the comparisons: both must answer often.
  EXPECT_GT(windows, 1000) << windows << " windows, " << none << " none";
  EXPECT_GT(none, 300);
  EXPECT_GT(descartes, 300) << descartes << " of " << descartes_checked;
}

}  // namespace
}  // namespace kmr::poly
