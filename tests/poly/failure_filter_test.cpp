// The double filter for next failure intervals (poly/failure_filter.hpp) against the exact Sturm
// path (LatticeRootSolver::next_failure_after), which shares no arithmetic with it beyond the
// polynomial's coefficients: whenever the filter decides, it decides the same; on random cubics it
// decides most queries; degenerate cubics (double and triple roots, roots on lattice points, roots
// closer than δ) are decided the same or left to the exact path.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "exact/error.hpp"
#include "poly/failure_filter.hpp"
#include "poly/sturm.hpp"
#include "small_polynomial.hpp"

namespace kmr::poly {
namespace {

using testing::P;

struct Tally {
  long long decided = 0, undecided = 0;
};

// Compares the filter with the exact path on [a, b); returns whether the filter decided.
bool same_decision(const Polynomial& p, int bits, std::int64_t a, std::int64_t b, Tally& t) {
  FailureFilterResult f = filtered_next_failure(p, double_coefficients(p), bits, a, b);
  if (!f.decided) {
    ++t.undecided;
    return false;
  }
  ++t.decided;
  LatticeRootSolver exact(p, bits);
  std::optional<Integer> e = exact.next_failure_after(Dyadic(Integer(a), -bits), Dyadic(Integer(b), -bits));
  EXPECT_EQ(f.failure.has_value(), e.has_value()) << p.to_string() << " bits " << bits << " [" << a << ", " << b << ")";
  if (f.failure && e) {
    EXPECT_EQ(Integer(*f.failure), *e) << p.to_string() << " bits " << bits << " [" << a << ", " << b << ")";
  }
  return true;
}

// scale·(4t − q1)(4t − q2)(4t − q3): roots q_i / 4 (lattice points when bits = 2).
Polynomial cubic_with_roots(long long q1, long long q2, long long q3, long long scale) {
  return P({-q1, 4}) * P({-q2, 4}) * P({-q3, 4}) * P({scale});
}

TEST(FailureFilter, RandomCubicsDecideAsTheExactPath) {
  std::mt19937_64 rng(8);
  Tally t;
  for (int i = 0; i < 3000; ++i) {
    std::uniform_int_distribution<long long> c(-(1 << 20), 1 << 20);
    int deg = 1 + static_cast<int>(rng() % 3);
    std::vector<Integer> coeffs;
    for (int j = 0; j <= deg; ++j) coeffs.emplace_back(c(rng));
    Polynomial p(coeffs);
    if (p.is_zero()) continue;
    int bits = static_cast<int>(rng() % 12);
    std::int64_t a = static_cast<std::int64_t>(rng() % 4096) - 2048;
    std::int64_t b = a + static_cast<std::int64_t>(rng() % (std::int64_t{1} << (10 + rng() % 30)));
    same_decision(p, bits, a, b, t);
  }
  // A filter that never decides would pass the comparisons: it must decide nearly everything here.
  EXPECT_GT(t.decided, 20 * t.undecided) << t.decided << " decided, " << t.undecided << " undecided";
}

TEST(FailureFilter, DegenerateCubicsDecideAsTheExactPathOrFallBack) {
  // Roots at q/4 with bits = 2: q are lattice indices, so roots fall on lattice points; with bits 1
  // odd q are mid-interval; bits 0 puts several roots in one lattice interval.
  Tally t;
  std::mt19937_64 rng(3);
  for (int i = 0; i < 3000; ++i) {
    std::uniform_int_distribution<long long> q(-40, 40);
    long long q1 = q(rng), q2 = rng() % 3 == 0 ? q1 : q(rng), q3 = rng() % 4 == 0 ? q2 : q(rng);
    long long scale = rng() % 2 ? 1 : -3;
    Polynomial p = cubic_with_roots(q1, q2, q3, scale);
    if (rng() % 5 == 0) p = p * P({static_cast<long long>(rng() % 7) + 1, 0, 1});  // a complex pair: degree 5
    int bits = static_cast<int>(rng() % 5);
    std::int64_t a = static_cast<std::int64_t>(rng() % 120) - 60;
    std::int64_t b = a + static_cast<std::int64_t>(rng() % 200);
    same_decision(p, bits, a, b, t);
  }
  EXPECT_GT(t.decided, 0);
  std::printf("degenerate: %lld decided, %lld left to the exact path\n", t.decided, t.undecided);
}

TEST(FailureFilter, RootsWithinRoundingOfALatticePointDecideAsTheExactPath) {
  // (2^e·t − (k·2^(e−b) + d)) · q(t): a root d·2^−e away from the lattice point kδ, with e up to 60,
  // so the enclosures' rounding (coefficients ≈ 2^60, values far beyond 2^53) decides whether the
  // filter wrongly excludes the root's range or puts it on the wrong side of kδ.
  std::mt19937_64 rng(5);
  Tally t;
  for (int i = 0; i < 2000; ++i) {
    int bits = static_cast<int>(rng() % 8), e = bits + 20 + static_cast<int>(rng() % (41 - bits));
    long long k = static_cast<long long>(rng() % 2000) - 1000, d = static_cast<long long>(rng() % 5) - 2;
    std::vector<Integer> lin{-(Integer(k) << (e - bits)) - d, Integer(1) << e};
    Polynomial p(lin);
    switch (rng() % 3) {
      case 0: p = p * P({1, 0, 1}); break;                                   // t² + 1
      case 1: p = p * P({static_cast<long long>(rng() % 100) - 50, 1}); break;  // another simple root
      default: p = p * P({-3, 0, static_cast<long long>(rng() % 7) + 1}); break;
    }
    std::int64_t a = k - static_cast<std::int64_t>(rng() % 3000), b = k + static_cast<std::int64_t>(rng() % 3000);
    same_decision(p, bits, a, b, t);
  }
  EXPECT_GT(t.decided, 10 * t.undecided) << t.decided << " decided, " << t.undecided << " undecided";
  // Lattice indices near 2^54…2^61 (bits 0): double(k) is rounded, by up to 2^8, so a range's end
  // can round past a root at k + 1/2 in its last lattice interval; only the widening keeps it in.
  Tally far;
  for (int i = 0; i < 2000; ++i) {
    std::int64_t k = static_cast<std::int64_t>((std::int64_t{1} << (54 + rng() % 7)) + static_cast<std::int64_t>(rng() % 100000));
    Polynomial p(std::vector<Integer>{-(Integer(2) * k + 1), Integer(2)});
    if (rng() % 2) p = p * P({1, 0, 1});
    std::int64_t r = static_cast<std::int64_t>(rng() % 1000);
    if (rng() % 2) same_decision(p, 0, k - r, k + 1, far);  // the root in the last interval
    else same_decision(p, 0, k, k + 1 + r, far);             // the root in the first interval
  }
  EXPECT_GT(far.decided, 10 * far.undecided) << far.decided << " decided, " << far.undecided << " undecided";
}

TEST(FailureFilter, HandPickedCases) {
  Tally t;
  // A double root at t = 1 (no sign change) and a simple one at t = 3: the failure is interval 3·2^b.
  Polynomial p = P({-1, 1}) * P({-1, 1}) * P({-3, 1});
  for (int bits : {0, 1, 4}) {
    FailureFilterResult f = filtered_next_failure(p, double_coefficients(p), bits, 0, 1000);
    if (f.decided) {
      ASSERT_TRUE(f.failure);
      EXPECT_EQ(*f.failure, 3 << bits);
    }
    same_decision(p, bits, 0, 1000, t);
  }
  // A root exactly on a lattice point belongs to the interval it starts: t³ − 8 fails in [2, 3).
  Polynomial q = P({-8, 0, 0, 1});
  FailureFilterResult f = filtered_next_failure(q, double_coefficients(q), 0, -5, 5);
  ASSERT_TRUE(f.decided);
  ASSERT_TRUE(f.failure);
  EXPECT_EQ(*f.failure, 2);
  // Starting past the only root: none.
  f = filtered_next_failure(q, double_coefficients(q), 0, 3, 1 << 20);
  ASSERT_TRUE(f.decided);
  EXPECT_FALSE(f.failure);
  // A constant never fails; an empty range has no failure.
  f = filtered_next_failure(P({-5}), double_coefficients(P({-5})), 3, 0, 100);
  EXPECT_TRUE(f.decided && !f.failure);
  f = filtered_next_failure(q, double_coefficients(q), 0, 2, 2);
  EXPECT_TRUE(f.decided && !f.failure);
  // Huge coefficients (beyond 2^1000) are not usable in doubles: undecided, never wrong.
  Polynomial huge(std::vector<Integer>{Integer(1) << 1100, Integer(-1)});
  EXPECT_FALSE(filtered_next_failure(huge, double_coefficients(huge), 0, 0, 10).decided);
}

TEST(FailureFilter, ProductsOfNearLatticeRootsAndNearCapCoefficientsDecideAsTheExactPath) {
  // Up to 6 linear factors (2^e·t − (k'·2^(e−b) + d)), some squared, times a complex pair, with
  // k' within 30 lattice steps of a centre k (|k| up to 2^8…2^61), δ = 2^0…2^−62, and sometimes
  // scaled to coefficients just below 2^1000 (the cap of double_coefficients): enclosures near
  // overflow and far beyond 2^53, roots on, within rounding of and within one step of lattice points.
  for (int kbmax : {8, 16, 30, 62}) {
    std::mt19937_64 rng(12345 + static_cast<unsigned>(kbmax));
    Tally t;
    for (int i = 0; i < 4000; ++i) {
      int bits = static_cast<int>(rng() % 63);
      bool on_lattice = rng() % 6 == 0, near_cap = rng() % 6 == 0;
      std::int64_t k = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << (rng() % static_cast<unsigned>(kbmax))));
      if (rng() % 2) k = -k;
      int factors = 1 + static_cast<int>(rng() % 6);
      Polynomial p(1);
      for (int j = 0; j < factors; ++j) {
        int e = bits + static_cast<int>(rng() % 20);
        std::int64_t off = static_cast<std::int64_t>(rng() % 61) - 30;
        long long d = on_lattice ? 0 : static_cast<long long>(rng() % 7) - 3;
        Integer num = (Integer(k + off) << static_cast<unsigned>(e - bits)) + Integer(d);
        Polynomial f(std::vector<Integer>{-num, Integer(1) << static_cast<unsigned>(e)});
        p = p * f;
        if (rng() % 4 == 0) p = p * f;
      }
      if (rng() % 3 == 0) p = p * P({static_cast<long long>(rng() % 7) + 1, 0, 1});
      if (near_cap) {
        std::int64_t top = 0;
        for (const auto& c : p.coefficients()) top = std::max(top, exact::bit_length(c));
        if (top < 1000) p = Polynomial(Integer(1) << static_cast<unsigned>(1000 - top - static_cast<std::int64_t>(rng() % 3))) * p;
      }
      if (p.degree() > 15) continue;
      const std::int64_t lim = (std::int64_t{1} << 62) - 1;
      std::int64_t a = std::max(-lim, k - static_cast<std::int64_t>(rng() % 80));
      std::int64_t b = std::min(lim, k + static_cast<std::int64_t>(rng() % 64));
      if (rng() % 4 == 0) b = std::min(lim, k + static_cast<std::int64_t>(rng() >> 3));
      if (a > b) std::swap(a, b);
      same_decision(p, bits, a, b, t);
    }
    EXPECT_GT(t.decided, 0);
    std::printf("indices to 2^%d: %lld decided, %lld left to the exact path\n", kbmax, t.decided, t.undecided);
  }
  // Two simple roots 1…2000 steps of 2^−e apart, maybe a third, scaled to coefficients near 2^1000.
  std::mt19937_64 rng(99);
  Tally t;
  for (int i = 0; i < 5000; ++i) {
    int bits = static_cast<int>(rng() % 63), e = bits + static_cast<int>(rng() % 40);
    std::int64_t k = static_cast<std::int64_t>(rng() % 4096) - 2048;
    Integer num = (Integer(k) << static_cast<unsigned>(e - bits)) + Integer(static_cast<long long>(rng() % 5) - 2);
    Integer gap(static_cast<long long>(rng() % 2000) + 1);
    Polynomial p = Polynomial(std::vector<Integer>{-num, Integer(1) << static_cast<unsigned>(e)}) *
                   Polynomial(std::vector<Integer>{-(num + gap), Integer(1) << static_cast<unsigned>(e)});
    if (rng() % 2) p = p * P({-1 - static_cast<long long>(rng() % 100), 1});
    std::int64_t top = 0;
    for (const auto& c : p.coefficients()) top = std::max(top, exact::bit_length(c));
    p = Polynomial((Integer(1) << static_cast<unsigned>(1000 - top)) - Integer(static_cast<long long>(rng() % 3))) * p;
    if (rng() % 2) p = -p;
    std::int64_t a = k - static_cast<std::int64_t>(rng() % 100), b = k + static_cast<std::int64_t>(rng() % 3000);
    same_decision(p, bits, a, b, t);
  }
  EXPECT_GT(t.decided, t.undecided / 4) << t.decided << " decided, " << t.undecided << " undecided";
}

