#pragma once
// Shared decoding and brute-force references for the root-solver fuzz harnesses.
//
// Guarantees:
//  * decode_case turns any byte string into a *bounded* case: degree ≤ 16, coefficients ≤ 64 bits
//    (≤ 256 bits for a few), lattice bits 0..8, a window of at most 48 lattice intervals around
//    k0 ∈ [−128, 127]; so every run of a harness is fast and never hangs. Half of the inputs plant
//    roots on lattice points of the window (with multiplicities) to reach the degenerate cases.
//  * brute_sign and brute_sign_before use only exact::Integer arithmetic written here, not
//    kmr::poly's evaluation: brute_sign expands Σ ci·m^i·2^(s(n−i)) term by term, and
//    brute_sign_before reads the lowest nonzero Taylor coefficient of p at kδ (binomial expansion).
//  * FUZZ_CHECK prints the case and aborts, so libFuzzer and the replay runner both report it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "poly/polynomial.hpp"

namespace kmr_fuzz {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::poly::Polynomial;

#define FUZZ_CHECK(cond, what)                                                                          \
  do {                                                                                                  \
    if (!(cond)) {                                                                                      \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s) at %s:%d\n", #cond, std::string(what).c_str(), \
                   __FILE__, __LINE__);                                                                 \
      std::abort();                                                                                     \
    }                                                                                                   \
  } while (0)

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : d_(data), n_(size) {}
  std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
  bool empty() const { return i_ >= n_; }
  Integer integer(int max_bytes) {  // sign from one byte, then up to max_bytes magnitude bytes
    std::uint8_t head = byte();
    int len = max_bytes == 0 ? 0 : head % (max_bytes + 1);
    Integer x(0);
    for (int j = 0; j < len; ++j) x = (x << 8) + Integer(byte());
    return (head & 0x80) ? Integer(-x) : x;
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

struct Case {
  Polynomial p;
  int bits = 0;      // δ = 2^−bits
  Integer k0;        // window [k0·δ, (k0 + width)·δ)
  int width = 1;
  std::string describe() const {
    return "p = " + p.to_string() + ", bits = " + std::to_string(bits) + ", window k in [" + k0.str() + ", " +
           Integer(k0 + width).str() + ")";
  }
};

inline Case decode_case(ByteReader& in) {
  Case c;
  int mode = in.byte();
  c.bits = in.byte() % 9;
  c.k0 = Integer(static_cast<int>(in.byte()) - 128);
  c.width = 1 + in.byte() % 48;
  int max_bytes = (mode & 0x40) ? 32 : 8;
  if (mode & 1) {
    // Planted: Π (2^bits·t − k)^m with k near the window, times a small free factor.
    Polynomial p(1);
    int degree = 0, roots = 1 + in.byte() % 6;
    for (int r = 0; r < roots && degree < 16; ++r) {
      int m = 1 + in.byte() % 3;
      if (degree + m > 16) break;
      Integer k = c.k0 + Integer(static_cast<int>(in.byte() % (c.width + 2)) - 1);
      Polynomial f(std::vector<Integer>{-k, Integer(1) << c.bits});
      for (int j = 0; j < m; ++j) p = p * f;
      degree += m;
    }
    int extra = in.byte() % 3;  // degree of the free factor
    std::vector<Integer> q;
    for (int j = 0; j <= extra && degree + j <= 16; ++j) q.push_back(in.integer(max_bytes));
    Polynomial fq(q);
    c.p = fq.is_zero() ? p : p * fq;
  } else {
    int degree = in.byte() % 17;
    std::vector<Integer> coeffs;
    for (int j = 0; j <= degree; ++j) coeffs.push_back(in.integer(max_bytes));
    c.p = Polynomial(coeffs);
  }
  return c;
}

// Exact sign of p(m / 2^s), term by term (independent of Polynomial::sign_at).
inline int brute_sign(const Polynomial& p, const Integer& m, unsigned s) {
  int n = p.degree();
  Integer sum(0), mp(1);
  for (int i = 0; i <= n; ++i) {
    sum += p[i] * mp * (Integer(1) << (s * static_cast<unsigned>(n - i)));
    mp *= m;
  }
  return sum.sign();
}

// Sign of p just before kδ: P(s) = 2^(bits·n)·p(s·δ) is an integer polynomial; the Taylor expansion
// P(k + u) = Σ Qj u^j has Qj = Σ_{i≥j} Pi·C(i, j)·k^(i−j); the lowest nonzero Qj decides: sign(Qj)·(−1)^j.
inline int brute_sign_before(const Polynomial& p, const Integer& k, int bits) {
  int n = p.degree();
  std::vector<Integer> P(static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) P[static_cast<std::size_t>(i)] = p[i] << static_cast<unsigned>(bits * (n - i));
  for (int j = 0; j <= n; ++j) {
    Integer q(0), binom(1), kp(1);  // C(i, j) and k^(i−j) for i = j, j+1, ...
    for (int i = j; i <= n; ++i) {
      q += P[static_cast<std::size_t>(i)] * binom * kp;
      binom = binom * (i + 1) / (i + 1 - j);
      kp *= k;
    }
    if (!q.is_zero()) return j % 2 == 0 ? q.sign() : -q.sign();
  }
  return 0;  // p ≡ 0
}

}  // namespace kmr_fuzz
