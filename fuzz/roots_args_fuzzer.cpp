// Fuzz harness (g): the `kmr roots` arguments, through the CLI's own parser (kmr::cli::Args and
// kmr::cli::parse_roots_request, src/cli/formats.hpp). The input is split at NUL bytes into argv.
// Checks:
//  * only kmr::InputError escapes parsing;
//  * an accepted request has 0 ≤ B ≤ 4096, from < to and ≥ 1 coefficient, and every coefficient
//    prints and parses back to itself (decimal round trip);
//  * for small accepted requests (degree ≤ 8, B ≤ 16, coefficients ≤ 128 bits) the zero polynomial
//    is refused with InputError and otherwise the solver runs, its intervals increasing and inside
//    [from, to) (judged by Dyadic comparisons written here).
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "cli/formats.hpp"
#include "exact/error.hpp"
#include "fuzz_common.hpp"
#include "poly/sturm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 2048) return 0;
  std::vector<std::string> argv;
  std::string cur;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) argv.push_back(cur), cur.clear();
    else cur += static_cast<char>(data[i]);
  }
  argv.push_back(cur);
  kmr::cli::RootsRequest r;
  try {
    kmr::cli::Args args(argv, {"lattice-bits", "from", "to"}, {});
    if (args.help()) return 0;
    r = kmr::cli::parse_roots_request(args);
  } catch (const kmr::InputError&) {
    return 0;
  }
  FUZZ_CHECK(r.bits >= 0 && r.bits <= 4096 && r.from < r.to && !r.coefficients.empty(), "accepted request");
  for (const auto& c : r.coefficients) FUZZ_CHECK(kmr::exact::parse_integer(c.str()) == c, c.str());
  kmr::poly::Polynomial p(r.coefficients);
  bool small = r.coefficients.size() <= 9 && r.bits <= 16;
  for (const auto& c : r.coefficients) small = small && kmr::exact::bit_length(c) <= 128;
  if (!small) return 0;
  if (p.is_zero()) {
    bool refused = false;
    try {
      kmr::poly::LatticeRootSolver s(p, r.bits);
    } catch (const kmr::InputError&) {
      refused = true;
    }
    FUZZ_CHECK(refused, "zero polynomial accepted");
    return 0;
  }
  kmr::poly::LatticeRootSolver solver(p, r.bits);
  bool first = true;
  kmr::exact::Integer last;
  for (const auto& i : solver.isolate(r.from, r.to)) {
    kmr::exact::Dyadic at(i.k, -r.bits);
    FUZZ_CHECK(i.roots >= 1 && !(at < r.from) && at < r.to, "interval outside the window: k = " + i.k.str());
    FUZZ_CHECK(first || i.k > last, "intervals not increasing");
    first = false;
    last = i.k;
  }
  return 0;
}
