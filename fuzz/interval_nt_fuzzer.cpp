// Fuzz harness (e): exact::IntervalNT against exact rationals.
// Any byte string decodes to ≤ 8 doubles (raw bits: NaN, ∞, subnormals and huge values included)
// and a straight-line program of ≤ 24 operations (+, −, ×, ÷ on registers). Every register is kept
// as an IntervalNT and as an exact rational; the harness checks the guarantees of interval_nt.hpp:
//  * enclosure: the exact value lies in the interval after every operation that did not throw;
//  * decisions are never guessed: sign(), <, <= and == either throw Uncertain or answer exactly;
//  * a non-finite input or an unrepresentable result throws Uncertain (never a wrong interval).
// Every run is bounded: ≤ 24 operations on values of ≤ 2^14 bits.
#include <cmath>
#include <cstring>
#include <string>

#include "exact/interval_nt.hpp"
#include "fuzz_common.hpp"

using kmr::exact::IntervalNT;
using kmr::exact::Uncertain;
using Q = boost::multiprecision::mpq_rational;
using kmr_fuzz::ByteReader;

namespace {

struct Reg {
  bool ok = false;  // false: the interval threw (or the exact value is undefined); not used again
  IntervalNT i;
  Q q;
};

bool holds(const IntervalNT& x, const Q& q) { return Q(x.lo()) <= q && q <= Q(x.hi()); }

// Size of an exact value in bits; repeated squaring doubles it, so the harness stops a register
// at 2^14 bits to keep every run fast (intervals of tiny products no longer throw, so such
// chains are not cut by Uncertain).
std::size_t bits(const Q& q) {
  const auto* r = q.backend().data();
  return mpz_sizeinbase(mpq_numref(r), 2) + mpz_sizeinbase(mpq_denref(r), 2);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Reg r[8];
  int n = 1 + in.byte() % 8;
  for (int k = 0; k < n; ++k) {
    std::uint64_t bits = 0;
    for (int b = 0; b < 8; ++b) bits = bits << 8 | in.byte();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    try {
      r[k].i = IntervalNT(x);
      r[k].q = Q(x);
      r[k].ok = true;
      FUZZ_CHECK(r[k].i.is_point() && r[k].i.lo() == x, "a double is a point interval");
    } catch (const Uncertain&) {
      FUZZ_CHECK(!std::isfinite(x), "a finite double was refused");
    }
  }
  int ops = in.byte() % 25;
  for (int s = 0; s < ops; ++s) {
    int op = in.byte() % 4, a = in.byte() % n, b = in.byte() % n, d = in.byte() % n;
    if (!r[a].ok || !r[b].ok) continue;
    if (bits(r[a].q) + bits(r[b].q) > (1u << 14)) {
      r[d].ok = false;
      continue;
    }
    if (op == 3 && r[b].q == 0) {
      bool refused = false;
      try {
        (void)(r[a].i / r[b].i);
      } catch (const Uncertain&) {
        refused = true;
      }
      FUZZ_CHECK(refused, "division by an interval holding 0 was not refused");
      continue;
    }
    Q q;
    if (op == 0) q = r[a].q + r[b].q;
    else if (op == 1) q = r[a].q - r[b].q;
    else if (op == 2) q = r[a].q * r[b].q;
    else q = r[a].q / r[b].q;
    try {
      IntervalNT x = op == 0 ? r[a].i + r[b].i : op == 1 ? r[a].i - r[b].i : op == 2 ? r[a].i * r[b].i : r[a].i / r[b].i;
      FUZZ_CHECK(holds(x, q), "enclosure, op " + std::to_string(op));
      r[d] = {true, x, q};
    } catch (const Uncertain&) {
      r[d].ok = false;
    }
    // decisions on the new value and against another register
    if (!r[d].ok) continue;
    try {
      FUZZ_CHECK(r[d].i.sign() == r[d].q.sign(), "sign");
    } catch (const Uncertain&) {
    }
    const Reg& o = r[a];
    if (!o.ok) continue;
    try {
      FUZZ_CHECK((r[d].i < o.i) == (r[d].q < o.q), "<");
    } catch (const Uncertain&) {
    }
    try {
      FUZZ_CHECK((r[d].i <= o.i) == (r[d].q <= o.q), "<=");
    } catch (const Uncertain&) {
    }
    try {
      FUZZ_CHECK((r[d].i == o.i) == (r[d].q == o.q), "==");
    } catch (const Uncertain&) {
    }
  }
  return 0;
}
