// kmr roots: the lattice root solver on one polynomial (§2.1).
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/formats.hpp"
#include "exact/error.hpp"
#include "poly/sturm.hpp"

namespace kmr::cli {

int roots_command(const Argv& argv) {
  Args args(argv, {"lattice-bits", "from", "to"}, {});
  if (args.help()) {
    std::cout << "usage: kmr roots [--lattice-bits B] [--from T0] [--to T1] -- c0 c1 ... cn\n"
                 "Isolates the real roots of p(t) = c0 + c1·t + ... + cn·t^n (decimal integers of any size)\n"
                 "to the lattice δ = 2^-B (default B = 10) in the window [T0, T1) (decimal dyadics; default\n"
                 "[0, 2^27)). Prints JSON: {\"degree\", \"distinct_real_roots\" (all of them, anywhere),\n"
                 "\"intervals\": [{\"k\", \"roots\", \"sign_change\"}]}: each lattice interval [kδ,(k+1)δ) with\n"
                 "T0 ≤ kδ < T1 holding distinct roots, and whether the sign just before (k+1)δ differs from\n"
                 "the sign just before kδ. Put '--' before the coefficients so negative ones are not options.\n"
                 "Exit status 2 on bad input (including the zero polynomial).\n";
    return 0;
  }
  RootsRequest r = parse_roots_request(args);
  const int bits = r.bits;
  const exact::Dyadic &from = r.from, &to = r.to;
  const std::vector<exact::Integer>& coefficients = r.coefficients;
  poly::Polynomial p(coefficients);
  if (p.is_zero()) throw InputError("the zero polynomial has no isolated roots");
  poly::LatticeRootSolver solver(p, bits);
  std::cout << "{\"degree\": " << p.degree() << ", \"distinct_real_roots\": " << solver.distinct_real_roots()
            << ", \"intervals\": [";
  bool first = true;
  for (const auto& i : solver.isolate(from, to)) {
    std::cout << (first ? "" : ", ") << "{\"k\": " << i.k << ", \"roots\": " << i.roots
              << ", \"sign_change\": " << (i.sign_change ? "true" : "false") << "}";
    first = false;
  }
  std::cout << "]}\n";
  return 0;
}

}  // namespace kmr::cli
