#include "poly/failure_filter.hpp"

#include "exact/error.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace kmr::poly {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A closed interval of reals. Every operation widens its rounded result r by |r|·2^−51 + 2^−1022:
// more than the round-to-nearest error 2^−53·|r| of the operation plus the rounding of the
// widening itself, and than any underflow error (≤ 2^−1074). Non-finite results give the whole line.
struct Iv {
  double lo, hi;
};
constexpr Iv kEntire{-kInf, kInf};
// always_inline (issue 9: kinetic hull cubics): without it the MachinePolynomial filter costs 1.7 %
// more instructions (callgrind, poly_machine_polynomial_test, rel8). At -O0 (coverage) each inlined
// copy counts its own branches; the non-finite sides of the copies in Filter<…, 2> and <…, 3> are
// unreachable (machine coefficients < 2^127 and |x| < 2^62 keep every value below 2^320), those of
// the Polynomial instantiation are taken by tests/poly/failure_filter_test.cpp (Overflowing*).
constexpr double kRel = 0x1p-51, kAbs = 0x1p-1022;
[[gnu::always_inline]] inline Iv widened(double lo, double hi) {
  if (!(std::fabs(lo) < kInf) || !(std::fabs(hi) < kInf)) return kEntire;  // also NaN
  return {lo - (std::fabs(lo) * kRel + kAbs), hi + (std::fabs(hi) * kRel + kAbs)};
}
[[gnu::always_inline]] inline bool finite(Iv a) { return std::fabs(a.lo) < kInf && std::fabs(a.hi) < kInf; }
[[gnu::always_inline]] inline Iv add(Iv a, Iv b) {
  if (!finite(a) || !finite(b)) return kEntire;
  return widened(a.lo + b.lo, a.hi + b.hi);
}
[[gnu::always_inline]] inline Iv mul(Iv a, Iv b) {
  if (!finite(a) || !finite(b)) return kEntire;
  double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;  // finite: no NaN
  return widened(std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3)));
}
int sign_of(Iv v) { return v.lo > 0 ? 1 : v.hi < 0 ? -1 : 0; }  // 0: may contain zero

constexpr int kMaxDegree = 15;  // higher degrees are left to the exact path
using Coefficients = std::array<Iv, kMaxDegree + 1>;

// Interval Horner of c[0..n]. N ≥ 0: n = N known at compile time (the loop unrolls; the same
// operations in the same order as N = −1, so the same enclosure to the bit).
template <int N>
[[gnu::always_inline]] inline Iv horner(const Coefficients& c, int n, Iv x) {
  if constexpr (N >= 0) n = N;
  Iv y = c[static_cast<std::size_t>(n)];
  for (int i = n - 1; i >= 0; --i) y = add(mul(y, x), c[static_cast<std::size_t>(i)]);
  return y;
}

// 2^−bits exactly (0 ≤ bits ≤ 62), as std::ldexp(1.0, −bits) without the library call.
double inv_pow2(int bits) {
  return bits >= 0 && bits <= 62 ? 1.0 / static_cast<double>(std::uint64_t{1} << bits) : std::ldexp(1.0, -bits);
}

// The double sign of p(kδ) with filtered_sign_at's rigorous bound (polynomial.cpp); 0: undecided.
// N as for horner.
template <int N = -1>
int double_sign_at(const double* c, int n, std::int64_t k, double inv_scale) {
  if constexpr (N >= 0) n = N;
  if (!(k > -(std::int64_t{1} << 53) && k < (std::int64_t{1} << 53))) return 0;
  double x = double(k) * inv_scale;  // exact
  double ax = std::fabs(x);
  double y = c[n], bound = std::fabs(c[n]);
  for (int i = n - 1; i >= 0; --i) {
    y = y * x + c[i];
    bound = bound * ax + std::fabs(c[i]);
  }
  double err = (2.0 * n + 2.0) * (bound * 0x1p-51);  // as in filtered_sign_at (polynomial.cpp); exact scaling
  if (std::isfinite(y) && std::isfinite(bound) && bound >= 0x1p-900) {
    if (y > err) return 1;
    if (y < -err) return -1;
  }
  return 0;
}

