#pragma once
// Exact geometric predicates, written once over any ring NT.
//
// Each predicate comes in two forms:
//  * `<name>_value(...)` returns the determinant whose sign decides the predicate. Over Integer or
//    Dyadic it is a number; over Polynomial (coordinates that are polynomials of time) it is the
//    predicate's *certificate polynomial* (§2.1): e.g. orientation_value of four linearly moving
//    points in 3D is a cubic in t.
//  * `<name>(...)` returns its sign (−1, 0, +1) for exact scalar rings.
//
// Sign conventions follow CGAL (and are checked against CGAL by the oracle tests):
//  * orientation(a, b, c) > 0   iff a, b, c make a left turn (counterclockwise).
//  * orientation(p, q, r, s) > 0 iff s lies on the positive side of the oriented plane pqr,
//    i.e. det[q−p, r−p, s−p] > 0.
//  * side_of_oriented_circle(p, q, r, t) > 0 iff t lies inside the circle through p, q, r when
//    orientation(p, q, r) > 0 (outside when it is < 0); 0 iff cocircular.
//  * side_of_oriented_sphere(p, q, r, s, t) > 0 iff t lies inside the sphere through p, q, r, s when
//    orientation(p, q, r, s) > 0; 0 iff cospherical.
//  * compare_squared_distance(p, q, r) = sign(|p−q|² − |p−r|²).
// All are exact: no rounding ever happens, so the answers are the true signs.
#include <cstddef>

#include "geometry/point.hpp"

namespace kmr::geometry {

template <class NT>
int sign_of(const NT& x) {
  return x.sign();
}

template <class NT>
NT det2(const NT& a, const NT& b, const NT& c, const NT& d) {
  return a * d - b * c;
}

template <class NT>
NT det3(const NT& a, const NT& b, const NT& c, const NT& d, const NT& e, const NT& f, const NT& g,
        const NT& h, const NT& i) {
  return a * det2<NT>(e, f, h, i) - b * det2<NT>(d, f, g, i) + c * det2<NT>(d, e, g, h);
}

template <std::size_t D, class NT>
NT squared_norm(const Point<D, NT>& v) {
  NT s = v[0] * v[0];
  for (std::size_t i = 1; i < D; ++i) s = s + v[i] * v[i];
  return s;
}

template <std::size_t D, class NT>
NT squared_distance(const Point<D, NT>& a, const Point<D, NT>& b) {
  return squared_norm<D, NT>(a - b);
}

template <class NT>
NT orientation_value(const Point<2, NT>& a, const Point<2, NT>& b, const Point<2, NT>& c) {
  auto u = b - a, v = c - a;
  return det2<NT>(u[0], u[1], v[0], v[1]);
}

template <class NT>
NT orientation_value(const Point<3, NT>& p, const Point<3, NT>& q, const Point<3, NT>& r,
                     const Point<3, NT>& s) {
  auto u = q - p, v = r - p, w = s - p;
  return det3<NT>(u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2]);
}

template <class NT>
NT side_of_oriented_circle_value(const Point<2, NT>& p, const Point<2, NT>& q, const Point<2, NT>& r,
                                 const Point<2, NT>& t) {
  auto a = p - t, b = q - t, c = r - t;
  return det3<NT>(a[0], a[1], squared_norm<2, NT>(a), b[0], b[1], squared_norm<2, NT>(b), c[0], c[1],
                  squared_norm<2, NT>(c));
}

template <class NT>
NT side_of_oriented_sphere_value(const Point<3, NT>& p, const Point<3, NT>& q, const Point<3, NT>& r,
                                 const Point<3, NT>& s, const Point<3, NT>& t) {
  // Expansion of the 4×4 lifted determinant along its last column (lifted coordinates).
  auto a = p - t, b = q - t, c = r - t, d = s - t;
  NT la = squared_norm<3, NT>(a), lb = squared_norm<3, NT>(b), lc = squared_norm<3, NT>(c),
     ld = squared_norm<3, NT>(d);
  NT mb = det3<NT>(a[0], a[1], a[2], c[0], c[1], c[2], d[0], d[1], d[2]);
  NT ma = det3<NT>(b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]);
  NT mc = det3<NT>(a[0], a[1], a[2], b[0], b[1], b[2], d[0], d[1], d[2]);
  NT md = det3<NT>(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
  // det[[a,la],[b,lb],[c,lc],[d,ld]] = −la·ma + lb·mb − lc·mc + ld·md; CGAL's sign is its negation.
  return la * ma - lb * mb + lc * mc - ld * md;
}

template <std::size_t D, class NT>
NT compare_squared_distance_value(const Point<D, NT>& p, const Point<D, NT>& q, const Point<D, NT>& r) {
  return squared_distance<D, NT>(p, q) - squared_distance<D, NT>(p, r);
}

template <class NT>
int orientation(const Point<2, NT>& a, const Point<2, NT>& b, const Point<2, NT>& c) {
  return sign_of(orientation_value(a, b, c));
}
template <class NT>
int orientation(const Point<3, NT>& p, const Point<3, NT>& q, const Point<3, NT>& r, const Point<3, NT>& s) {
  return sign_of(orientation_value(p, q, r, s));
}
template <class NT>
int side_of_oriented_circle(const Point<2, NT>& p, const Point<2, NT>& q, const Point<2, NT>& r,
                            const Point<2, NT>& t) {
  return sign_of(side_of_oriented_circle_value(p, q, r, t));
}
template <class NT>
int side_of_oriented_sphere(const Point<3, NT>& p, const Point<3, NT>& q, const Point<3, NT>& r,
                            const Point<3, NT>& s, const Point<3, NT>& t) {
  return sign_of(side_of_oriented_sphere_value(p, q, r, s, t));
}
template <std::size_t D, class NT>
int compare_squared_distance(const Point<D, NT>& p, const Point<D, NT>& q, const Point<D, NT>& r) {
  return sign_of(compare_squared_distance_value<D, NT>(p, q, r));
}

}  // namespace kmr::geometry
