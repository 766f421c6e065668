// Fuzz harness (b): lattice isolation vs brute-force evaluation at every lattice point of a small
// window (and at 7 points inside each lattice interval). For each k in the window:
//  * a zero of p at kδ, or a sign change among the samples of [kδ, (k+1)δ], means k is reported;
//  * the reported sign_change equals brute_sign_before((k+1)δ) ≠ brute_sign_before(kδ), computed from
//    the Taylor expansion (fuzz_common.hpp), and an unreported k has no sign change;
//  * reported intervals are increasing, inside the window, and hold ≥ 1 roots;
//  * k is reported exactly when the independent counter BruteSturm (fuzz_common.hpp: its own Sturm
//    sequence over rationals) finds a root in [kδ, (k+1)δ), with exactly that many roots; so an
//    interval reported with no root fails, and so does a wrong root count.
#include <map>

#include "fuzz_common.hpp"
#include "poly/sturm.hpp"

using namespace kmr_fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  Case c = decode_case(in);
  if (c.p.is_zero()) return 0;  // refusal is checked by sturm_count
  std::string what = c.describe();
  kmr::poly::LatticeRootSolver solver(c.p, c.bits);
  Dyadic lo(c.k0, -c.bits), hi(c.k0 + c.width, -c.bits);
  std::map<Integer, kmr::poly::LatticeInterval> reported;
  Integer last = c.k0 - 1;
  for (const auto& i : solver.isolate(lo, hi)) {
    FUZZ_CHECK(i.k > last && i.k < c.k0 + c.width && i.roots >= 1, what);
    last = i.k;
    reported[i.k] = i;
  }
  BruteSturm brute(c.p);
  unsigned fine = static_cast<unsigned>(c.bits + 3);  // δ/8
  for (int j = 0; j < c.width; ++j) {
    Integer k = c.k0 + j;
    bool root_seen = false;
    int prev = 0;
    for (int q = 0; q <= 8; ++q) {
      int sg = brute_sign(c.p, (k << 3) + q, fine);
      if (q < 8 && sg == 0) root_seen = true;
      if (sg != 0 && prev != 0 && sg != prev) root_seen = true;
      if (sg != 0) prev = sg;
    }
    bool change = brute_sign_before(c.p, k + 1, c.bits) != brute_sign_before(c.p, k, c.bits);
    auto it = reported.find(k);
    std::string at = what + " k = " + k.str();
    if (root_seen || change) FUZZ_CHECK(it != reported.end(), at + " missing");
    if (it != reported.end()) FUZZ_CHECK(it->second.sign_change == change, at + " sign_change");
    int roots = brute.count(k, k + 1, static_cast<unsigned>(c.bits));
    FUZZ_CHECK((it != reported.end()) == (roots > 0), at + " reported without a root, or root not reported");
    if (it != reported.end()) FUZZ_CHECK(it->second.roots == roots, at + " root count");
    FUZZ_CHECK(solver.sign_before_lattice(k) == brute_sign_before(c.p, k, c.bits), at + " sign_before");
  }
  return 0;
}
