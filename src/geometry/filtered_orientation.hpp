#pragma once
// orientation(p, q, r, s) of four points with double coordinates, decided exactly: a static-bound
// floating-point filter in the style of Shewchuk's orient3d (stage A) answers when it can; when it
// cannot, the determinant is evaluated exactly over exact::Dyadic (predicates.hpp).
//
// Guarantees (each is a test in tests/geometry/filtered_orientation_test.cpp):
//  * filtered_orientation(...) == orientation over Dyadic of the same points, for every finite input
//    (the filter never changes an answer; near-degenerate inputs fall back).
//  * Sign convention as predicates.hpp (CGAL): > 0 iff s lies on the positive side of plane pqr,
//    i.e. det[q−p, r−p, s−p] > 0.
//  * orientation_filter(...) returns 0 ("cannot decide") or the certified sign ±1; it never returns a
//    wrong sign.
//
// The bound. With the differences a = p−s, b = q−s, c = r−s rounded to doubles and the determinant
// D = a_z(b_x c_y − c_x b_y) + b_z(c_x a_y − a_x c_y) + c_z(a_x b_y − b_x a_y) evaluated in double
// arithmetic (round to nearest, relative error ε = 2^-53 per operation), Shewchuk (1997, §4.3)
// proves |D̃ − D| ≤ (7 + 56ε)ε · P̃, P̃ the permanent (the same expression with absolute values of
// every product) evaluated in doubles. His proof assumes no overflow and no underflow. We use the
// filter only when every coordinate is 0 or of magnitude in [2^-250, 2^250] (filter_safe): then
// every nonzero difference is ≥ 2^-302 (both operands are multiples of 2^-302) and ≤ 2^251, no
// product or sum overflows, and two-factor products (≥ 2^-604) never underflow. Only the three
// final products a_z·(…) may underflow, each with absolute error ≤ 2^-1075, which the additive
// term 2^-1070 covers (a difference landing in the subnormal range is exact). So
//        |D̃ − D| ≤ (7 + 56ε)ε · P̃ + 2^-1070,
// and sign(D̃) is the true sign whenever |D̃| exceeds that. CGAL's orientation is det[q−p, r−p, s−p]
// = −det[p−s, q−s, r−s], hence the sign flip below.
#include <array>
#include <cmath>

#include "exact/dyadic.hpp"
#include "geometry/predicates.hpp"

namespace kmr::geometry {

using Point3d = std::array<double, 3>;

// The range in which orientation_filter's error bound holds (see above).
inline bool filter_safe(double x) {
  double a = std::fabs(x);
  return a == 0.0 || (a >= 0x1p-250 && a <= 0x1p250);
}
inline bool filter_safe(const Point3d& p) { return filter_safe(p[0]) && filter_safe(p[1]) && filter_safe(p[2]); }

inline constexpr double kOrient3dErrBound = (7.0 + 56.0 * 0x1p-53) * 0x1p-53;  // Shewchuk's o3derrboundA
inline constexpr double kOrient3dAbsBound = 0x1p-1070;                        // final-product underflow

// Certified sign of orientation(p, q, r, s), or 0 when the filter cannot decide. Requires
// filter_safe on all four points (the caller checks once per input). `value` and `bound` receive
// D̃ (in CGAL's sign) and its error bound, for filters built on this one (hull centre tests).
inline int orientation_filter(const Point3d& p, const Point3d& q, const Point3d& r, const Point3d& s,
                              double* value = nullptr, double* bound = nullptr) {
  const double adx = p[0] - s[0], bdx = q[0] - s[0], cdx = r[0] - s[0];
  const double ady = p[1] - s[1], bdy = q[1] - s[1], cdy = r[1] - s[1];
  const double adz = p[2] - s[2], bdz = q[2] - s[2], cdz = r[2] - s[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  const double err = kOrient3dErrBound * permanent + kOrient3dAbsBound;
  if (value) *value = -det;
  if (bound) *bound = err;
  if (det > err) return -1;  // Shewchuk's sign is the negation of CGAL's
  if (-det > err) return 1;
  return 0;
}

inline Point<3, exact::Dyadic> to_dyadic(const Point3d& p) {
  return {exact::Dyadic::from_double(p[0]), exact::Dyadic::from_double(p[1]), exact::Dyadic::from_double(p[2])};
}

// The exact answer, always by Dyadic arithmetic (the fallback; also the reference in tests).
inline int orientation_exact(const Point3d& p, const Point3d& q, const Point3d& r, const Point3d& s) {
  return orientation(to_dyadic(p), to_dyadic(q), to_dyadic(r), to_dyadic(s));
}

// Filtered exact orientation for finite doubles (any magnitude: unsafe ranges go straight to exact).
inline int filtered_orientation(const Point3d& p, const Point3d& q, const Point3d& r, const Point3d& s) {
  if (filter_safe(p) && filter_safe(q) && filter_safe(r) && filter_safe(s))
    if (int sg = orientation_filter(p, q, r, s)) return sg;
  return orientation_exact(p, q, r, s);
}

}  // namespace kmr::geometry
