#include "poly/failure_filter.hpp"

#include "exact/error.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace kmr::poly {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A closed interval of reals; every operation rounds outward by one ulp, which covers the
// round-to-nearest error of the operation (and underflow: nextafter steps at least one subnormal).
struct Iv {
  double lo, hi;
};
constexpr Iv kEntire{-kInf, kInf};
double down(double x) { return std::nextafter(x, -kInf); }
double up(double x) { return std::nextafter(x, kInf); }
Iv finite_or_entire(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return kEntire;  // also catches NaN
  return {lo, hi};
}
Iv add(Iv a, Iv b) {
  if (!std::isfinite(a.lo) || !std::isfinite(b.lo) || !std::isfinite(a.hi) || !std::isfinite(b.hi)) return kEntire;
  return finite_or_entire(down(a.lo + b.lo), up(a.hi + b.hi));
}
Iv mul(Iv a, Iv b) {
  if (!std::isfinite(a.lo) || !std::isfinite(b.lo) || !std::isfinite(a.hi) || !std::isfinite(b.hi)) return kEntire;
  double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  double lo = p[0], hi = p[0];
  for (double x : p) {
    if (std::isnan(x)) return kEntire;
    lo = x < lo ? x : lo;
    hi = x > hi ? x : hi;
  }
  return finite_or_entire(down(lo), up(hi));
}
int sign_of(Iv v) { return v.lo > 0 ? 1 : v.hi < 0 ? -1 : 0; }  // 0: may contain zero

Iv horner(const std::vector<Iv>& c, Iv x) {
  Iv y = c.back();
  for (std::size_t i = c.size() - 1; i-- > 0;) y = add(mul(y, x), c[i]);
  return y;
}

class Filter {
 public:
  Filter(const Polynomial& p, const DoubleCoefficients& approx, int bits) : p_(p), approx_(approx), bits_(bits) {
    for (double c : approx.c) coeff_.push_back({down(c), up(c)});  // mpz_get_d truncates: < 1 ulp
    for (std::size_t i = 1; i < coeff_.size(); ++i)
      deriv_.push_back(mul(Iv{double(i), double(i)}, coeff_[i]));
    if (deriv_.empty()) deriv_.push_back({0, 0});
  }

  FailureFilterResult run(std::int64_t a, std::int64_t b) {
    FailureFilterResult r;
    if (!approx_.usable) return r;
    if (a >= b) {
      r.decided = true;
      return r;
    }
    // Ranges [lo, hi] of lattice indices, leftmost on top: the first failure found is the earliest.
    std::vector<std::pair<std::int64_t, std::int64_t>> stack{{a, b}};
    int budget = 4096;  // range evaluations before giving up (keeps the worst case bounded)
    while (!stack.empty()) {
      auto [lo, hi] = stack.back();
      stack.pop_back();
      if (--budget < 0) return r;
      Iv x{std::ldexp(down(double(lo)), -bits_), std::ldexp(up(double(hi)), -bits_)};
      if (sign_of(horner(coeff_, x)) != 0) continue;  // no root in [lo·δ, hi·δ]
      if (int d = sign_of(horner(deriv_, x)); d != 0) {
        // p strictly monotone on the range: sign_before changes at most once along it.
        int s_lo = sign_before(lo, d), s_hi = sign_before(hi, d);
        if (s_lo == s_hi) continue;
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
      stack.push_back({mid, hi});
      stack.push_back({lo, mid});
    }
    r.decided = true;
    return r;
  }

 private:
  // sign_before(kδ) where p' has sign d around kδ: sign p(kδ), or −d at a root.
  int sign_before(std::int64_t k, int d) const {
    int s = sign_at(k);
    return s != 0 ? s : -d;
  }
  // The exact sign of p(kδ): a double evaluation with filtered_sign_at's bound, else exact.
  int sign_at(std::int64_t k) const {
    int n = p_.degree();
    if (k > -(std::int64_t{1} << 53) && k < (std::int64_t{1} << 53)) {
      double x = std::ldexp(double(k), -bits_);  // exact
      double ax = std::fabs(x);
      double y = approx_.c.back(), bound = std::fabs(approx_.c.back());
      for (int i = n - 1; i >= 0; --i) {
        y = y * x + approx_.c[static_cast<std::size_t>(i)];
        bound = bound * ax + std::fabs(approx_.c[static_cast<std::size_t>(i)]);
      }
      double err = (2.0 * n + 2.0) * std::ldexp(bound, -51);  // as in filtered_sign_at (polynomial.cpp)
      if (std::isfinite(y) && std::isfinite(bound) && bound >= std::ldexp(1.0, -900)) {
        if (y > err) return 1;
        if (y < -err) return -1;
      }
    }
    return p_.sign_at(Integer(k), bits_);
  }

  const Polynomial& p_;
  const DoubleCoefficients& approx_;
  int bits_;
  std::vector<Iv> coeff_, deriv_;
};

}  // namespace

FailureFilterResult filtered_next_failure(const Polynomial& p, const DoubleCoefficients& approx, int bits,
                                          std::int64_t a, std::int64_t b) {
  KMR_CHECK(!p.is_zero(), "filtered_next_failure of the zero polynomial");
  KMR_CHECK(bits >= 0 && bits <= 62, "filtered_next_failure: lattice bits must be in [0, 62]");
  return Filter(p, approx, bits).run(a, b);
}

}  // namespace kmr::poly
