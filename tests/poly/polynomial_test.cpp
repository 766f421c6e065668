// Unit tests of poly::Polynomial against hand-derived values: arithmetic, derivative, mirroring,
// content, exact sign, the double filter, pseudo-remainders (with their sign), gcd, square-free part,
// sign just before/after a point, and the refusal of the zero polynomial.
#include <gtest/gtest.h>

#include <random>

#include "exact/error.hpp"
#include "poly/polynomial.hpp"
#include "small_polynomial.hpp"

namespace {
using kmr::ContractError;
using kmr::InputError;
using kmr::exact::Dyadic;
using kmr::exact::Integer;
using namespace kmr::poly;

using kmr::poly::testing::P;
const Polynomial t = Polynomial::identity();

TEST(Polynomial, CanonicalForm) {
  EXPECT_EQ(P({1, 2, 0, 0}).degree(), 1);
  EXPECT_EQ(P({0, 0}).degree(), -1);
  EXPECT_TRUE(Polynomial().is_zero());
  EXPECT_TRUE(Polynomial(0).is_zero());
  EXPECT_EQ(Polynomial(5).degree(), 0);
  EXPECT_EQ(Polynomial::monomial(Integer(3), 4), P({0, 0, 0, 0, 3}));
  EXPECT_TRUE(Polynomial::monomial(Integer(0), 4).is_zero());
  EXPECT_EQ(P({1, -2}).sign(), -1);
  EXPECT_EQ(Polynomial().sign(), 0);
  EXPECT_EQ(P({3, 2, 1}).leading(), Integer(1));
  EXPECT_EQ(P({3, 2, 1})[0], Integer(3));
}

TEST(Polynomial, Arithmetic) {
  EXPECT_EQ((t + Polynomial(1)) * (t - Polynomial(1)), P({-1, 0, 1}));
  EXPECT_EQ(P({1, 2, 3}) + P({-1, -2, -3}), Polynomial());
  EXPECT_EQ(P({1, 2, 3}) - P({1, 2}), P({0, 0, 3}));
  EXPECT_EQ(-P({1, -2}), P({-1, 2}));
  EXPECT_EQ(Integer(3) * P({1, -2}), P({3, -6}));
  EXPECT_EQ(Integer(0) * P({1, -2}), Polynomial());
  EXPECT_EQ(P({1, 1}) * Polynomial(), Polynomial());
  EXPECT_EQ(P({1, 1}) * P({1, 1}) * P({1, 1}), P({1, 3, 3, 1}));
  EXPECT_EQ(P({5, 2, 0, 3}).derivative(), P({2, 0, 9}));
  EXPECT_EQ(Polynomial(7).derivative(), Polynomial());
  EXPECT_EQ(P({0, 0, 1, 1}).mirrored(), P({0, 0, 1, -1}));
  EXPECT_EQ(P({0, 0, 1}).shifted_by(Integer(1)), P({1, 2, 1}));
  EXPECT_EQ(P({-2, 0, 1}).shifted_by(Integer(-3)), P({7, -6, 1}));  // (t−3)² − 2
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic::parse("0.375")), P({-3, 8}));
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic(4)), P({-4, 1}));
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic::parse("-2.5")), P({5, 2}));
  EXPECT_EQ(Polynomial::linear_with_root(Dyadic()), P({0, 1}));
}

TEST(Polynomial, ContentAndPrimitivePart) {
  EXPECT_EQ(P({4, 0, 6}).content(), Integer(2));
  EXPECT_EQ(P({4, 0, 6}).primitive_part(), P({2, 0, 3}));
  EXPECT_EQ(P({-4, 0, -6}).content(), Integer(2));
  EXPECT_EQ(P({-4, 0, -6}).primitive_part(), P({-2, 0, -3}));  // keeps the leading sign
  EXPECT_EQ(P({3, 5}).primitive_part(), P({3, 5}));
  EXPECT_EQ(Polynomial().content(), Integer(0));
  EXPECT_EQ(Polynomial().primitive_part(), Polynomial());
}