// Enclosures that overflow to ±∞ (interval Horner's "whole line"): p = 2^100·(t − 3)·(t^14 + 2^854)
// has one real root, t = 3 (t^14 + 2^854 > 0), but a complex pair of modulus 2^61, so Fujiwara's
// bound (|c_1/c_15|^(1/14) = 2^61) does not shrink the query, and the enclosure of p over the whole
// range [0, 2^62) (2^100·2^(62·15) = 2^1030) is the entire line. The filter must split until the
// enclosures are finite and still find the failure at the root: sign_before(3) = −, sign_before of
// the next lattice point = +, so interval 3·2^bits (hand-derived, and the exact path's answer).
TEST(FailureFilter, OverflowingEnclosuresStillFindTheFailure) {
  const Integer e100 = Integer(1) << 100, e954 = Integer(1) << 954;
  std::vector<Integer> c(16, Integer(0));
  c[0] = -3 * e954;  // 2^100·(−3·2^854)
  c[1] = e954;       // 2^100·2^854
  c[14] = -3 * e100;
  c[15] = e100;
  Polynomial p(c);
  ASSERT_TRUE(p == P({-3, 1}) * Polynomial(std::vector<Integer>{Integer(1) << 854, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}) *
                       Polynomial(std::vector<Integer>{e100}));
  const DoubleCoefficients approx = double_coefficients(p);
  ASSERT_TRUE(approx.usable);
  const std::int64_t top = (std::int64_t{1} << 62) - 1;
  Tally t;
  for (int bits : {0, 4, 20}) {
    FailureFilterResult f = filtered_next_failure(p, approx, bits, 0, top);
    ASSERT_TRUE(f.decided) << "bits " << bits;
    ASSERT_TRUE(f.failure) << "bits " << bits;
    EXPECT_EQ(*f.failure, std::int64_t{3} << bits) << "bits " << bits;
    EXPECT_TRUE(same_decision(p, bits, 0, top, t));
    // From the left of the root across negative indices (p < 0 there; the enclosure of the far left overflows too).
    f = filtered_next_failure(p, approx, bits, -top, top);
    ASSERT_TRUE(f.decided && f.failure) << "bits " << bits;
    EXPECT_EQ(*f.failure, std::int64_t{3} << bits) << "bits " << bits;
    // Past the root there is no failure; every enclosure right of 3 overflows or excludes 0.
    f = filtered_next_failure(p, approx, bits, std::int64_t{4} << bits, top);
    if (f.decided) EXPECT_FALSE(f.failure) << "bits " << bits;
  }
}