// The filter over rounded coefficients c[0..n] (each within one ulp of the exact one); ExactSign(k)
// is the exact sign of p(kδ), asked only when the double evaluation cannot decide it. N ≥ 0: the
// degree n = N is known at compile time (the cubics of the kinetic hull; the same arithmetic, bit
// for bit, as N = −1, only unrolled); N = −1: any degree.
template <class ExactSign, int N = -1>
class Filter {
 public:
  Filter(const double* c, int n, bool usable, int bits, ExactSign exact)
      : c_(c), usable_(usable), exact_(exact), n_(N >= 0 ? N : n), inv_scale_(inv_pow2(bits)) {
    if (!usable_ || n_ > kMaxDegree) return;
    for (int i = 0; i <= n_; ++i)  // mpz_get_d truncates: < 1 ulp, inside the widening
      coeff_[static_cast<std::size_t>(i)] = widened(c[i], c[i]);
    for (int i = 1; i <= n_; ++i)
      deriv_[static_cast<std::size_t>(i - 1)] = mul(Iv{double(i), double(i)}, coeff_[static_cast<std::size_t>(i)]);
    if (n_ == 0) deriv_[0] = {0, 0};
  }

  FailureFilterResult run(std::int64_t a, std::int64_t b) {
    FailureFilterResult r;
    if (!usable_ || n_ > kMaxDegree) return r;
    // Every real root r has |r| < R (Fujiwara's bound): intervals k with |k|·δ > R hold none, so the
    // query shrinks to [max(a, −K), min(b, K)) with K = floor(R·2^b) + 1 (issue 9: most cubics'
    // roots lie far below the horizon, whose empty upper ranges were subdivided one by one).
    if (std::optional<std::int64_t> K = root_bound_index()) {
      a = std::max(a, -*K);
      b = std::min(b, *K);
    }
    if (a >= b) {
      r.decided = true;
      return r;
    }
    // Ranges [lo, hi] of lattice indices, leftmost on top: the first failure found is the earliest.
    // Each split leaves its right half below the left one: at most 64 levels of ranges < 2^63.
    std::pair<std::int64_t, std::int64_t> stack[70];
    int top = 0;
    stack[top++] = {a, b};
    int budget = 4096;  // range evaluations before giving up (keeps the worst case bounded)
    while (top > 0) {
      auto [lo, hi] = stack[--top];
      if (--budget < 0) return r;
      // [lo·δ, hi·δ] enclosed: double(k) rounds to nearest, the widening covers it; ·2^−b is exact.
      Iv x = widened(double(lo) * inv_scale_, double(hi) * inv_scale_);
      if (sign_of(horner<N>(coeff_, n_, x)) != 0) continue;  // no root in [lo·δ, hi·δ]
      if (int d = sign_of(horner<(N > 0 ? N - 1 : N)>(deriv_, std::max(n_ - 1, 0), x)); d != 0) {
        // p strictly monotone on the range: sign_before changes at most once along it.
        int s_lo = sign_before(lo, d), s_hi = sign_before(hi, d);
        if (s_lo == s_hi) continue;
        // Invariant: sign_before(lo) = s_lo ≠ sign_before(hi). A Newton guess in doubles (issue 9)
        // only chooses where to look: each probe is an exact sign that narrows the bracket, so
        // the answer is the bisection's whatever the guess.
        if (hi - lo > 2) {
          std::int64_t k = newton_guess(lo, hi);
          if (k > lo && k < hi) (sign_before(k, d) == s_lo ? lo : hi) = k;
          if (k + 1 > lo && k + 1 < hi) (sign_before(k + 1, d) == s_lo ? lo : hi) = k + 1;
        }
        while (hi - lo > 1) {
          std::int64_t mid = lo + (hi - lo) / 2;
          (sign_before(mid, d) == s_lo ? lo : hi) = mid;
        }
        r.decided = true;
        r.failure = lo;
        return r;
      }
      if (hi - lo == 1) return r;  // a double root or roots closer than δ: undecided
      std::int64_t mid = lo + (hi - lo) / 2;
      stack[top++] = {mid, hi};
      stack[top++] = {lo, mid};
    }
    r.decided = true;
    return r;
  }

