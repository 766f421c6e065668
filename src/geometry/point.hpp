#pragma once
// Point<D, NT>: a point of R^D with coordinates in a ring NT (Integer, Dyadic, or, for a moving
// point, a Polynomial in time). Guarantees: plain value semantics; no arithmetic is rounded.
#include <array>
#include <cstddef>

namespace kmr::geometry {

template <std::size_t D, class NT>
using Point = std::array<NT, D>;

template <std::size_t D, class NT>
Point<D, NT> operator-(const Point<D, NT>& a, const Point<D, NT>& b) {
  Point<D, NT> r;
  for (std::size_t i = 0; i < D; ++i) r[i] = a[i] - b[i];
  return r;
}

// Σ a_i·b_i and |a − b|² in NT's arithmetic, summed in coordinate order (for doubles: the same
// rounding as any loop that sums in that order).
template <std::size_t D, class NT>
NT dot(const Point<D, NT>& a, const Point<D, NT>& b) {
  NT s = 0;
  for (std::size_t i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}
template <std::size_t D, class NT>
NT dist2(const Point<D, NT>& a, const Point<D, NT>& b) {
  NT s = 0;
  for (std::size_t i = 0; i < D; ++i) {
    NT d = a[i] - b[i];
    s += d * d;
  }
  return s;
}

}  // namespace kmr::geometry
