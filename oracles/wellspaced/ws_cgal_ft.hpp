#pragma once
// Internal, CGAL TUs only: an exact Dyadic as a CGAL lazy-exact number (FT = Lazy_exact_nt<ET>,
// ET the Exact_field_selector type: Gmpq, mpq_class or Boost mpq, all built from an mpq_t).
// Guarantees: exact; the double fast path is taken only when the value is exactly a double.
#include "ws_exact_q.hpp"

namespace kmr::oracle::ws::detail {

template <class FT, class ET>
FT to_ft(const exact::Dyadic& d) {
  double x;
  if (exact_double(d, x)) return FT(x);
  Q q = to_q(d);
  return FT(ET(q.backend().data()));
}

}  // namespace kmr::oracle::ws::detail