 private:
  // An approximate lattice index of the root of p in the monotone range [lo, hi] (a few Newton
  // steps from the midpoint in doubles), clamped to [lo, hi − 1]; its accuracy does not matter.
  std::int64_t newton_guess(std::int64_t lo, std::int64_t hi) const {
    const int n_ = N >= 0 ? N : this->n_;  // (compile-time degree: the loop unrolls)
    const double a = double(lo) * inv_scale_, b = double(hi) * inv_scale_;
    double x = 0.5 * (a + b);
    for (int it = 0; it < 8; ++it) {
      double y = c_[n_], dy = 0;
      for (int i = n_ - 1; i >= 0; --i) {
        dy = dy * x + y;
        y = y * x + c_[i];
      }
      if (!(dy != 0) || !std::isfinite(y / dy)) break;
      double nx = std::clamp(x - y / dy, a, b);
      if (nx == x) break;
      x = nx;
    }
    double k = std::floor(x / inv_scale_);
    if (!(k >= double(lo))) return lo;
    if (!(k < double(hi))) return hi - 1;
    return std::clamp(static_cast<std::int64_t>(k), lo, hi - 1);
  }

  // floor(R·2^bits) + 1 for R ≥ 2·max_i |c_{n−i}/c_n|^{1/i} > |every root| (Fujiwara), or nothing
  // when it does not fit. The coefficients are within one ulp of the exact ones and pow, sqrt and
  // cbrt within a few ulps, so the factor 1 + 2^−20 covers every rounding.
  std::optional<std::int64_t> root_bound_index() const {
    const int n_ = N >= 0 ? N : this->n_;
    if (n_ < 1) return std::nullopt;  // c_[n_] ≠ 0: the double of a nonzero integer is at least 1 in magnitude
    const double lead = std::fabs(c_[n_]);
    double m = 0;
    for (int i = 1; i <= n_; ++i) {
      double q = std::fabs(c_[n_ - i]) / lead;
      if (q == 0) continue;
      double root = i == 1 ? q : i == 2 ? std::sqrt(q) : i == 3 ? std::cbrt(q) : std::pow(q, 1.0 / i);
      m = std::max(m, root);
    }
    double k = std::floor(2 * m * (1 + 0x1p-20) / inv_scale_) + 1;  // ·2^bits, exact scaling
    if (!(k < 0x1p61)) return std::nullopt;  // also NaN / ∞
    return static_cast<std::int64_t>(k);
  }

  // sign_before(kδ) where p' has sign d around kδ: sign p(kδ), or −d at a root.
  int sign_before(std::int64_t k, int d) const {
    int s = sign_at(k);
    return s != 0 ? s : -d;
  }
  // The exact sign of p(kδ): a double evaluation with filtered_sign_at's bound, else exact.
  int sign_at(std::int64_t k) const {
    if (int s = double_sign_at<N>(c_, n_, k, inv_scale_); s != 0) return s;
    return exact_(k);
  }

  const double* c_;
  bool usable_;
  ExactSign exact_;
  int n_;
  double inv_scale_;  // 2^−bits
  Coefficients coeff_{}, deriv_{};
};

}  // namespace

