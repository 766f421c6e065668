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
//  * BruteSturm counts distinct real roots in [a, b) with its own classical Sturm sequence over exact
//    rationals (Boost mpq, Euclidean remainders, square-free part by exact division): no code of
//    kmr::poly's Sturm sequences, pseudo-remainders, gcd or sign filter; only Polynomial's
//    coefficient list is read.
//  * FUZZ_CHECK prints the case and aborts, so libFuzzer and the replay runner both report it.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <boost/multiprecision/gmp.hpp>

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

// An independent root counter (see the header comment): Euclid over rationals, each member scaled by
// a positive rational to a primitive integer polynomial (signs unchanged), the classical Sturm theorem.
class BruteSturm {
 public:
  using Q = boost::multiprecision::mpq_rational;
  using QPoly = std::vector<Q>;  // c0..cn, no trailing zeros

  explicit BruteSturm(const Polynomial& p) {
    QPoly f;
    for (int i = 0; i <= p.degree(); ++i) f.push_back(Q(p[i].str()));
    trim(f);
    QPoly g = f, h = derivative(f);  // gcd(f, f') by Euclid
    while (!h.empty()) {
      QPoly r = normalized(rem(g, h));
      g = h;
      h = r;
    }
    std::vector<QPoly> seq{normalized(quotient(f, g))};  // square-free part, same distinct roots
    seq.push_back(normalized(derivative(seq[0])));
    while (!seq.back().empty()) {
      QPoly r = rem(seq[seq.size() - 2], seq.back());
      for (auto& c : r) c = -c;
      seq.push_back(normalized(r));
    }
    seq.pop_back();
    for (const auto& q : seq) {
      std::vector<Integer> z;
      for (const auto& c : q) z.push_back(Integer(boost::multiprecision::numerator(c).str()));
      seq_.push_back(std::move(z));
    }
  }
  // Distinct real roots in [m1/2^s, m2/2^s), m1 < m2.
  int count(const Integer& m1, const Integer& m2, unsigned s) const {
    int in_open_closed = variations(m1, s) - variations(m2, s);  // roots in (a, b]
    return in_open_closed + (sign(seq_[0], m1, s) == 0) - (sign(seq_[0], m2, s) == 0);
  }
  int distinct_real_roots() const {
    int minus = 0, plus = 0, last_m = 0, last_p = 0;
    for (const auto& q : seq_) {
      int sp = q.back().sign(), sm = (q.size() % 2 == 1) ? sp : -sp;
      if (last_p != 0 && sp != last_p) ++plus;
      if (last_m != 0 && sm != last_m) ++minus;
      last_p = sp;
      last_m = sm;
    }
    return minus - plus;
  }

 private:
  static void trim(QPoly& p) {
    while (!p.empty() && p.back() == 0) p.pop_back();
  }
  static QPoly derivative(const QPoly& p) {
    QPoly d;
    for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * Q(static_cast<long>(i)));
    trim(d);
    return d;
  }
  // p times the positive rational that makes it a primitive integer polynomial.
  static QPoly normalized(QPoly p) {
    if (p.empty()) return p;
    Integer l(1), g(0);
    for (const auto& c : p) {
      Integer d(boost::multiprecision::denominator(c).str());
      l = l / boost::multiprecision::gcd(l, d) * d;
    }
    for (auto& c : p) {
      c *= Q(l.str());
      g = boost::multiprecision::gcd(g, Integer(boost::multiprecision::numerator(c).str()));
    }
    for (auto& c : p) c /= Q(abs(g).str());
    return p;
  }
  static QPoly rem(QPoly a, const QPoly& b) {
    while (!a.empty() && a.size() >= b.size()) {
      Q f = a.back() / b.back();
      std::size_t sh = a.size() - b.size();
      for (std::size_t j = 0; j < b.size(); ++j) a[sh + j] -= f * b[j];
      a.pop_back();
      trim(a);
    }
    return a;
  }
  static QPoly quotient(QPoly a, const QPoly& b) {
    QPoly q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0);
    while (!a.empty() && a.size() >= b.size()) {
      Q f = a.back() / b.back();
      std::size_t sh = a.size() - b.size();
      q[sh] = f;
      for (std::size_t j = 0; j < b.size(); ++j) a[sh + j] -= f * b[j];
      a.pop_back();
      trim(a);
    }
    FUZZ_CHECK(a.empty(), "BruteSturm: inexact division");
    return q;
  }
  // Sign of q(m / 2^s), homogeneous Horner in integers.
  static int sign(const std::vector<Integer>& q, const Integer& m, unsigned s) {
    std::size_t n = q.size() - 1;
    Integer acc = q[n];
    for (std::size_t i = n; i-- > 0;) acc = acc * m + (q[i] << static_cast<unsigned>(s * (n - i)));
    return acc.sign();
  }
  int variations(const Integer& m, unsigned s) const {
    int v = 0, last = 0;
    for (const auto& q : seq_) {
      int sg = sign(q, m, s);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++v;
      last = sg;
    }
    return v;
  }
  std::vector<std::vector<Integer>> seq_;
};

}  // namespace kmr_fuzz
