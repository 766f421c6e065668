// Unit tests of exact::Integer helpers and exact::Dyadic against hand-derived values.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

#include "exact/dyadic.hpp"
#include "exact/error.hpp"

namespace {
using kmr::InputError;
using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::exact::parse_integer;

TEST(Integer, ParseAndBitLength) {
  EXPECT_EQ(parse_integer("-123"), Integer(-123));
  EXPECT_EQ(parse_integer("+7"), Integer(7));
  EXPECT_EQ(parse_integer("0"), Integer(0));
  // Leading zeros are decimal, never octal (regression: "0123" was read as 83, "09" refused).
  EXPECT_EQ(parse_integer("0123"), Integer(123));
  EXPECT_EQ(parse_integer("-0009"), Integer(-9));
  EXPECT_EQ(parse_integer("000"), Integer(0));
  EXPECT_EQ(parse_integer("123456789012345678901234567890"), Integer("123456789012345678901234567890"));
  for (const char* bad : {"", "-", "+", "12a", " 1", "1 ", "1.0", "--1"}) EXPECT_THROW(parse_integer(bad), InputError) << bad;
  EXPECT_EQ(kmr::exact::bit_length(Integer(0)), 0);
  EXPECT_EQ(kmr::exact::bit_length(Integer(1)), 1);
  EXPECT_EQ(kmr::exact::bit_length(Integer(-255)), 8);
  EXPECT_EQ(kmr::exact::bit_length(Integer(256)), 9);
  EXPECT_EQ(kmr::exact::bit_length(Integer(1) << 600), 601);
  EXPECT_EQ(kmr::exact::sign(Integer(-3)), -1);
}

TEST(Dyadic, CanonicalRepresentation) {
  Dyadic a(Integer(12), 0);  // 12 = 3·2^2
  EXPECT_EQ(a.mantissa(), Integer(3));
  EXPECT_EQ(a.exponent(), 2);
  Dyadic z(Integer(0), 5);
  EXPECT_EQ(z.exponent(), 0);
  EXPECT_TRUE(z.is_zero());
  EXPECT_EQ(Dyadic(Integer(6), -3), Dyadic(Integer(3), -2));  // 6/8 = 3/4
  Dyadic n(Integer(-40), -4);                                  // −40/16 = −5/2
  EXPECT_EQ(n.mantissa(), Integer(-5));
  EXPECT_EQ(n.exponent(), -1);
  EXPECT_TRUE(Dyadic(8).is_integer());
  EXPECT_FALSE(Dyadic(Integer(1), -1).is_integer());
  EXPECT_EQ(Dyadic(Integer(3), -2).shifted(2), Dyadic(3));
  EXPECT_EQ(Dyadic().shifted(7), Dyadic());
}

TEST(Dyadic, ParseHandDerived) {
  EXPECT_EQ(Dyadic::parse("0.375"), Dyadic(Integer(3), -3));
  EXPECT_EQ(Dyadic::parse("-2.5e-1"), Dyadic(Integer(-1), -2));
  EXPECT_EQ(Dyadic::parse("3"), Dyadic(3));
  EXPECT_EQ(Dyadic::parse("+1e3"), Dyadic(1000));
  EXPECT_EQ(Dyadic::parse(".5"), Dyadic(Integer(1), -1));
  EXPECT_EQ(Dyadic::parse("5."), Dyadic(5));
  EXPECT_EQ(Dyadic::parse("0.1e1"), Dyadic(1));  // the value is dyadic even if the text has ".1"
  EXPECT_EQ(Dyadic::parse("-0"), Dyadic());
  EXPECT_EQ(Dyadic::parse("0.0009765625"), Dyadic::pow2(-10));
  EXPECT_EQ(Dyadic::parse("1E2"), Dyadic(100));
  EXPECT_EQ(Dyadic::parse("0.5"), Dyadic(Integer(1), -1));  // regression: digits "05" were octal
  EXPECT_EQ(Dyadic::parse("09.5"), Dyadic(Integer(19), -1));
  EXPECT_EQ(Dyadic::parse("0.09375"), Dyadic(Integer(3), -5));
}

TEST(Dyadic, ParseRefusesNonDyadicAndMalformed) {
  for (const char* bad : {"0.1", "0.2", "1.3e-1", "1e-1", "", "-", ".", "1.2.3", "1e", "abc", "1 ", " 1",
                          "1e999999999", "1e100001", "nan", "inf", "0x10", "1e+", "1,5"})
    EXPECT_THROW(Dyadic::parse(bad), InputError) << bad;
  try {
    Dyadic::parse("0.1");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0.1"), std::string::npos);  // the message names the value
  }
}

TEST(Dyadic, ToDecimalHandDerived) {
  EXPECT_EQ(Dyadic(Integer(3), -3).to_decimal(), "0.375");
  EXPECT_EQ(Dyadic(Integer(-1), -2).to_decimal(), "-0.25");
  EXPECT_EQ(Dyadic(Integer(-5), -1).to_decimal(), "-2.5");
  EXPECT_EQ(Dyadic(Integer(3), 2).to_decimal(), "12");
  EXPECT_EQ(Dyadic().to_decimal(), "0");
  EXPECT_EQ(Dyadic::pow2(-10).to_decimal(), "0.0009765625");
  EXPECT_EQ(Dyadic(Integer(-7), 0).to_decimal(), "-7");
}

TEST(Dyadic, DecimalRoundTrip) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    Integer m = Integer(static_cast<long long>(rng() >> 1)) * Integer(static_cast<long long>(rng() >> 1));
    if (rng() % 2) m = -m;
    Dyadic d(m, static_cast<std::int64_t>(rng() % 400) - 200);
    EXPECT_EQ(Dyadic::parse(d.to_decimal()), d) << d.to_decimal();
  }
}

