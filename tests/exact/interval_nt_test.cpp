// IntervalNT (src/exact/interval_nt.hpp): each guarantee of the header is a test here.
#include "exact/interval_nt.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

using kmr::exact::enclose;
using kmr::exact::IntervalNT;
using kmr::exact::Uncertain;
using Q = boost::multiprecision::mpq_rational;

namespace {

bool holds(const IntervalNT& x, const Q& q) { return Q(x.lo()) <= q && q <= Q(x.hi()); }

// Random doubles of mixed magnitudes and signs, including exact small dyadics.
double sample(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-1, 1);
  switch (g() % 4) {
    case 0: return std::ldexp(u(g), -static_cast<int>(g() % 60));
    case 1: return std::ldexp(std::round(u(g) * 64), -6);
    case 2: return u(g) * 1e6;
    default: return u(g);
  }
}

}  // namespace

TEST(IntervalNT, EnclosureOfEveryOperation) {
  std::mt19937_64 g(20121);
  for (int it = 0; it < 20000; ++it) {
    double a = sample(g), b = sample(g), c = sample(g);
    IntervalNT A(a), B(b), C(c);
    // compound expressions, so that non-point intervals are combined too
    IntervalNT x = (A + B) * C - A * B, y = (A - C) * (B + C);
    Q qa(a), qb(b), qc(c);
    Q qx = (qa + qb) * qc - qa * qb, qy = (qa - qc) * (qb + qc);
    ASSERT_TRUE(holds(x, qx)) << a << " " << b << " " << c;
    ASSERT_TRUE(holds(y, qy)) << a << " " << b << " " << c;
    if (y.lo() > 0 || y.hi() < 0) {
      ASSERT_TRUE(holds(x / y, qx / qy)) << a << " " << b << " " << c;
    }
  }
}

TEST(IntervalNT, ExactResultsStayPoints) {
  IntervalNT a(0.375), b(-1.25);
  EXPECT_TRUE((a + b).is_point());
  EXPECT_TRUE((a * b).is_point());
  EXPECT_TRUE((a / IntervalNT(0.5)).is_point());
  EXPECT_EQ((a * b).lo(), 0.375 * -1.25);
  IntervalNT third = IntervalNT(1.0) / IntervalNT(3.0);  // not a double: a true interval
  EXPECT_FALSE(third.is_point());
  EXPECT_TRUE(holds(third, Q(1, 3)));
  EXPECT_EQ(std::nextafter(third.lo(), 1.0), third.hi());  // one ulp wide
}

TEST(IntervalNT, DecisionsAreCertainOrThrow) {
  IntervalNT third = IntervalNT(1.0) / IntervalNT(3.0);
  EXPECT_EQ((third - IntervalNT(0.3)).sign(), 1);
  EXPECT_TRUE(third < IntervalNT(0.34));
  EXPECT_FALSE(third < IntervalNT(0.33));
  EXPECT_EQ(IntervalNT(0.0).sign(), 0);
  EXPECT_TRUE(IntervalNT(0.5) == IntervalNT(0.5));
  // 3·(1/3) − 1 is 0 exactly, but the interval straddles 0: undecided
  EXPECT_THROW((third * IntervalNT(3.0) - IntervalNT(1.0)).sign(), Uncertain);
  EXPECT_THROW((void)(third == IntervalNT(1.0) / IntervalNT(3.0)), Uncertain);
  EXPECT_THROW((void)(third < third), Uncertain);
  EXPECT_THROW(IntervalNT(1.0) / (third - third), Uncertain);  // divisor holds 0
  EXPECT_THROW(IntervalNT(1e300) * IntervalNT(1e300), Uncertain);  // overflow
  // below fma's reach: a sound, wide bound instead of an exception; its sign stays undecided
  IntervalNT tiny = IntervalNT(1e-200) * IntervalNT(-1e-200);
  EXPECT_TRUE(holds(tiny, Q(1e-200) * Q(-1e-200)));
  EXPECT_THROW(tiny.sign(), Uncertain);
  // subnormal operands: the remainder a − q·b would be rounded (found by fuzz/interval_nt)
  EXPECT_THROW(IntervalNT(0x0.016687e92154ep-1022) / IntervalNT(0x0.0000000000307p-1022), Uncertain);
}

TEST(IntervalNT, EncloseRationals) {
  EXPECT_TRUE(enclose(Q(3, 8)).is_point());
  EXPECT_EQ(enclose(Q(3, 8)).lo(), 0.375);
  EXPECT_TRUE(enclose(Q(0)).is_point());
  std::mt19937_64 g(7);
  for (int it = 0; it < 2000; ++it) {
    Q q(static_cast<long long>(g() % 2000001) - 1000000, static_cast<long long>(g() % 999999) + 1);
    IntervalNT e = enclose(q);
    ASSERT_TRUE(holds(e, q)) << q;
    ASSERT_LE(e.hi() - e.lo(), 4 * std::ldexp(std::fabs(e.approx()), -52) + 1e-300) << q;
  }
}

