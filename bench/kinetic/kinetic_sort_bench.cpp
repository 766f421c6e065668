// Kinetic sorting throughput on the lattice motion simulator (§2.1, §2.4 input: positions of
// Bℓ = 20 bits, velocities of Bv = 8 bits, δ = 2^-10, M_t = 2^27).
// usage: kinetic_sort_bench [n = 100000] [events = 200000] [seed = 1] [path = machine|exact|sturm] [degree = 1]
// Prints JSON: events per second (initial run excluded; wall clock and thread CPU time), batch-size histogram, counters, and the
// root-solver work (filter decisions, exact fallbacks, Sturm queries) per event. `exact` runs every
// certificate on the exact path (Polynomial + LatticeRootSolver, GMP), as before the fast path;
// `sturm` keeps the machine path but turns off the double failure filter of exact-path
// certificates (poly/failure_filter.hpp). degree ≥ 2 adds terms a2·t² + ... + ad·t^d with
// |ai| ≤ 2^4 to each trajectory, so every certificate takes the exact path (degree-d polynomials,
// like the hull's orient3d cubics for d = 3).
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <random>
#include <string>

#include "kinetic/kinetic_sort.hpp"
#include "kinetic/trajectory.hpp"

// Thread CPU time: on a loaded machine it excludes the time other processes hold the core.
double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

int main(int argc, char** argv) {
  using namespace kmr;
  std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  long long target = argc > 2 ? std::strtoll(argv[2], nullptr, 10) : 200000;
  std::mt19937_64 rng(argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 1);
  std::vector<poly::Polynomial> x;
  int degree = argc > 5 ? std::atoi(argv[5]) : 1;
  for (auto& t : kinetic::random_linear_trajectories<1>(n, rng)) {
    std::vector<exact::Integer> c = t[0].coefficients();
    c.resize(2);
    for (int d = 2; d <= degree; ++d) c.emplace_back(static_cast<long long>(rng() % 33) - 16);
    x.emplace_back(c);
  }
  // Identical trajectories are refused; with 2^21·2^9 choices per point they are rare: drop them.
  std::sort(x.begin(), x.end(), [](const auto& a, const auto& b) { return a.coefficients() < b.coefficients(); });
  x.erase(std::unique(x.begin(), x.end()), x.end());
  std::string path = argc > 4 ? argv[4] : "machine";
  bool machine = path != "exact";
  kinetic::MotionSimulator sim(10, exact::Dyadic::pow2(27), kinetic::SimulatorOptions{machine, path != "sturm"});
  auto t0 = std::chrono::steady_clock::now();
  kinetic::KineticSort sort(x, sim);
  auto t1 = std::chrono::steady_clock::now();
  double c1 = cpu_seconds();
  while (sim.counters().events < target) {
    auto batch = sim.next_batch(sim.horizon());
    if (!batch) break;
    sort.update(*batch);
  }
  auto t2 = std::chrono::steady_clock::now();
  double cpu = cpu_seconds() - c1;
  double initial = std::chrono::duration<double>(t1 - t0).count(), run = std::chrono::duration<double>(t2 - t1).count();
  const auto& c = sim.counters();
  auto per_event = [&](long long x) { return c.events ? static_cast<double>(x) / c.events : 0.0; };
  std::cout << "{\"path\": \"" << path << "\", \"degree\": " << degree << ", \"n\": " << x.size() << ", \"initial_s\": " << initial << ", \"events\": " << c.events
            << ", \"batches\": " << c.batches << ", \"simulated_until\": \"" << sim.now().to_decimal() << "\""
            << ", \"run_s\": " << run << ", \"events_per_s\": " << (run > 0 ? c.events / run : 0)
            << ", \"us_per_event\": " << (c.events ? 1e6 * run / c.events : 0) << ", \"run_cpu_s\": " << cpu
            << ", \"events_per_cpu_s\": " << (cpu > 0 ? c.events / cpu : 0)
            << ", \"filter_decided_per_event\": " << per_event(c.filter_decided)
            << ", \"exact_fallbacks_per_event\": " << per_event(c.filter_fallbacks)
            << ", \"sturm_queries_per_event\": " << per_event(c.sturm_queries)
            << ", \"poly_filter_decided_per_event\": " << per_event(c.poly_filter_decided)
            << ", \"poly_filter_fallbacks_per_event\": " << per_event(c.poly_filter_fallbacks)
            << ", \"machine_sign_evaluations_per_event\": " << per_event(c.machine_sign_evaluations)
            << ", \"exact_certificates\": " << c.exact_certificates
            << ", \"swaps\": " << sort.swaps() << ", \"max_batch\": " << c.max_batch << ", \"batch_sizes\": {";
  bool first = true;
  for (auto& [size, count] : c.batch_sizes) {
    std::cout << (first ? "" : ", ") << "\"" << size << "\": " << count;
    first = false;
  }
  std::cout << "}}\n";
}
