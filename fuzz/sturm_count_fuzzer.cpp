// Fuzz harness (a): Sturm counts and lattice intervals judged by an independent root counter.
// For a bounded random polynomial and window (fuzz_common.hpp) it checks, against BruteSturm (its
// own Sturm sequence over exact rationals, sharing no code with kmr::poly's):
//  * distinct_real_roots equals the brute count over the real line;
//  * count_roots over each sub-window [x_j, x_{j+1}) of the dyadic samples x_j = k0·δ + j·δ/4
//    equals the brute count there (both directions: over- and undercounts fail), and over the
//    whole window too; exact term-by-term evaluation (brute_sign) also sees every zero and sign
//    change of the samples as a root;
//  * every lattice interval of the window with a brute-force root is reported by isolate, with
//    exactly the brute count, and no other interval is reported;
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
  BruteSturm brute(c.p);
  FUZZ_CHECK(s.distinct_real_roots() == brute.distinct_real_roots(), what + " distinct_real_roots");
  int sign_minus_inf = n % 2 == 0 ? c.p.sign() : -c.p.sign();
  if (sign_minus_inf != c.p.sign()) FUZZ_CHECK(s.distinct_real_roots() >= 1, what);
  unsigned sb = static_cast<unsigned>(c.bits + 2);  // sample step δ/4
  Integer m0 = c.k0 << 2;
  int samples = 4 * c.width, total = 0;
  for (int j = 0; j < samples; ++j) {
    Integer a = m0 + j, b = a + 1;
    int cnt = s.count_roots(Dyadic(a, -static_cast<int>(sb)), Dyadic(b, -static_cast<int>(sb)));
    FUZZ_CHECK(cnt >= 0 && cnt <= s.distinct_real_roots(), what);
    FUZZ_CHECK(cnt == brute.count(a, b, sb), what + " sample " + std::to_string(j) + " count");
    int sa = brute_sign(c.p, a, sb), sbv = brute_sign(c.p, b, sb);
    if (sa == 0 || (sbv != 0 && sa != sbv)) FUZZ_CHECK(cnt >= 1, what + " sample " + std::to_string(j));
    total += cnt;
  }
  Dyadic lo(c.k0, -c.bits), hi(c.k0 + c.width, -c.bits);
  unsigned lb = static_cast<unsigned>(c.bits);
  int window = brute.count(c.k0, c.k0 + c.width, lb);
  FUZZ_CHECK(s.count_roots(lo, hi) == window && total == window, what + " window count");
  kmr::poly::LatticeRootSolver solver(c.p, c.bits);
  std::vector<Integer> expected;  // lattice intervals with a root, by brute force
  for (int j = 0; j < c.width; ++j)
    if (brute.count(c.k0 + j, c.k0 + j + 1, lb) > 0) expected.push_back(c.k0 + j);
  std::size_t next = 0;
  for (const auto& i : solver.isolate(lo, hi)) {
    FUZZ_CHECK(next < expected.size() && i.k == expected[next], what + " reported k = " + i.k.str());
    FUZZ_CHECK(i.roots == brute.count(i.k, i.k + 1, lb), what + " roots at k = " + i.k.str());
    ++next;
  }
  FUZZ_CHECK(next == expected.size(), what + " intervals missing");
  return 0;
}
