// §2.1: lattice batching vs exact separation (the classic event-at-a-time simulator), on §2.4 sort
// motions with and without simultaneous events. Runs the three simulators interleaved, `reps`
// rounds, and reports the best time of each; root-solver work is deterministic.
// usage: separation_bench [n = 2000] [until = 1/4 as lattice steps of 2^-10: 256] [reps = 3] [seed = 1]
#include <cstdio>
#include <cstdlib>

#include "exact/error.hpp"
#include "kinetic/separation_study.hpp"

int main(int argc, char** argv) {
  using namespace kmr;
  std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2000;
  long long steps = argc > 2 ? std::strtoll(argv[2], nullptr, 10) : 256;
  int reps = argc > 3 ? std::atoi(argv[3]) : 3;
  std::uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  const int bits = 10;
  exact::Dyadic until(exact::Integer(steps), -bits);
  std::printf("{\"n\": %zu, \"until\": \"%s\", \"lattice_bits\": %d, \"runs\": [\n", n, until.to_decimal().c_str(), bits);
  bool first = true;
  for (bool simultaneous : {false, true}) {
    auto x = kinetic::section_2_4_sort_motions(n, simultaneous, seed);
    std::vector<kinetic::StudyRun> best(3);
    for (int rep = 0; rep < reps; ++rep) {
      kinetic::StudyRun runs[3] = {kinetic::run_lattice_sort(x, bits, until, true),
                                   kinetic::run_lattice_sort(x, bits, until, false),
                                   kinetic::run_classic_sort(x, bits, until)};
      for (int i = 0; i < 3; ++i) {
        KMR_CHECK(runs[i].order == runs[0].order && runs[i].crossings == runs[0].crossings, "simulators disagree");
        if (rep == 0 || runs[i].seconds < best[i].seconds) best[i] = runs[i];
      }
    }
    for (const auto& r : best) {
      std::printf("%s  {\"simultaneous\": %s, \"simulator\": \"%s\", \"events\": %lld, \"crossings\": %lld, \"batches\": %lld, "
                  "\"sturm_queries\": %lld, \"bisection_steps\": %lld, \"machine_steps\": %lld, "
                  "\"root_work_per_crossing\": %.2f, \"ties\": %lld, \"seconds\": %.4f, "
                  "\"us_per_crossing\": %.3f, \"us_per_event\": %.3f}",
                  first ? "" : ",\n", simultaneous ? "true" : "false", r.simulator.c_str(), r.events, r.crossings,
                  r.batches, r.sturm_queries, r.bisection_steps, r.machine_steps,
                  r.crossings ? double(r.root_work()) / r.crossings : 0.0, r.ties, r.seconds,
                  r.crossings ? 1e6 * r.seconds / r.crossings : 0.0, r.events ? 1e6 * r.seconds / r.events : 0.0);
      first = false;
    }
  }
  std::printf("\n]}\n");
}