TEST(Polynomial, EvaluationAndExactSign) {
  Polynomial p = P({-1, 2});  // 2t − 1
  EXPECT_EQ(p.evaluate(Integer(3)), Integer(5));
  EXPECT_EQ(p.sign_at(Dyadic::parse("0.5")), 0);
  EXPECT_EQ(p.sign_at(Integer(1), 2), -1);  // t = 1/4
  EXPECT_EQ(p.sign_at(Integer(3), 2), 1);   // t = 3/4
  EXPECT_EQ(p.sign_at(Dyadic(Integer(1), 3)), 1);  // t = 8 (integer exponent)
  EXPECT_EQ(Polynomial().sign_at(Integer(1), 2), 0);
  EXPECT_THROW(p.sign_at(Integer(1), -1), ContractError);
  // A root of 600-bit size: (2^600 t − (2^600 + 1)) at t = 1 + 2^-600 is 0, just below is < 0.
  Integer big = Integer(1) << 600;
  Polynomial q(std::vector<Integer>{-(big + 1), big});
  EXPECT_EQ(q.sign_at(big + 1, 600), 0);
  EXPECT_EQ(q.sign_at(big, 600), -1);
  EXPECT_EQ(q.sign_at(big + 2, 600), 1);
  EXPECT_EQ(P({-3, 0, 1}).to_string(), "t^2 - 3");
  EXPECT_EQ(P({-1, 2, 0, -1}).to_string(), "-t^3 + 2·t - 1");
  EXPECT_EQ(Polynomial().to_string(), "0");
}

TEST(Polynomial, DoubleFilterEqualsExactSign) {
  // Cancellation the double evaluation cannot see: 2^100·t − (2^100 + 1) at t = 1 is −1.
  Integer big = Integer(1) << 100;
  Polynomial q(std::vector<Integer>{-(big + 1), big});
  EXPECT_EQ(filtered_sign_at(q, double_coefficients(q), Integer(1), 0), -1);
  // Cancellation the double evaluation gets wrong *and nonzero*: p(t) below at t = 760902275 is
  // exactly +1 (hand-derived with Python's integers), but double Horner gives −142288748544, and
  // |y| is 2.27 % of the filter's error bound. So a bound too small by a factor ≥ 44 returns −1 here
  // (the 2^100 case above rounds to y = 0 and passes with any bound ≥ 0).
  Polynomial w(std::vector<Integer>{Integer("309750165573593959376"), Integer("578971457934741375"),
                                    Integer(-1521804015), Integer(1)});
  Integer wx(760902275);
  EXPECT_EQ(w.evaluate(wx), Integer(1));
  auto wa = double_coefficients(w);
  ASSERT_TRUE(wa.usable);
  double wy = wa.c[3];
  for (int i = 2; i >= 0; --i) wy = wy * 760902275.0 + wa.c[static_cast<std::size_t>(i)];
  EXPECT_EQ(wy, -142288748544.0);  // the filter really is challenged: the plain double sign is wrong
  EXPECT_EQ(filtered_sign_at(w, wa, wx, 0), 1);
  // Coefficients beyond the filter's range, points with > 53 bits or s > 1000: exact fallback.
  Polynomial huge(std::vector<Integer>{Integer(1), -(Integer(1) << 1200)});
  EXPECT_FALSE(double_coefficients(huge).usable);
  EXPECT_EQ(filtered_sign_at(huge, double_coefficients(huge), Integer(1), 1200), 0);  // 1 − 2^1200·2^−1200 = 0
  Polynomial r = P({-1, 2});
  EXPECT_EQ(filtered_sign_at(r, double_coefficients(r), (Integer(1) << 1100), 1101), 0);
  EXPECT_EQ(filtered_sign_at(r, double_coefficients(r), (Integer(1) << 60) + 1, 61), 1);
  EXPECT_EQ(filtered_sign_at(r, double_coefficients(r), Integer(0), 0), -1);
  EXPECT_THROW(filtered_sign_at(r, double_coefficients(r), Integer(1), -1), ContractError);
  EXPECT_THROW(filtered_sign_at(r, double_coefficients(P({1, 2, 3})), Integer(1), 1), ContractError);
  // Random polynomials, points near their roots: always equal to the exact sign.
  std::mt19937_64 rng(99);
  for (int i = 0; i < 3000; ++i) {
    Integer root_num(static_cast<long long>(rng() % 2001) - 1000);
    unsigned s = static_cast<unsigned>(rng() % 70);
    Polynomial p = Polynomial(std::vector<Integer>{-root_num, Integer(1) << s});
    for (int j = 0; j < 3; ++j) p = p * P({static_cast<long long>(rng() % 200) - 100, static_cast<long long>(rng() % 7) - 3});
    if (p.is_zero()) continue;
    auto approx = double_coefficients(p);
    Integer m = root_num + Integer(static_cast<long long>(rng() % 5) - 2);
    EXPECT_EQ(filtered_sign_at(p, approx, m, s), p.sign_at(m, s)) << p.to_string() << " at " << m << "/2^" << s;
  }
}