// When the enclosure overflows on every range around the root, the filter may not guess: it
// leaves the query undecided (the caller's exact path answers). 2^900·t^14·(t − 2^60) at bits 0:
// near t = 2^60 every enclosure is beyond 2^1024; the exact path finds the failure at 2^60.
TEST(FailureFilter, EnclosuresOverflowingAtTheRootLeaveTheQueryUndecided) {
  std::vector<Integer> c(16, Integer(0));
  c[14] = -(Integer(1) << 960);
  c[15] = Integer(1) << 900;
  Polynomial p(c);
  const std::int64_t a = 1, b = std::int64_t{1} << 61;
  FailureFilterResult f = filtered_next_failure(p, double_coefficients(p), 0, a, b);
  EXPECT_FALSE(f.decided);
  LatticeRootSolver exact(p, 0);
  std::optional<Integer> e = exact.next_failure_after(Dyadic(Integer(a), 0), Dyadic(Integer(b), 0));
  ASSERT_TRUE(e);
  EXPECT_EQ(*e, Integer(1) << 60);
}

TEST(FailureFilter, ContractViolationsAreRefused) {
  // The proof needs the range inside |a|, |b| < 2^62 (b − a < 2^63, no signed overflow) and the
  // double coefficients of p (at least as many as p has coefficients, as filtered_sign_at checks).
  Polynomial q = P({-8, 0, 0, 1});
  const std::int64_t big = std::int64_t{1} << 62;
  EXPECT_THROW((void)filtered_next_failure(q, double_coefficients(q), 0, -big, 5), ContractError);
  EXPECT_THROW((void)filtered_next_failure(q, double_coefficients(q), 0, 0, big), ContractError);
  EXPECT_THROW((void)filtered_next_failure(q, double_coefficients(q), 0, std::numeric_limits<std::int64_t>::min(),
                                           std::numeric_limits<std::int64_t>::max()),
               ContractError);
  Polynomial shorter = P({-8, 1});
  EXPECT_THROW((void)filtered_next_failure(q, double_coefficients(shorter), 0, -5, 5), ContractError);
  // In range: fine.
  EXPECT_TRUE(filtered_next_failure(q, double_coefficients(q), 0, -(big - 1), big - 1).decided);
}

}  // namespace
}  // namespace kmr::poly
