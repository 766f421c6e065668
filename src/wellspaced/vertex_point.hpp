#pragma once
// VertexPoint<D>: a vertex of a well-spaced set, a point of [0,1]^D whose coordinates are exact
// dyadic rationals. Inputs and almost all Steiner vertices have double coordinates; a Steiner
// vertex whose picking region holds no double (near-duplicate inputs, issue 11; spec/wellspaced.md,
// "Near-duplicate inputs") has finer ones.
// Guarantees:
//  * One representation per value: a point whose coordinates are all doubles is stored as doubles
//    (is_double()), so such points compare, print and hash exactly as std::array<double, D> did.
//  * == and < are exact and lexicographic by coordinate value (< is a strict weak order; -0.0 and
//    0.0 are equal, as for doubles).
//  * below()[i] is the largest double ≤ coordinate i (the coordinate itself when it is a double).
//  * text(i) is exact: "%a" for a double, otherwise a hex float 0x1.<hex digits>p<exp> with as many
//    digits as needed (spec/formats.md); read_hex_dyadic reads either form back exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>

#include "exact/dyadic.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
using Point = std::array<double, D>;

// The largest double ≤ x for 0 ≤ x ≤ 1 (x itself when it is a double); *exact says which.
inline double dyadic_floor_to_double(const exact::Dyadic& x, bool* exact = nullptr) {
  if (x.is_zero()) {
    if (exact) *exact = true;
    return 0.0;
  }
  const exact::Integer& m = x.mantissa();  // odd, > 0
  const std::int64_t e = x.exponent();
  const std::int64_t b = exact::bit_length(m);
  // keep at most 53 significant bits, and no bit below 2^-1074
  std::int64_t s = std::max<std::int64_t>({0, b - 53, -1074 - e});
  exact::Integer t = m >> static_cast<unsigned>(s);
  if (exact) *exact = (s == 0);
  return std::ldexp(t.convert_to<double>(), static_cast<int>(e + s));
}

template <std::size_t D>
class VertexPoint {
 public:
  VertexPoint() = default;
  VertexPoint(const Point<D>& p) : lo_(p) {}  // every double point (exactly)
  // The point with exact coordinates x (each in [0,1]); stored as doubles when they all are.
  static VertexPoint exactly(const std::array<exact::Dyadic, D>& x) {
    VertexPoint p;
    bool all = true;
    for (std::size_t i = 0; i < D; ++i) {
      bool ex = false;
      p.lo_[i] = dyadic_floor_to_double(x[i], &ex);
      all = all && ex;
    }
    if (!all) p.fine_ = std::make_shared<const std::array<exact::Dyadic, D>>(x);
    return p;
  }
  bool is_double() const { return fine_ == nullptr; }
  bool is_double(std::size_t i) const { return !fine_ || (*fine_)[i] == exact::Dyadic::from_double(lo_[i]); }
  const Point<D>& below() const { return lo_; }
  exact::Dyadic coord(std::size_t i) const { return fine_ ? (*fine_)[i] : exact::Dyadic::from_double(lo_[i]); }
  std::string text(std::size_t i) const {
    if (is_double(i)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%a", lo_[i]);
      return buf;
    }
    // m·2^e = 0x1.<frac>p<e + b − 1>, m odd with b > 53 bits
    const exact::Dyadic& x = (*fine_)[i];
    const exact::Integer& m = x.mantissa();
    const std::int64_t b = exact::bit_length(m);
    const std::int64_t n4 = (b - 1 + 3) / 4;  // hex digits of the fraction
    exact::Integer frac = (m - (exact::Integer(1) << static_cast<unsigned>(b - 1))) << static_cast<unsigned>(4 * n4 - (b - 1));
    std::string h = frac.str(0, std::ios_base::hex);
    h = std::string(static_cast<std::size_t>(n4) - h.size(), '0') + h;
    while (!h.empty() && h.back() == '0') h.pop_back();
    return "0x1." + h + "p" + std::to_string(x.exponent() + b - 1);
  }
  friend bool operator==(const VertexPoint& a, const VertexPoint& b) {
    if (a.lo_ != b.lo_ || (a.fine_ == nullptr) != (b.fine_ == nullptr)) return false;
    return !a.fine_ || *a.fine_ == *b.fine_;
  }
  friend std::weak_ordering operator<=>(const VertexPoint& a, const VertexPoint& b) {
    for (std::size_t i = 0; i < D; ++i) {
      // below() is monotone, so it orders unequal floors; equal floors need the exact values
      if (a.lo_[i] < b.lo_[i]) return std::weak_ordering::less;
      if (b.lo_[i] < a.lo_[i]) return std::weak_ordering::greater;
      if (a.fine_ || b.fine_) {
        auto c = a.coord(i) <=> b.coord(i);
        if (c != 0) return c < 0 ? std::weak_ordering::less : std::weak_ordering::greater;
      }
    }
    return std::weak_ordering::equivalent;
  }

 private:
  Point<D> lo_{};
  std::shared_ptr<const std::array<exact::Dyadic, D>> fine_;  // null: the coordinates are lo_
};

}  // namespace kmr::wellspaced