FailureFilterResult filtered_next_failure(const Polynomial& p, const DoubleCoefficients& approx, int bits,
                                          std::int64_t a, std::int64_t b) {
  KMR_CHECK(!p.is_zero(), "filtered_next_failure of the zero polynomial");
  KMR_CHECK(bits >= 0 && bits <= 62, "filtered_next_failure: lattice bits must be in [0, 62]");
  // |a|, |b| < 2^62: b − a and the ranges' midpoints cannot overflow, and the stack suffices.
  constexpr std::int64_t kLimit = std::int64_t{1} << 62;
  KMR_CHECK(a > -kLimit && a < kLimit && b > -kLimit && b < kLimit, "filtered_next_failure: lattice indices beyond 2^62");
  KMR_CHECK(!approx.usable || approx.c.size() == p.coefficients().size(), "filtered_next_failure: approx is not from p");
  auto exact = [&p, bits](std::int64_t k) { return p.sign_at(Integer(k), bits); };
  return Filter<decltype(exact)>(approx.c.data(), p.degree(), approx.usable, bits, exact).run(a, b);
}

namespace {
void check_query(int bits, std::int64_t a, std::int64_t b) {
  KMR_CHECK(bits >= 0 && bits <= 62, "filtered_next_failure: lattice bits must be in [0, 62]");
  constexpr std::int64_t kLimit = std::int64_t{1} << 62;
  KMR_CHECK(a > -kLimit && a < kLimit && b > -kLimit && b < kLimit, "filtered_next_failure: lattice indices beyond 2^62");
}
}  // namespace

FailureFilterResult filtered_next_failure(const MachinePolynomial& p, int bits, std::int64_t a, std::int64_t b) {
  KMR_CHECK(!p.is_zero(), "filtered_next_failure of the zero polynomial");
  check_query(bits, a, b);
  const auto approx = p.approximations();  // round to nearest: within the one-ulp allowance
  auto exact = [&p, bits](std::int64_t k) { return p.to_polynomial().sign_at(Integer(k), bits); };
  switch (p.degree()) {  // the degree at compile time: the same decisions, unrolled arithmetic
    case 3: return Filter<decltype(exact), 3>(approx.data(), 3, true, bits, exact).run(a, b);
    case 2: return Filter<decltype(exact), 2>(approx.data(), 2, true, bits, exact).run(a, b);
    default: return Filter<decltype(exact)>(approx.data(), p.degree(), true, bits, exact).run(a, b);
  }
}

bool no_failure_from_zero(const MachinePolynomial& p) {
  const __int128 c0 = p[0];
  if (c0 == 0) return false;  // a root at 0: sign_before(0) may differ from the sign after it
  for (int i = 1; i <= p.degree(); ++i)
    if (p[i] != 0 && (p[i] < 0) != (c0 < 0)) return false;  // a sign change: Descartes allows a root
  return true;
}

namespace {
// ⌊log2 v⌋ of a positive normal double.
int floor_log2(double v) { return static_cast<int>((std::bit_cast<std::uint64_t>(v) >> 52) & 0x7ff) - 1023; }
}  // namespace