TEST(Polynomial, PseudoRemainderHandDerived) {
  // prem(t³ + 1, 2t − 1) = 2³·(t³ + 1)(1/2) = 8·9/8 = 9.
  EXPECT_EQ(pseudo_remainder(P({1, 0, 0, 1}), P({-1, 2})), Polynomial(9));
  // With lc(b) = −2 the factor (−2)³ flips the sign of the true remainder: −9.
  EXPECT_EQ(pseudo_remainder(P({1, 0, 0, 1}), P({1, -2})), Polynomial(-9));
  // prem(t⁴ + t − 1, 4t³ + 1) = 4²·((3/4)t − 1) = 12t − 16.
  EXPECT_EQ(pseudo_remainder(P({-1, 1, 0, 0, 1}), P({1, 0, 0, 4})), P({-16, 12}));
  EXPECT_EQ(pseudo_remainder(P({1, 1}), P({1, 0, 1})), P({1, 1}));  // deg a < deg b
  EXPECT_EQ(pseudo_remainder(P({-1, 0, 1}), P({-1, 1})), Polynomial());
  EXPECT_THROW(pseudo_remainder(P({1, 1}), Polynomial()), ContractError);
}

TEST(Polynomial, ExactQuotient) {
  EXPECT_EQ(exact_quotient(P({-1, 0, 1}), P({-1, 1})), P({1, 1}));
  EXPECT_EQ(exact_quotient(P({-6, 0, 6}), P({-1, 1})), P({6, 6}));
  EXPECT_EQ(exact_quotient(Polynomial(), P({-1, 1})), Polynomial());
  EXPECT_THROW(exact_quotient(P({1, 0, 1}), P({-1, 1})), ContractError);  // remainder 2
  EXPECT_THROW(exact_quotient(P({1, 3}), P({0, 2})), ContractError);      // 3/2 not integral
  EXPECT_THROW(exact_quotient(P({1}), P({0, 1})), ContractError);
  EXPECT_THROW(exact_quotient(P({1}), Polynomial()), ContractError);
}

TEST(Polynomial, GcdAndSquareFreePart) {
  Polynomial a = P({-1, 1}) * P({-1, 1}) * P({2, 1});  // (t−1)²(t+2)
  Polynomial b = Integer(6) * P({-1, 1}) * P({3, 1});  // 6(t−1)(t+3)
  EXPECT_EQ(gcd(a, b), P({-1, 1}));
  EXPECT_EQ(gcd(P({2, 2}), P({4, 4})), P({1, 1}));
  EXPECT_EQ(gcd(P({2, -2}), P({-4, 4})), P({-1, 1}));  // positive leading coefficient
  EXPECT_EQ(gcd(P({-3, -6}), Polynomial()), P({1, 2}));
  EXPECT_EQ(gcd(P({1, 0, 1}), P({-1, 1})), Polynomial(1));
  Polynomial c = Integer(-4) * a * P({-1, 1}) * P({2, 1});  // −4(t−1)³(t+2)²
  EXPECT_EQ(square_free_part(c), P({-2, 1, 1}));           // (t−1)(t+2)
  EXPECT_EQ(square_free_part(P({1, 0, 1})), P({1, 0, 1}));
  EXPECT_EQ(square_free_part(P({0, 0, 0, -5})), P({0, 1}));
  EXPECT_EQ(square_free_part(Polynomial(-7)), Polynomial(1));
  EXPECT_EQ(square_free_part(Polynomial()), Polynomial());
}

TEST(Polynomial, SignBeforeAfter) {
  Polynomial sq = P({1, -2, 1});  // (t−1)²
  EXPECT_EQ(sign_before(sq, Dyadic(1)), 1);
  EXPECT_EQ(sign_after(sq, Dyadic(1)), 1);
  Polynomial cube = sq * P({-1, 1});  // (t−1)³
  EXPECT_EQ(sign_before(cube, Dyadic(1)), -1);
  EXPECT_EQ(sign_after(cube, Dyadic(1)), 1);
  EXPECT_EQ(sign_before(-cube, Dyadic(1)), 1);
  EXPECT_EQ(sign_after(-cube, Dyadic(1)), -1);
  EXPECT_EQ(sign_before(P({-1, 1}), Dyadic(0)), -1);
  EXPECT_EQ(sign_after(P({-1, 1}), Dyadic(0)), -1);
  Polynomial quad = sq * sq;  // (t−1)⁴
  EXPECT_EQ(sign_before(-quad, Dyadic(1)), -1);
  EXPECT_EQ(sign_after(Polynomial(-3), Dyadic(5)), -1);
  EXPECT_THROW(sign_before(Polynomial(), Dyadic(0)), InputError);
  EXPECT_THROW(sign_after(Polynomial(), Dyadic(0)), InputError);
}

}  // namespace
