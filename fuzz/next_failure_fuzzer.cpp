// Fuzz harness (c): next_failure_after vs brute force. For a start t (a dyadic inside or before the
// window, possibly between lattice points) and the window end as horizon, the answer must be the
// first k with kδ ≥ t, kδ < horizon and brute_sign_before((k+1)δ) ≠ brute_sign_before(kδ)
// (Taylor expansion, fuzz_common.hpp), or none. It must also equal the first sign-changing interval
// that isolate reports, and sign_before / sign_after at lattice points match the Taylor signs.
// With zero_fails (Chapter 4's strict certificates) the answer is the first such k, or the first
// k with kδ > t at which p is exactly zero (brute_sign), whichever comes first.
#include <optional>

#include "fuzz_common.hpp"
#include "poly/sturm.hpp"

using namespace kmr_fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Case c = decode_case(in);
  if (c.p.is_zero()) return 0;
  std::string what = c.describe();
  // t = (k0 + off)·δ − frac·δ/16 with off in [0, width], frac in [0, 15]
  int off = in.byte() % (c.width + 1), frac = in.byte() % 16;
  Dyadic t = Dyadic((c.k0 + off) * 16 - frac, -(c.bits + 4));
  Dyadic horizon(c.k0 + c.width, -c.bits);
  kmr::poly::LatticeRootSolver solver(c.p, c.bits);
  Integer kt = c.k0 + off;  // the first k with kδ ≥ t (t is (k0+off)δ or just below it)
  std::optional<Integer> want;
  for (Integer k = kt; k < c.k0 + c.width; ++k)
    if (brute_sign_before(c.p, k + 1, c.bits) != brute_sign_before(c.p, k, c.bits)) {
      want = k;
      break;
    }
  auto have = solver.next_failure_after(t, horizon);
  FUZZ_CHECK(have == want, what + " t = " + t.to_decimal());
  std::optional<Integer> want_zero;
  for (Integer k = kt; k < c.k0 + c.width && (!want || k <= *want); ++k)
    if (brute_sign(c.p, k, static_cast<unsigned>(c.bits)) == 0 && Dyadic(k, -c.bits) > t) {
      want_zero = k;
      break;
    }
  if (!want_zero) want_zero = want;
  auto have_zero = solver.next_failure_after(t, horizon, /*zero_fails=*/true);
  FUZZ_CHECK(have_zero == want_zero, what + " zero_fails, t = " + t.to_decimal());
  std::optional<Integer> from_isolate;
  for (const auto& i : solver.isolate(t, horizon))
    if (i.sign_change) {
      from_isolate = i.k;
      break;
    }
  FUZZ_CHECK(from_isolate == want, what + " isolate vs next_failure");
  for (int j = 0; j <= c.width; j += 4) {
    Integer k = c.k0 + j;
    Dyadic x(k, -c.bits);
    FUZZ_CHECK(kmr::poly::sign_before(c.p, x) == brute_sign_before(c.p, k, c.bits), what);
    FUZZ_CHECK(kmr::poly::sign_after(c.p, x) == brute_sign_before(c.p.mirrored(), -k, c.bits), what);
  }
  return 0;
}
