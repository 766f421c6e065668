// Unit tests of SturmSequence and LatticeRootSolver against hand-derived sequences and roots.
#include <gtest/gtest.h>

#include "exact/error.hpp"
#include "poly/sturm.hpp"
#include "small_polynomial.hpp"

namespace {
using kmr::InputError;
using kmr::exact::Dyadic;
using kmr::exact::Integer;
using namespace kmr::poly;

using kmr::poly::testing::P;

TEST(Sturm, A2_1_HandDerivedSequence) {
  RecordProperty("claim", "A2.1-sturm-count");
  // p = t³ − 3t + 1: p' = 3t² − 3, −rem(p, p') = 2t − 1, −rem(p', 2t − 1) = −p'(1/2) = 9/4.
  SturmSequence s(P({1, -3, 0, 1}));
  const auto& m = s.members();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0], P({1, -3, 0, 1}));
  EXPECT_EQ(m[1], P({-3, 0, 3}));
  ASSERT_EQ(m[2].degree(), 1);
  EXPECT_GT(m[2][1], 0);                 // a positive multiple of 2t − 1
  EXPECT_EQ(m[2][1], Integer(-2) * m[2][0]);
  ASSERT_EQ(m[3].degree(), 0);
  EXPECT_GT(m[3][0], 0);
  EXPECT_EQ(s.variations_at_minus_infinity(), 3);
  EXPECT_EQ(s.variations_at_plus_infinity(), 0);
  EXPECT_EQ(s.distinct_real_roots(), 3);  // roots ≈ −1.879, 0.347, 1.532
  EXPECT_EQ(s.roots_below(Dyadic(0)), 1);
  EXPECT_EQ(s.roots_below(Dyadic(1)), 2);
  EXPECT_EQ(s.count_roots(Dyadic(0), Dyadic(1)), 1);
  EXPECT_EQ(s.count_roots(Dyadic(-2), Dyadic(2)), 3);
  EXPECT_EQ(s.count_roots(Dyadic::parse("0.34"  "375"), Dyadic::parse("0.375")), 1);  // 0.34375 < 0.3473 < 0.375
  EXPECT_EQ(s.variations_at(Dyadic(0)), 2);  // signs +, −, −, +
}

TEST(Sturm, A2_1_SignTrapNegativeLeadingOddDegreeDifference) {
  RecordProperty("claim", "A2.1-sturm-count");
  // p = t⁴ + t − 1: p' = 4t³ + 1; −rem(p, p') = −(3/4)t + 1 has a negative leading coefficient and
  // degree 3 − 1 = 2 below p', so prem(p', ·) carries lc³ < 0. The true next member is
  // −rem(p', −(3/4)t + 1) = −p'(4/3) = −283/27 < 0.
  SturmSequence s(P({-1, 1, 0, 0, 1}));
  const auto& m = s.members();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].degree(), 1);
  EXPECT_LT(m[2][1], 0);
  EXPECT_EQ(Integer(3) * m[2][0], Integer(-4) * m[2][1]);  // ∝ −3t + 4
  ASSERT_EQ(m[3].degree(), 0);
  EXPECT_LT(m[3][0], 0);
  EXPECT_EQ(s.distinct_real_roots(), 2);
  EXPECT_EQ(s.count_roots(Dyadic(0), Dyadic(1)), 1);   // ≈ 0.7245
  EXPECT_EQ(s.count_roots(Dyadic(-2), Dyadic(-1)), 1);  // ≈ −1.2207
  // Negating p (negative leading coefficient, even degree) or mirroring it changes no count.
  EXPECT_EQ(SturmSequence(-P({-1, 1, 0, 0, 1})).distinct_real_roots(), 2);
  EXPECT_EQ(SturmSequence(P({-1, 1, 0, 0, 1}).mirrored()).count_roots(Dyadic(-1), Dyadic(0)), 1);
  // Odd degree, negative leading coefficient: −(t³ − 3t + 1) still has 3 roots.
  EXPECT_EQ(SturmSequence(-P({1, -3, 0, 1})).distinct_real_roots(), 3);
}

TEST(Sturm, A2_1_CountsDistinctRootsOfMultipleRoots) {
  RecordProperty("claim", "A2.1-sturm-count");
  Polynomial p = P({-1, 1}) * P({-1, 1}) * P({-2, 1}) * P({-2, 1}) * P({-2, 1}) * P({1, 0, 1});  // (t−1)²(t−2)³(t²+1)
  SturmSequence s(p);
  EXPECT_EQ(s.square_free(), P({2, -3, 1}) * P({1, 0, 1}));
  EXPECT_EQ(s.distinct_real_roots(), 2);
  EXPECT_EQ(s.roots_below(Dyadic(1)), 0);  // the root at 1 is not below 1
  EXPECT_EQ(s.roots_below(Dyadic(2)), 1);
  EXPECT_EQ(s.count_roots(Dyadic(1), Dyadic(2)), 1);  // [1, 2)
  EXPECT_EQ(SturmSequence(Polynomial(5)).distinct_real_roots(), 0);
  EXPECT_EQ(SturmSequence(P({1, 0, 1})).distinct_real_roots(), 0);
  EXPECT_THROW((void)SturmSequence{Polynomial()}, InputError);
}

