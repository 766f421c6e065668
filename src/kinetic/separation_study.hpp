#pragma once
// §2.1's claim measured: "once we reach the lattice interval, we can stop without further
// separation, thus avoid potentially expensive separation costs". The same §2.4 motions are sorted
// kinetically by the lattice simulator (machine fast path, or exact path only) and by the classic
// event-at-a-time simulator (classic_simulator.hpp); each run reports its root-solver work and time.
// Guarantees: all runs end in the same order (checked by the caller); the motions are a
// deterministic function of (n, simultaneous, seed).
#include <cstdint>
#include <string>
#include <vector>

#include "poly/polynomial.hpp"

namespace kmr::kinetic {

// n points x0 + V·2^12·t with x0 ∈ [−2^20, 2^20], V ∈ [−2^8, 2^8] (§2.4, Bℓ = 20, Bv = 8), distinct;
// with `simultaneous`, every 10th point instead passes through the place of point 0 at t = 1/8
// (a lattice point for δ ≤ 2^−3), so that crossings at one place and time are frequent.
std::vector<poly::Polynomial> section_2_4_sort_motions(std::size_t n, bool simultaneous, std::uint64_t seed);

struct StudyRun {
  std::string simulator;          // "lattice (machine)", "lattice (exact)", "classic"
  long long events = 0;           // certificate failures processed (classic: one per crossing)
  long long crossings = 0;        // swaps
  long long batches = 0;          // lattice intervals processed (classic: = events)
  long long sturm_queries = 0;    // Sturm queries to lattice resolution (exact-path certificates)
  long long bisection_steps = 0;  // classic: Sturm queries refining failure times below the lattice
  long long machine_steps = 0;    // machine path: failure intervals (filter or __int128) + sign evaluations
  long long ties = 0;             // classic: equal failure times established at the separation bound
  long long root_work() const { return sturm_queries + bisection_steps + machine_steps; }
  double seconds = 0;             // the run, after the initial certificates (thread CPU time)
  std::vector<std::size_t> order; // at the end
};

StudyRun run_lattice_sort(const std::vector<poly::Polynomial>& x, int bits, const exact::Dyadic& until, bool machine);
StudyRun run_classic_sort(const std::vector<poly::Polynomial>& x, int bits, const exact::Dyadic& until);

}  // namespace kmr::kinetic