// Division picks two of the four corner quotients by the signs of the operands (issue 11 §4). The
// expectation shares nothing with it: the four corner quotients as exact rationals, their min
// rounded down and their max rounded up to doubles by stepping (the tightest hull of the corner
// quotients, which the former four-quotient min/max computed). Random and sign-boundary operands:
// endpoints 0 and −0, point intervals, a straddling 0, b touching 0 (must throw).
namespace {
double down_to_double(const Q& q) {  // the largest double ≤ q
  double d = q.convert_to<double>();
  while (Q(d) > q) d = std::nextafter(d, -INFINITY);
  while (Q(std::nextafter(d, INFINITY)) <= q) d = std::nextafter(d, INFINITY);
  return d;
}
double up_to_double(const Q& q) { return -down_to_double(-q); }
IntervalNT ordered(double x, double y) { return IntervalNT::hull(std::min(x, y), std::max(x, y)); }
}  // namespace

TEST(IntervalNT, DivisionIsTheTightestHullOfTheCornerQuotients) {
  std::mt19937_64 g(311);
  std::uniform_real_distribution<double> u(-1, 1);
  auto endpoint = [&] {
    switch (g() % 6) {
      case 0: return 0.0;
      case 1: return -0.0;
      case 2: return std::ldexp(u(g), static_cast<int>(g() % 40) - 20);
      case 3: return std::ldexp(std::round(u(g) * 16), -3);  // exact small dyadics: exact quotients
      default: return u(g);
    }
  };
  int checked = 0, refused = 0;
  int classes[2][3] = {};  // b's sign × a's class (≥ 0, ≤ 0, straddling)
  for (int it = 0; it < 50000; ++it) {
    IntervalNT a = ordered(endpoint(), it % 5 == 0 ? 0.0 : endpoint());
    if (it % 7 == 0) a = IntervalNT(a.lo());  // a point
    IntervalNT b = ordered(endpoint(), endpoint());
    if (b.lo() <= 0 && b.hi() >= 0) {  // holds 0: refused
      EXPECT_THROW((void)(a / b), Uncertain) << b.lo() << " " << b.hi();
      ++refused;
      continue;
    }
    Q lo, hi;
    bool first = true;
    for (double x : {a.lo(), a.hi()})
      for (double y : {b.lo(), b.hi()}) {
        Q q = Q(x) / Q(y);
        if (first || q < lo) lo = q;
        if (first || q > hi) hi = q;
        first = false;
      }
    IntervalNT r = a / b;
    ASSERT_EQ(r.lo(), down_to_double(lo)) << "[" << a.lo() << ", " << a.hi() << "] / [" << b.lo() << ", " << b.hi() << "]";
    ASSERT_EQ(r.hi(), up_to_double(hi)) << "[" << a.lo() << ", " << a.hi() << "] / [" << b.lo() << ", " << b.hi() << "]";
    ++classes[b.lo() > 0 ? 0 : 1][a.lo() >= 0 ? 0 : (a.hi() <= 0 ? 1 : 2)];
    ++checked;
  }
  for (auto& row : classes)
    for (int c : row) EXPECT_GT(c, 300);  // every sign case is reached often
  EXPECT_GT(refused, 1000);
  EXPECT_GT(checked, 10000);
}

// kmr::exact::next_up / next_down (issue 11 §4: inline replacements of std::nextafter toward
// ±∞) must equal std::nextafter bit for bit: zeros of both signs, the subnormal and normal
// boundaries, ±max, ±∞, NaN, and 200 000 random bit patterns.
TEST(IntervalNT, NextUpDownEqualStdNextafter) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> xs = {0.0, -0.0, std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::min(), -std::numeric_limits<double>::min(),
                            std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), inf, -inf,
                            std::numeric_limits<double>::quiet_NaN(), 1.0, -1.0, 0.5, -0.5, 0x1p-1022 - 0x1p-1074};
  std::mt19937_64 g(1411);
  for (int k = 0; k < 200000; ++k) xs.push_back(std::bit_cast<double>(g()));
  int checked = 0;
  for (double x : xs) {
    const double u = kmr::exact::next_up(x), d = kmr::exact::next_down(x);
    const double eu = std::nextafter(x, inf), ed = std::nextafter(x, -inf);
    if (std::isnan(x)) {
      EXPECT_TRUE(std::isnan(u) && std::isnan(d));
      continue;
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(u), std::bit_cast<std::uint64_t>(eu)) << std::hexfloat << x;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(d), std::bit_cast<std::uint64_t>(ed)) << std::hexfloat << x;
    ++checked;
  }
  EXPECT_GT(checked, 190000);
}