std::int64_t root_free_until(const MachinePolynomial& p, int bits, std::int64_t from, std::int64_t last) {
  check_query(bits, from, last);
  KMR_CHECK(from <= last, "root_free_until: empty range");
  const int n = p.degree();
  if (n < 0 || from == last) return from;
  if (n == 0) return last;  // a nonzero constant has no root
  constexpr std::int64_t kExact = std::int64_t{1} << 53;
  if (from < 0 || from >= kExact) return from;  // A = from·δ below must be exact and ≥ 0
  const auto c = p.approximations();  // |c_i − c̃_i| ≤ 2^−53·|c_i|
  const double inv_scale = inv_pow2(bits);
  const double A = double(from) * inv_scale;  // exact
  // |p(A)| ≥ lo: the double value with filtered_sign_at's rigorous bound (as double_sign_at).
  // At A = 0 (every certificate of an initial run) Horner's steps y·0 + c_i give c_0 exactly.
  double y = c[0], bound = std::fabs(c[0]);
  if (from != 0) {
    y = c[static_cast<std::size_t>(n)], bound = std::fabs(y);
    for (int i = n - 1; i >= 0; --i) {
      y = y * A + c[static_cast<std::size_t>(i)];
      bound = bound * A + std::fabs(c[static_cast<std::size_t>(i)]);
    }
  }
  const double err = (2.0 * n + 2.0) * (bound * 0x1p-51);
  if (!(std::isfinite(y) && std::isfinite(bound) && bound >= 0x1p-900)) return from;
  const double lo = (std::fabs(y) - err) * (1 - 0x1p-50);  // rounded down with room to spare
  if (!(lo > 0x1p-900)) return from;                       // p(A) may be 0 (or is tiny): no window
  // q(s) = p(A + s) = p(A) + Σ_{i≥1} q_i s^i with |q_i| ≤ U_i = Σ_{j≥i} C(j, i)|c_j| A^{j−i}
  // (nonnegative terms: each rounding is relative; 1 + 2^−45 covers them and the coefficients').
  const double a1 = std::fabs(c[1]), a2 = n >= 2 ? std::fabs(c[2]) : 0.0, a3 = n >= 3 ? std::fabs(c[3]) : 0.0;
  constexpr double kUp = 1 + 0x1p-45;
  const double U[4] = {0, (a1 + A * (2 * a2 + 3 * a3 * A)) * kUp, (a2 + 3 * a3 * A) * kUp, a3 * kUp};
  // A guess s = 2^e with U_i s^i ≤ lo/8 for each i (exponents only); the test below decides.
  int e = 1 << 20;
  const int elo = floor_log2(lo);
  // i runs to the machine degree 3 (as U above), a constant trip count: unrolled, constant divisors.
  static_assert(MachinePolynomial::kMaxDegree == 3, "U and the window guess cover machine degrees up to 3");
  for (int i = 1; i <= MachinePolynomial::kMaxDegree && i <= n; ++i) {
    if (!(U[i] > 0)) continue;  // U_i is finite: A < 2^53 and |c_j| < 2^127 keep it below 2^236
    const int d = elo - floor_log2(U[i]) - 4;  // lo/(8·U_i) ≥ 2^d
    e = std::min(e, d >= 0 ? d / i : -((-d + i - 1) / i));  // ⌊d/i⌋
  }
  // The window in lattice intervals: 2^(e+bits), capped at the horizon.
  const int le = e + bits;
  if (le < 0) return from;
  std::int64_t len = le >= 61 ? last - from : std::min<std::int64_t>(std::int64_t{1} << le, last - from);
  if (len >= kExact) return from;  // keeps D exact
  // Σ U_i D^i (nonnegative terms, rounded up by the factor) < |p(A)|: no root in [A, A + D].
  auto root_free = [&](std::int64_t l) {
    const double D = double(l) * inv_scale;  // exact (l < 2^53)
    return ((U[3] * D + U[2]) * D + U[1]) * D * (1 + 0x1p-48) < lo;
  };
  if (!root_free(len)) return from;
  // The guess is cautious (each term ≤ lo/8): double the window while the test still holds.
  for (int i = 0; i < 4 && len < last - from && len < kExact / 2; ++i) {
    const std::int64_t longer = std::min(2 * len, last - from);
    if (!root_free(longer)) break;
    len = longer;
  }
  return from + len;
}

int sign_before_lattice(const MachinePolynomial& p, std::int64_t k, int bits) {
  KMR_CHECK(!p.is_zero(), "sign_before of the zero polynomial");
  if (k == 0 && p[0] != 0) return p[0] > 0 ? 1 : -1;  // p(0) = c_0 ≠ 0: its sign, exactly (the initial run)
  const auto approx = p.approximations();
  const double inv_scale = inv_pow2(bits);
  if (int s = p.degree() == 3 ? double_sign_at<3>(approx.data(), 3, k, inv_scale) : double_sign_at(approx.data(), p.degree(), k, inv_scale); s != 0)
    return s;
  return sign_before(p.to_polynomial(), Dyadic(Integer(k), -bits));
}

}  // namespace kmr::poly
