#include "poly/machine_polynomial.hpp"

#include <gmp.h>

#include "exact/error.hpp"

namespace kmr::poly {

void MachinePolynomial::overflow() {
  throw ContractError("MachinePolynomial: __int128 overflow or degree above 3");
}

Integer to_integer(__int128 c) {
  const bool negative = c < 0;
  unsigned __int128 m = negative ? -static_cast<unsigned __int128>(c) : static_cast<unsigned __int128>(c);
  const std::uint64_t words[2] = {static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(m >> 64)};
  Integer r;
  mpz_import(r.backend().data(), 2, -1, sizeof(std::uint64_t), 0, 0, words);  // least significant word first
  return negative ? Integer(-r) : r;
}

Polynomial MachinePolynomial::to_polynomial() const {
  std::vector<Integer> c;
  c.reserve(static_cast<std::size_t>(degree_ + 1));
  for (int i = 0; i <= degree_; ++i) c.push_back(to_integer(c_[static_cast<std::size_t>(i)]));
  return Polynomial(std::move(c));
}

}  // namespace kmr::poly
