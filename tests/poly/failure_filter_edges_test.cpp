// The failure filter's bad queries and degenerate polynomials (issue 13 §2), each against a
// hand-derived answer: contract refusals (zero polynomial, lattice bits beyond 62, indices beyond
// 2^62, an approximation of another polynomial, an empty root_free_until range); constants and
// linear certificates through the any-degree MachinePolynomial filter; a root bound beyond 2^61
// lattice steps (the query is not shrunk); degrees above the filter's 15 (left to the exact path);
// root_free_until where the only correct answer is `from` (a root at or just after from·δ, the zero
// polynomial, a negative `from` with a root to its right) or the whole horizon (no root at all);
// sign_before_lattice at 0 and on roots that the double evaluation cannot decide.
#include <gtest/gtest.h>

#include <cstdint>

#include "exact/dyadic.hpp"
#include "exact/error.hpp"
#include "poly/failure_filter.hpp"
#include "poly/machine_polynomial.hpp"
#include "small_polynomial.hpp"

namespace kmr::poly {
namespace {

using M = MachinePolynomial;
using testing::P;
constexpr std::int64_t k2_62 = std::int64_t{1} << 62;

TEST(FailureFilterEdges, BadQueriesAreRefused) {
  const Polynomial p = P({-8, 0, 0, 1});  // t³ − 8
  const DoubleCoefficients a = double_coefficients(p);
  EXPECT_THROW(filtered_next_failure(Polynomial(), double_coefficients(Polynomial()), 0, 0, 1), ContractError);
  EXPECT_THROW(filtered_next_failure(p, a, -1, 0, 1), ContractError);
  EXPECT_THROW(filtered_next_failure(p, a, 63, 0, 1), ContractError);
  EXPECT_NO_THROW(filtered_next_failure(p, a, 62, 0, 1));
  // Each end of each index at ±2^62 (excluded) and just inside.
  EXPECT_THROW(filtered_next_failure(p, a, 0, -k2_62, 0), ContractError);
  EXPECT_THROW(filtered_next_failure(p, a, 0, k2_62, k2_62 - 1), ContractError);
  EXPECT_THROW(filtered_next_failure(p, a, 0, 0, -k2_62), ContractError);
  EXPECT_THROW(filtered_next_failure(p, a, 0, 0, k2_62), ContractError);
  EXPECT_NO_THROW(filtered_next_failure(p, a, 0, -k2_62 + 1, k2_62 - 1));
  // An approximation of a polynomial of another degree: refused (it would read past the end).
  EXPECT_THROW(filtered_next_failure(p, double_coefficients(P({1, 1})), 0, 0, 5), ContractError);
  // The machine overload and root_free_until check the same query limits.
  const M m = M::cubic(-8, 0, 0, 1);
  EXPECT_THROW(filtered_next_failure(M(), 0, 0, 1), ContractError);
  EXPECT_THROW(filtered_next_failure(m, 63, 0, 1), ContractError);
  EXPECT_THROW(filtered_next_failure(m, -1, 0, 1), ContractError);
  EXPECT_THROW(filtered_next_failure(m, 0, 0, k2_62), ContractError);
  EXPECT_THROW(filtered_next_failure(m, 0, -k2_62, 0), ContractError);
  EXPECT_THROW(root_free_until(m, 0, 5, 4), ContractError);  // from > last: an empty range
  EXPECT_THROW(root_free_until(m, 70, 0, 4), ContractError);
  EXPECT_THROW(root_free_until(m, 0, 0, k2_62), ContractError);
  EXPECT_THROW(sign_before_lattice(M(), 3, 0), ContractError);
}

// Degrees 0 and 1 go through the any-degree instantiation of the machine filter (the kinetic hull
// uses 2 and 3): a constant never fails; c1·t + c0 fails in the lattice interval holding −c0/c1.
TEST(FailureFilterEdges, MachineConstantsAndLinearCertificates) {
  for (int bits : {0, 3, 62}) {
    FailureFilterResult f = filtered_next_failure(M(-7), bits, -1000, 1000);
    EXPECT_TRUE(f.decided && !f.failure) << bits;
  }
  // 2t − 6: root 3, on a lattice point for every bits: interval 3·2^b (the one the root starts).
  for (int bits : {0, 1, 5}) {
    FailureFilterResult f = filtered_next_failure(M::linear(-6, 2), bits, -100, 1000);
    ASSERT_TRUE(f.decided && f.failure) << bits;
    EXPECT_EQ(*f.failure, std::int64_t{3} << bits);
  }
  // −4t + 10: root 5/2, mid-interval at bits 0 (interval 2), on a lattice point at bits 1 (5).
  FailureFilterResult f = filtered_next_failure(M::linear(10, -4), 0, -5, 5);
  ASSERT_TRUE(f.decided && f.failure);
  EXPECT_EQ(*f.failure, 2);
  f = filtered_next_failure(M::linear(10, -4), 1, -5, 50);
  ASSERT_TRUE(f.decided && f.failure);
  EXPECT_EQ(*f.failure, 5);
  // The range starts past the root, or ends at it (the root's interval is outside [a, b)): none.
  f = filtered_next_failure(M::linear(10, -4), 1, 6, 50);
  EXPECT_TRUE(f.decided && !f.failure);
  f = filtered_next_failure(M::linear(10, -4), 1, -50, 5);
  EXPECT_TRUE(f.decided && !f.failure);
}

// t − 2^45 at bits 16: the root is lattice point 2^61, so Fujiwara's bound (2·2^45·2^16 > 2^61
// lattice steps) does not fit and the query is searched unshrunk. Interval 2^61 is the failure.
TEST(FailureFilterEdges, RootBoundBeyondTheIndexRange) {
  const std::int64_t root = std::int64_t{1} << 61;
  const Polynomial p(std::vector<Integer>{-(Integer(1) << 45), Integer(1)});
  for (std::int64_t a : {root - 10, -k2_62 + 1}) {
    FailureFilterResult f = filtered_next_failure(p, double_coefficients(p), 16, a, k2_62 - 1);
    ASSERT_TRUE(f.decided && f.failure);
    EXPECT_EQ(*f.failure, root);
    f = filtered_next_failure(M::linear(-(static_cast<__int128>(1) << 45), 1), 16, a, k2_62 - 1);
    ASSERT_TRUE(f.decided && f.failure);
    EXPECT_EQ(*f.failure, root);
  }
  FailureFilterResult f = filtered_next_failure(p, double_coefficients(p), 16, root + 1, k2_62 - 1);
  EXPECT_TRUE(f.decided && !f.failure);
}

// Degree 16 (t^16 − 1, roots ±1): beyond the filter's degrees, so it must leave every query to the
// exact path; degree 15 (t^15 − 1, root 1) is decided: the failure is interval 1·2^b.
TEST(FailureFilterEdges, DegreesAboveFifteenAreLeftToTheExactPath) {
  std::vector<Integer> c16(17, Integer(0)), c15(16, Integer(0));
  c16[0] = -1, c16[16] = 1, c15[0] = -1, c15[15] = 1;
  const Polynomial p16(c16), p15(c15);
  EXPECT_FALSE(filtered_next_failure(p16, double_coefficients(p16), 2, -100, 100).decided);
  EXPECT_FALSE(filtered_next_failure(p16, double_coefficients(p16), 2, 10, 100).decided);
  FailureFilterResult f = filtered_next_failure(p15, double_coefficients(p15), 2, -100, 100);
  ASSERT_TRUE(f.decided && f.failure);
  EXPECT_EQ(*f.failure, 4);
}

// root_free_until(p, bits, from, last) = w promises no root of p in [from·δ, w·δ]. Where a root
// lies at or within one lattice step after from·δ, w = from is the only correct answer.
TEST(FailureFilterEdges, RootFreeUntilWhereOnlyFromIsCorrect) {
  EXPECT_EQ(root_free_until(M(), 0, 3, 10), 3);                  // the zero polynomial: roots everywhere
  EXPECT_EQ(root_free_until(M::linear(-5, 1), 0, 5, 100), 5);    // t − 5 at from = 5: p(from·δ) = 0
  EXPECT_EQ(root_free_until(M::linear(-5, 1), 3, 40, 100), 40);  // the same root at bits 3 (5 = 40·2^−3)
  EXPECT_EQ(root_free_until(M::cubic(0, -1, 0, 1), 0, 0, 9), 0); // t³ − t: a root at 0
  // 2^100·t − (5·2^100 + 1): the root 5 + 2^−100 lies inside [5, 6), far below one lattice step.
  const __int128 e100 = static_cast<__int128>(1) << 100;
  EXPECT_EQ(root_free_until(M::linear(-(5 * e100 + 1), e100), 0, 5, 1000), 5);
  EXPECT_EQ(root_free_until(M::linear(-(5 * e100 + 1), e100), 30, std::int64_t{5} << 30, std::int64_t{6} << 30),
            std::int64_t{5} << 30);
  // A range of one point: nothing to prove.
  EXPECT_EQ(root_free_until(M(4), 0, 7, 7), 7);
  // t² − 4 from t = −3 (bits 4: from = −48): the root −2 (lattice point −32) lies to the right, so
  // w < −32; the window bounds assume from·δ ≥ 0 (they would shrink with a negative A).
  const std::int64_t w = root_free_until(M::cubic(-4, 0, 1, 0), 4, -48, 1000);
  EXPECT_GE(w, -48);
  EXPECT_LT(w, -32);
}

// Where p has no root in [from·δ, ∞) at all and the horizon is within reach, the whole horizon is
// proven: a nonzero constant, and t + 2^100 (its root −2^100, every Taylor term tiny against p(0)).
TEST(FailureFilterEdges, RootFreeUntilProvesTheWholeHorizonWithoutRoots) {
  EXPECT_EQ(root_free_until(M(-3), 5, 2, 1000), 1000);
  EXPECT_EQ(root_free_until(M::linear(static_cast<__int128>(1) << 100, 1), 0, 0, std::int64_t{1} << 50), std::int64_t{1} << 50);
  EXPECT_EQ(root_free_until(M::linear(static_cast<__int128>(1) << 100, 1), 10, 1000, 1 << 20), 1 << 20);
  // (t − 1000)² + 1 > 0, from t = 0 at bits 0 (p(0) = 10^6 + 1): a window, and never past a root
  // (there is none), so any w in (0, last] is right; w > 0 here because p'(t) ≤ 2000 keeps p > 0
  // on [0, 2^8] by the Taylor bound with room to spare.
  const std::int64_t w = root_free_until(M::cubic(1000001, -2000, 1, 0), 0, 0, 1 << 20);
  EXPECT_GT(w, 0);
  EXPECT_LE(w, 1 << 20);
}

// sign_before_lattice(p, k, bits) = sign of p just left of kδ: at k = 0 it is sign c0 when c0 ≠ 0;
// on a root, the first nonvanishing derivative decides, which doubles cannot (p(kδ) = 0 exactly).
TEST(FailureFilterEdges, SignBeforeLatticeAtZeroAndOnRoots) {
  EXPECT_EQ(sign_before_lattice(M::cubic(-3, 100, 0, 5), 0, 7), -1);
  EXPECT_EQ(sign_before_lattice(M::cubic(3, -100, 0, -5), 0, 7), 1);
  // t² − t: a root at 0, negative slope: positive just before 0.
  EXPECT_EQ(sign_before_lattice(M::cubic(0, -1, 1, 0), 0, 0), 1);
  // (t − 3)³ = t³ − 9t² + 27t − 27: negative before 3 (an odd triple root), positive before 4.
  const M cube = M::cubic(-27, 27, -9, 1);
  EXPECT_EQ(sign_before_lattice(cube, 3, 0), -1);
  EXPECT_EQ(sign_before_lattice(cube, 12, 2), -1);
  EXPECT_EQ(sign_before_lattice(cube, 4, 0), 1);
  // (t − 3)² (t + 1) = t³ − 5t² + 3t + 9: positive on both sides of the double root 3.
  const M touch = M::cubic(9, 3, -5, 1);
  EXPECT_EQ(sign_before_lattice(touch, 3, 0), 1);
  EXPECT_EQ(sign_before_lattice(touch, 6, 1), 1);
  EXPECT_EQ(sign_before_lattice(touch, -1, 0), -1);  // a simple root at −1, increasing: − before it
  // Quadratic (the any-degree evaluation): 4t² − 1 at its roots ±1/2 (bits 1: k = ±1).
  const M q = M::cubic(-1, 0, 4, 0);
  EXPECT_EQ(sign_before_lattice(q, 1, 1), -1);
  EXPECT_EQ(sign_before_lattice(q, -1, 1), 1);
}

}  // namespace
}  // namespace kmr::poly
