// Polynomial and Sturm cases the other tests leave out (issue 13 §2, found by coverage/run.sh),
// against hand-derived values: Sturm variations at non-integer dyadic points, linear_with_root at
// negative and integer roots, shifted_by, square_free_part of powers and of constants.
#include <gtest/gtest.h>

#include "exact/dyadic.hpp"
#include "poly/polynomial.hpp"
#include "poly/sturm.hpp"

namespace kmr::poly {
namespace {

using exact::Dyadic;
using exact::Integer;

Polynomial P(std::vector<long long> c) {
  std::vector<Integer> v;
  for (long long x : c) v.emplace_back(x);
  return Polynomial(std::move(v));
}

TEST(PolyEdges, SturmCountsAtNonIntegerDyadicPoints) {
  // 4t² − 8t + 3 = (2t − 1)(2t − 3): roots 1/2 and 3/2.
  SturmSequence s(P({3, -8, 4}));
  // Sturm's theorem: V(−∞) − V(t) = number of distinct roots in (−∞, t] (a root at t counts).
  auto below = [&](const char* t) { return s.variations_at_minus_infinity() - s.variations_at(Dyadic::parse(t)); };
  EXPECT_EQ(below("0.25"), 0);
  EXPECT_EQ(below("0.5"), 1);
  EXPECT_EQ(below("0.625"), 1);
  EXPECT_EQ(below("1.375"), 1);
  EXPECT_EQ(below("1.5"), 2);
  EXPECT_EQ(below("1.75"), 2);
  EXPECT_EQ(below("-3.5"), 0);
  EXPECT_EQ(s.count_roots(Dyadic::parse("0.5"), Dyadic::parse("1.5")), 1);  // [lo, hi): 1/2 in, 3/2 out
  EXPECT_EQ(s.count_roots(Dyadic::parse("0.5"), Dyadic::parse("1.5078125")), 2);
  EXPECT_EQ(s.distinct_real_roots(), 2);
}

TEST(PolyEdges, LinearWithRootAndShifts) {
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic(-3)), P({3, 1}));                // t + 3
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic::parse("-0.75")), P({3, 4}));    // 4t + 3
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic::parse("2.5")), P({-5, 2}));     // 2t − 5
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic(0)), P({0, 1}));                 // t
  EXPECT_EQ(P({1, 0, 1}).shifted_by(Integer(2)), P({5, 4, 1}));                 // (t+2)² + 1
  EXPECT_EQ(P({0, 0, 0, 1}).shifted_by(Integer(-1)), P({-1, 3, -3, 1}));        // (t−1)³
  EXPECT_EQ(Polynomial().shifted_by(Integer(7)), Polynomial());
}

TEST(PolyEdges, SquareFreePartOfPowersAndConstants) {
  // (t − 1)³ (t + 2)² → (t − 1)(t + 2) = t² + t − 2
  Polynomial p = P({-1, 1}) * P({-1, 1}) * P({-1, 1}) * P({2, 1}) * P({2, 1});
  EXPECT_EQ(square_free_part(p), P({-2, 1, 1}));
  EXPECT_EQ(square_free_part(Integer(-6) * P({-2, 1, 1})), P({-2, 1, 1}));  // content and sign removed
  EXPECT_EQ(square_free_part(P({-7})), P({1}));
  EXPECT_EQ(square_free_part(Polynomial()), Polynomial());
  SturmSequence s(p);
  EXPECT_EQ(s.distinct_real_roots(), 2);
}

// −6t + 15 (negative leading coefficient, content 3): one root 5/2, found in closed form from the
// square-free part (whose leading coefficient the Sturm sequence makes positive): interval 2 at
// bits 0 (mid-interval), 5 at bits 1 (on a lattice point), −3 for the mirrored root −5/2.
TEST(PolyEdges, LinearRootWithNegativeLeadingCoefficient) {
  for (auto [bits, k] : {std::pair{0, 2}, std::pair{1, 5}, std::pair{3, 20}}) {
    LatticeRootSolver s(P({15, -6}), bits);
    auto iv = s.isolate(Dyadic(-100), Dyadic(100));
    ASSERT_EQ(iv.size(), 1u) << bits;
    EXPECT_EQ(iv[0].k, Integer(k)) << bits;
    EXPECT_TRUE(iv[0].sign_change);
    EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(100)), std::optional<Integer>(Integer(k))) << bits;
  }
  LatticeRootSolver m(P({15, 6}), 0);  // 6t + 15: root −5/2 in [−3, −2)
  EXPECT_EQ(m.next_failure_after(Dyadic(-100), Dyadic(100)), std::optional<Integer>(Integer(-3)));
}

}  // namespace
}  // namespace kmr::poly