TEST(LatticeRootSolver, A2_1_IsolationHandDerived) {
  RecordProperty("claim", "A2.1-lattice-isolation");
  Polynomial p = P({-1, 1}) * P({-1, 1}) * P({-2, 1}) * P({-2, 1}) * P({-2, 1});  // (t−1)²(t−2)³
  LatticeRootSolver s0(p, 0);
  auto all = s0.isolate(Dyadic(-100), Dyadic(100));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0], (LatticeInterval{Integer(1), 1, false}));
  EXPECT_EQ(all[1], (LatticeInterval{Integer(2), 1, true}));
  EXPECT_EQ(s0.isolate(Dyadic(1), Dyadic(2)).size(), 1u);                     // root at T1 excluded
  EXPECT_EQ(s0.isolate(Dyadic::parse("1.5"), Dyadic(3)).size(), 1u);          // k starts at 2
  EXPECT_TRUE(s0.isolate(Dyadic(3), Dyadic(1)).empty());
  // δ = 2^−1: the root 1 is the lattice point k = 2, the root 2 is k = 4.
  LatticeRootSolver s1(p, 1);
  auto half = s1.isolate(Dyadic(0), Dyadic(3));
  ASSERT_EQ(half.size(), 2u);
  EXPECT_EQ(half[0].k, Integer(2));
  EXPECT_EQ(half[1].k, Integer(4));
  // A cluster closer than δ: roots 1/8 and 1/4 share [0, 1/2) when δ = 1/2; separate when δ = 1/16.
  Polynomial c = P({-1, 8}) * P({-1, 4});
  auto merged = LatticeRootSolver(c, 1).isolate(Dyadic(-1), Dyadic(1));
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0], (LatticeInterval{Integer(0), 2, false}));  // two simple roots: no net change
  auto split = LatticeRootSolver(c, 4).isolate(Dyadic(-1), Dyadic(1));
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0], (LatticeInterval{Integer(2), 1, true}));
  EXPECT_EQ(split[1], (LatticeInterval{Integer(4), 1, true}));
  // Negative roots: −5/2 lies in [−3, −2) for δ = 1 and is the lattice point −5 for δ = 1/2.
  EXPECT_EQ(LatticeRootSolver(P({5, 2}), 0).isolate(Dyadic(-10), Dyadic(10))[0].k, Integer(-3));
  EXPECT_EQ(LatticeRootSolver(P({5, 2}), 1).isolate(Dyadic(-10), Dyadic(10))[0].k, Integer(-5));
  EXPECT_TRUE(LatticeRootSolver(Polynomial(3), 5).isolate(Dyadic(-10), Dyadic(10)).empty());
  EXPECT_THROW((void)LatticeRootSolver(p, -1), InputError);
  EXPECT_THROW((void)LatticeRootSolver(Polynomial(), 3), InputError);
}

TEST(LatticeRootSolver, A2_1_NextFailureHandDerived) {
  RecordProperty("claim", "A2.1-next-failure");
  Polynomial p = P({-1, 1}) * P({-1, 1}) * P({-2, 1}) * P({-2, 1}) * P({-2, 1});  // (t−1)²(t−2)³
  LatticeRootSolver s(p, 0);
  EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(10)), Integer(2));  // the double root at 1 is no failure
  EXPECT_EQ(s.next_failure_after(Dyadic(2), Dyadic(10)), Integer(2));  // a root at t itself counts
  EXPECT_EQ(s.next_failure_after(Dyadic::parse("2.5"), Dyadic(10)), std::nullopt);
  EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(2)), std::nullopt);  // horizon excludes k = 2
  EXPECT_EQ(s.sign_before_lattice(Integer(1)), -1);
  EXPECT_EQ(s.sign_before_lattice(Integer(2)), -1);
  EXPECT_EQ(s.sign_before_lattice(Integer(3)), 1);
  EXPECT_FALSE(s.sign_changes_across(Integer(1)));
  EXPECT_TRUE(s.sign_changes_across(Integer(2)));
  // A cluster with odd total multiplicity is a failure: (8t − 1)(4t − 1)² in [0, 1/2).
  Polynomial c = P({-1, 8}) * P({-1, 4}) * P({-1, 4});
  EXPECT_EQ(LatticeRootSolver(c, 1).next_failure_after(Dyadic(0), Dyadic(1)), Integer(0));
  EXPECT_EQ(LatticeRootSolver(c, 4).next_failure_after(Dyadic(0), Dyadic(1)), Integer(2));
  EXPECT_EQ(lattice_ceil(Dyadic::parse("-2.5"), 1), Integer(-5));
  EXPECT_EQ(lattice_ceil(Dyadic::parse("0.375"), 2), Integer(2));
  EXPECT_EQ(lattice_ceil(Dyadic::parse("-0.375"), 2), Integer(-1));
  EXPECT_GT(s.sturm_queries, 0);
  // zero_fails: an interval starting at a root after t ends the search too, with or without a sign
  // change across it — here the double root at 1, first; a root at t itself does not (from 1: the
  // triple root at 2, a sign change). (t − 1)(8t − 9): roots 1 and 9/8 in one interval [1, 5/4) of
  // 2^−2, no sign change anywhere, so no failure without zero_fails and interval 4 with it.
  // (8t − 1)(4t − 1)² at 2^−2: the sign change in [0, 1/4) comes before the double root at 1/4.
  EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(10), true), Integer(1));
  EXPECT_EQ(s.next_failure_after(Dyadic(1), Dyadic(10), true), Integer(2));
  EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(1), true), std::nullopt);  // horizon excludes k = 1
  LatticeRootSolver two(P({-1, 1}) * P({-9, 8}), 2);
  EXPECT_EQ(two.next_failure_after(Dyadic(0), Dyadic(10)), std::nullopt);
  EXPECT_EQ(two.next_failure_after(Dyadic(0), Dyadic(10), true), Integer(4));
  EXPECT_EQ(two.next_failure_after(Dyadic(1), Dyadic(10), true), std::nullopt);  // the zero at t itself
  EXPECT_EQ(LatticeRootSolver(c, 2).next_failure_after(Dyadic(0), Dyadic(1), true), Integer(0));
}

}  // namespace
