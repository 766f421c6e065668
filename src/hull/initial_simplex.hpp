#pragma once
// §2.2 step 1: the initial tetrahedron conv(A_4) — the first four affinely independent points in
// priority order: a = p_1; b the first point ≠ a; c the first point not collinear with a, b; d the
// first point not coplanar with a, b, c. Guarantees: exact decisions (kernel); if no such four
// points exist (all points equal, collinear or coplanar) an InputError says which.
#include <array>
#include <string>
#include <vector>

#include "exact/error.hpp"

namespace kmr::hull {

template <class Kernel>
std::array<int, 4> initial_simplex(const std::vector<int>& order, Kernel& k) {
  const std::size_t n = order.size();
  if (n == 0) throw InputError("no points: a 3D hull needs at least four affinely independent points");
  const int a = order[0];
  std::size_t i = 1;
  while (i < n && k.equal(a, order[i])) ++i;
  if (i == n) throw InputError("all points are equal: a 3D hull needs four affinely independent points");
  const int b = order[i];
  while (i < n && k.collinear(a, b, order[i])) ++i;
  if (i == n) throw InputError("all points are collinear: a 3D hull needs four affinely independent points");
  const int c = order[i];
  while (i < n && k.orientation(a, b, c, order[i]) == 0) ++i;
  if (i == n) throw InputError("all points are coplanar: a 3D hull needs four affinely independent points");
  return {a, b, c, order[i]};
}

}  // namespace kmr::hull
