#pragma once
// Integer: arbitrary-precision integers (Boost.Multiprecision over GMP's mpz).
// Guarantees: every operation is exact; no overflow; division truncates toward zero as in C++.
#include <boost/multiprecision/gmp.hpp>
#include <cstdint>
#include <string>
#include <string_view>

namespace kmr::exact {

// Expression templates off: `auto x = a * b` must be a value, never a dangling expression.
using Integer = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

// Sign of x: -1, 0 or +1.
inline int sign(const Integer& x) { return x.sign(); }

// Number of bits of |x| (0 for 0).
inline std::int64_t bit_length(const Integer& x) {
  return x.is_zero() ? 0 : static_cast<std::int64_t>(boost::multiprecision::msb(abs(x))) + 1;
}

// Parses a decimal integer ("-123", "+7"); throws InputError naming the text on anything else.
Integer parse_integer(std::string_view text);

}  // namespace kmr::exact
