// Fuzz harness (a): Sturm counts vs reported lattice intervals vs exact evaluation.
// For a bounded random polynomial and window (fuzz_common.hpp) it checks:
//  * count_roots over consecutive dyadic sample points x_j = k0·δ + j·δ/4 is additive and never 0
//    where exact evaluation shows a root (a zero at x_j, or opposite signs at x_j and x_{j+1});
//  * the distinct roots of each reported lattice interval equal count_roots over that interval, and
//    the reported intervals sum to count_roots over the window;
//  * 0 ≤ counts ≤ distinct_real_roots ≤ degree; a sign difference at ±∞ forces a real root;
//  * the zero polynomial is refused with InputError.
#include "exact/error.hpp"
#include "fuzz_common.hpp"
#include "poly/sturm.hpp"

using namespace kmr_fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Case c = decode_case(in);
  if (c.p.is_zero()) {
    bool refused = false;
    try {
      kmr::poly::SturmSequence s(c.p);
    } catch (const kmr::InputError&) {
      refused = true;
    }
    FUZZ_CHECK(refused, "zero polynomial accepted");
    return 0;
  }
  std::string what = c.describe();
  kmr::poly::SturmSequence s(c.p);
  int n = c.p.degree();
  FUZZ_CHECK(s.distinct_real_roots() >= 0 && s.distinct_real_roots() <= n, what);
  int sign_minus_inf = n % 2 == 0 ? c.p.sign() : -c.p.sign();
  if (sign_minus_inf != c.p.sign()) FUZZ_CHECK(s.distinct_real_roots() >= 1, what);
  unsigned sb = static_cast<unsigned>(c.bits + 2);  // sample step δ/4
  Integer m0 = c.k0 << 2;
  int samples = 4 * c.width, total = 0;
  for (int j = 0; j < samples; ++j) {
    Integer a = m0 + j, b = a + 1;
    int cnt = s.count_roots(Dyadic(a, -static_cast<int>(sb)), Dyadic(b, -static_cast<int>(sb)));
    FUZZ_CHECK(cnt >= 0 && cnt <= s.distinct_real_roots(), what);
    int sa = brute_sign(c.p, a, sb), sbv = brute_sign(c.p, b, sb);
    if (sa == 0 || (sbv != 0 && sa != sbv)) FUZZ_CHECK(cnt >= 1, what + " sample " + std::to_string(j));
    total += cnt;
  }
  Dyadic lo(c.k0, -c.bits), hi(c.k0 + c.width, -c.bits);
  FUZZ_CHECK(s.count_roots(lo, hi) == total, what);
  kmr::poly::LatticeRootSolver solver(c.p, c.bits);
  int reported = 0;
  for (const auto& i : solver.isolate(lo, hi)) {
    FUZZ_CHECK(i.roots >= 1, what);
    FUZZ_CHECK(i.roots == s.count_roots(Dyadic(i.k, -c.bits), Dyadic(i.k + 1, -c.bits)), what);
    reported += i.roots;
  }
  FUZZ_CHECK(reported == total, what);
  return 0;
}
