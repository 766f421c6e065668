// Edge cases of exact/ that the other tests leave out (issue 13 §2, found by coverage/run.sh), each
// against a hand-derived value: Dyadic ordering across signs and magnitudes, to_double beyond the
// double range, parse's exponent limits, shifted zero, Interval::contains; IntervalNT division at
// and below the underflow guard (kTiny = 2^-900: refused with Uncertain, never a wrong enclosure),
// and a non-exact quotient enclosed by adjacent doubles (checked in exact Dyadic arithmetic).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "exact/dyadic.hpp"
#include "exact/error.hpp"
#include "exact/interval_nt.hpp"

namespace kmr::exact {
namespace {

TEST(DyadicEdges, OrderingAcrossSignsAndMagnitudes) {
  // −8 < −1 < −0.75 < 0 < 0.375 < 3 < 2^70, by hand; every ordered pair both ways.
  const Dyadic v[] = {Dyadic(-8), Dyadic(-1), Dyadic::parse("-0.75"), Dyadic(0), Dyadic::parse("0.375"), Dyadic(3),
                      Dyadic::pow2(70)};
  const int n = sizeof v / sizeof v[0];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      EXPECT_EQ(v[i] < v[j], i < j) << i << " " << j;
      EXPECT_EQ(v[i] == v[j], i == j) << i << " " << j;
    }
  // Same sign, same bit position: the exact difference decides (−5 vs −7, 5/8 vs 7/8).
  EXPECT_LT(Dyadic(-7), Dyadic(-5));
  EXPECT_LT(Dyadic::parse("0.625"), Dyadic::parse("0.875"));
}

TEST(DyadicEdges, ToDoubleBeyondTheDoubleRange) {
  EXPECT_EQ(Dyadic::pow2(2'000'000'000).to_double(), HUGE_VAL);
  EXPECT_EQ((-Dyadic::pow2(2'000'000'000)).to_double(), -HUGE_VAL);
  double tiny = Dyadic::pow2(-2'000'000'000).to_double(), neg_tiny = (-Dyadic::pow2(-2'000'000'000)).to_double();
  EXPECT_EQ(tiny, 0.0);
  EXPECT_FALSE(std::signbit(tiny));
  EXPECT_EQ(neg_tiny, 0.0);
  EXPECT_TRUE(std::signbit(neg_tiny));
  // In range, and with more than 60 mantissa bits: (2^70 + 1)·2^-70 rounds to 1.
  EXPECT_EQ(Dyadic(Integer(1) << 70 | Integer(1), -70).to_double(), 1.0);
}

TEST(DyadicEdges, ParseRefusesExponentsBeyondItsLimits) {
  EXPECT_THROW(Dyadic::parse("1e100001"), InputError);   // |exponent| > 100 000
  EXPECT_THROW(Dyadic::parse("1e-100001"), InputError);
  EXPECT_THROW(Dyadic::parse("1e123456789"), InputError);  // exponent field longer than 8 characters
  EXPECT_THROW(Dyadic::parse("1e"), InputError);
  try {
    Dyadic::parse("5e-100001");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exponent out of range"), std::string::npos) << e.what();
  }
  // Far but within the limit, and not dyadic: refused for its value, not its size.
  EXPECT_THROW(Dyadic::parse("1e-300"), InputError);
  EXPECT_EQ(Dyadic::parse("5e-1"), Dyadic::pow2(-1));
  EXPECT_EQ(Dyadic::parse("0e99999"), Dyadic());  // zero with a huge exponent is zero
}

TEST(DyadicEdges, ShiftedZeroAndIntervalContains) {
  Dyadic z = Dyadic().shifted(40);
  EXPECT_TRUE(z.is_zero());
  EXPECT_EQ(z.exponent(), 0);  // canonical
  EXPECT_EQ(Dyadic(3).shifted(-2), Dyadic::parse("0.75"));
  Interval iv{Dyadic(1), Dyadic(2)};
  EXPECT_TRUE(iv.contains(Dyadic(1)));
  EXPECT_TRUE(iv.contains(Dyadic(2)));
  EXPECT_TRUE(iv.contains(Dyadic::parse("1.5")));
  EXPECT_FALSE(iv.contains(Dyadic::parse("0.5")));
  EXPECT_FALSE(iv.contains(Dyadic::parse("2.5")));
  EXPECT_EQ(iv.midpoint(), Dyadic::parse("1.5"));
  EXPECT_EQ(bit_length(Integer(0)), 0);
  EXPECT_EQ(bit_length(Integer(-8)), 4);
}

TEST(IntervalNTEdges, DivisionNearUnderflowIsRefusedNotGuessed) {
  const IntervalNT one(1.0);
  EXPECT_THROW(one / IntervalNT(0x1p-901), Uncertain);                     // divisor below 2^-900
  EXPECT_THROW(IntervalNT(0x1p-901) / one, Uncertain);                     // dividend below 2^-900
  EXPECT_THROW(IntervalNT(0x1p-800) / IntervalNT(0x1p200), Uncertain);     // quotient 2^-1000: tiny
  EXPECT_THROW(IntervalNT(0x1p-890) / IntervalNT(0x1p300), Uncertain);     // quotient 2^-1190: rounds to 0
  EXPECT_THROW(one / IntervalNT::hull(-1.0, 1.0), Uncertain);              // divisor holds 0
  // 0 / x is exactly 0; 2^-890 / 2^10 = 2^-900 exactly (not below the guard).
  IntervalNT z = IntervalNT(0.0) / IntervalNT(7.0);
  EXPECT_TRUE(z.is_point());
  EXPECT_EQ(z.lo(), 0.0);
  IntervalNT q = IntervalNT(0x1p-890) / IntervalNT(0x1p10);
  EXPECT_TRUE(q.is_point());
  EXPECT_EQ(q.lo(), 0x1p-900);
}

TEST(IntervalNTEdges, InexactQuotientIsEnclosedByAdjacentDoubles) {
  // 1/3 and −2/7: lo < a/b < hi checked exactly as lo·b < a < hi·b in Dyadic arithmetic.
  for (auto [a, b] : {std::pair{1.0, 3.0}, std::pair{-2.0, 7.0}, std::pair{5.0, -0.1}}) {
    IntervalNT q = IntervalNT(a) / IntervalNT(b);
    EXPECT_EQ(std::nextafter(q.lo(), HUGE_VAL), q.hi()) << a << "/" << b;
    Dyadic da = Dyadic::from_double(a), db = Dyadic::from_double(b);
    Dyadic lo_b = Dyadic::from_double(q.lo()) * db, hi_b = Dyadic::from_double(q.hi()) * db;
    if (b > 0) {
      EXPECT_LT(lo_b, da);
      EXPECT_LT(da, hi_b);
    } else {
      EXPECT_GT(lo_b, da);
      EXPECT_GT(da, hi_b);
    }
  }
}

}  // namespace
}  // namespace kmr::exact
