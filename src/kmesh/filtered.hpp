#pragma once
// Filtered exact predicates on dyadic points: each is first decided on interval enclosures
// (exact::IntervalNT, which throws Uncertain instead of guessing) and, when that cannot decide,
// recomputed exactly on the Dyadic coordinates. The answers are therefore always the exact ones.
// Enclosure of a Dyadic: Dyadic::to_double is within 1.1·2^-53 relative (60-bit truncation, then one
// rounding), so [d − (|d|·2^-51 + 2^-1000), d + (…)] widened by one ulp holds the value; magnitudes
// above 2^900 are not enclosed (every predicate then goes exact).
#include <array>
#include <cmath>

#include "exact/interval_nt.hpp"
#include "geometry/predicates.hpp"
#include "kmesh/satellites.hpp"

namespace kmr::kmesh {

using exact::IntervalNT;
struct IPoint {
  std::array<IntervalNT, 2> c;
  bool ok = false;  // false: out of range, always decide exactly
};

inline IPoint enclose(const Point2& p) {
  IPoint e;
  e.ok = true;
  for (int i = 0; i < 2; ++i) {
    double d = p[i].to_double();
    if (!(std::abs(d) < 0x1p900)) {
      e.ok = false;
      return e;
    }
    double w = std::abs(d) * 0x1p-51 + 0x1p-1000;
    e.c[i] = IntervalNT::hull(exact::next_down(d - w), exact::next_up(d + w));
  }
  return e;
}

// sign(|pq|² − (k·kScale)²·4^ℓ) ≤ 0, i.e. |pq| ≤ k·2^ℓ in input units.
bool within_exact(const Point2& p, const Point2& q, std::int64_t k, std::int64_t l);
inline bool within_filtered(const Point2& p, const IPoint& pe, const Point2& q, const IPoint& qe, std::int64_t k,
                            std::int64_t l) {
  if (pe.ok && qe.ok && l > -400 && l < 400) {
    try {
      IntervalNT dx = pe.c[0] - qe.c[0], dy = pe.c[1] - qe.c[1];
      IntervalNT kl(double(k) * double(kScale));
      IntervalNT T = kl * kl * IntervalNT(std::ldexp(1.0, static_cast<int>(2 * l)));
      return (dx * dx + dy * dy - T).sign() <= 0;
    } catch (const exact::Uncertain&) {
    }
  }
  return within_exact(p, q, k, l);
}

// sign(|pa|² − |pb|²).
inline int compare_distance(const Point2& p, const IPoint& pe, const Point2& a, const IPoint& ae, const Point2& b,
                            const IPoint& be) {
  if (pe.ok && ae.ok && be.ok) {
    try {
      return geometry::compare_squared_distance_value<2, IntervalNT>(pe.c, ae.c, be.c).sign();
    } catch (const exact::Uncertain&) {
    }
  }
  return geometry::compare_squared_distance<2, Dyadic>(p, a, b);
}

inline int orientation_filtered(const Point2& a, const IPoint& ae, const Point2& b, const IPoint& be, const Point2& c,
                                const IPoint& ce) {
  if (ae.ok && be.ok && ce.ok) {
    try {
      return geometry::orientation_value<IntervalNT>(ae.c, be.c, ce.c).sign();
    } catch (const exact::Uncertain&) {
    }
  }
  return geometry::orientation<Dyadic>(a, b, c);
}

inline int side_of_circle_filtered(const Point2& p, const IPoint& pe, const Point2& q, const IPoint& qe,
                                   const Point2& r, const IPoint& re, const Point2& t, const IPoint& te) {
  if (pe.ok && qe.ok && re.ok && te.ok) {
    try {
      return geometry::side_of_oriented_circle_value<IntervalNT>(pe.c, qe.c, re.c, te.c).sign();
    } catch (const exact::Uncertain&) {
    }
  }
  return geometry::side_of_oriented_circle<Dyadic>(p, q, r, t);
}

}  // namespace kmr::kmesh
