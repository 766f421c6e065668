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

}  // namespace kmr::geometry