TEST(Dyadic, FromDoubleIsExact) {
  // 0.1 as a double is 3602879701896397·2^−55, not 1/10.
  Dyadic tenth = Dyadic::from_double(0.1);
  EXPECT_EQ(tenth.mantissa(), Integer(3602879701896397LL));
  EXPECT_EQ(tenth.exponent(), -55);
  EXPECT_EQ(Dyadic::from_double(0.375), Dyadic(Integer(3), -3));
  EXPECT_EQ(Dyadic::from_double(-2.5), Dyadic(Integer(-5), -1));
  EXPECT_EQ(Dyadic::from_double(0.0), Dyadic());
  EXPECT_EQ(Dyadic::from_double(-0.0), Dyadic());
  EXPECT_EQ(Dyadic::from_double(std::ldexp(1.0, -1074)), Dyadic::pow2(-1074));  // smallest subnormal
  EXPECT_EQ(Dyadic::from_double(DBL_MAX), Dyadic(Integer((1LL << 53) - 1), 971));
  EXPECT_EQ(Dyadic::from_double(9007199254740993.0), Dyadic(Integer(9007199254740992LL)));  // rounds at parse time
  EXPECT_THROW(Dyadic::from_double(std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(Dyadic::from_double(std::numeric_limits<double>::infinity()), InputError);
  EXPECT_THROW(Dyadic::from_double(-std::numeric_limits<double>::infinity()), InputError);
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    double x = std::ldexp(static_cast<double>(static_cast<long long>(rng() >> 11)), static_cast<int>(rng() % 200) - 100);
    if (rng() % 2) x = -x;
    EXPECT_EQ(Dyadic::from_double(x).to_double(), x);
  }
}

TEST(Dyadic, ArithmeticAndOrder) {
  Dyadic a = Dyadic::parse("0.375"), b = Dyadic::parse("0.125");
  EXPECT_EQ(a + b, Dyadic::parse("0.5"));
  EXPECT_EQ(a - b, Dyadic::parse("0.25"));
  EXPECT_EQ(b - a, Dyadic::parse("-0.25"));
  EXPECT_EQ(a * b, Dyadic(Integer(3), -6));
  EXPECT_EQ(-a, Dyadic::parse("-0.375"));
  Dyadic c = a;
  c += b;
  c -= Dyadic(1);
  c *= Dyadic(4);
  EXPECT_EQ(c, Dyadic(-2));
  EXPECT_LT(Dyadic::parse("-1"), Dyadic::parse("-0.5"));
  EXPECT_LT(Dyadic::parse("-0.5"), Dyadic());
  EXPECT_LT(Dyadic(), Dyadic::pow2(-1000));
  EXPECT_LT(Dyadic::pow2(-1000), Dyadic::pow2(-999));
  EXPECT_LT(Dyadic(Integer(3), -2), Dyadic(1));
  EXPECT_LT(Dyadic(Integer(5), -3), Dyadic(Integer(3), -2));  // same top bit: decided exactly
  EXPECT_GT(Dyadic(Integer(-5), -3), Dyadic(Integer(-3), -2));
  EXPECT_EQ(Dyadic(Integer(1), 700) + Dyadic(Integer(1), -700) - Dyadic(Integer(1), 700), Dyadic(Integer(1), -700));
}

TEST(Dyadic, FloorCeilToDouble) {
  EXPECT_EQ(Dyadic::parse("-2.5").floor(), Integer(-3));
  EXPECT_EQ(Dyadic::parse("-2.5").ceil(), Integer(-2));
  EXPECT_EQ(Dyadic::parse("2.5").floor(), Integer(2));
  EXPECT_EQ(Dyadic::parse("2.5").ceil(), Integer(3));
  EXPECT_EQ(Dyadic(4).floor(), Integer(4));
  EXPECT_EQ(Dyadic(4).ceil(), Integer(4));
  EXPECT_EQ(Dyadic(Integer(-1), -600).floor(), Integer(-1));
  EXPECT_EQ(Dyadic(Integer(-1), -600).ceil(), Integer(0));
  EXPECT_EQ(Dyadic(Integer(3), 100).floor(), Integer(3) << 100);
  EXPECT_EQ(Dyadic::parse("-0.375").to_double(), -0.375);
  EXPECT_EQ(Dyadic().to_double(), 0.0);
  EXPECT_EQ(Dyadic((Integer(1) << 200) + 1, -100).to_double(), std::ldexp(1.0, 100));
  EXPECT_TRUE(std::isinf(Dyadic(Integer(1), 1LL << 40).to_double()));
  EXPECT_EQ(Dyadic(Integer(1), -(1LL << 40)).to_double(), 0.0);
}

TEST(Dyadic, Interval) {
  kmr::exact::Interval i{Dyadic(1), Dyadic(2)};
  EXPECT_EQ(i.midpoint(), Dyadic::parse("1.5"));
  EXPECT_EQ(i.width(), Dyadic(1));
  EXPECT_TRUE(i.contains(Dyadic(1)));
  EXPECT_TRUE(i.contains(Dyadic(2)));
  EXPECT_FALSE(i.contains(Dyadic::parse("2.0001220703125")));
}

}  // namespace
