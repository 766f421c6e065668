#include "kinetic/separation_study.hpp"

#include <algorithm>
#include <ctime>
#include <random>

#include "kinetic/classic_simulator.hpp"
#include "kinetic/kinetic_sort.hpp"

namespace kmr::kinetic {

namespace {
// Thread CPU time: on a loaded machine it excludes the time other processes hold the core.
double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
}  // namespace

using exact::Dyadic;
using exact::Integer;
using poly::Polynomial;

std::vector<Polynomial> section_2_4_sort_motions(std::size_t n, bool simultaneous, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 8), 1LL << 8);
  std::vector<std::pair<long long, long long>> m;
  for (std::size_t i = 0; i < n; ++i) m.emplace_back(pos(rng), vel(rng) << 12);
  if (simultaneous && !m.empty())
    for (std::size_t i = 10; i < n; i += 10) {
      long long v = m[0].second + 8 * 4096 * static_cast<long long>(i / 10) * ((i / 10) % 2 ? 1 : -1);
      m[i] = {m[0].first + (m[0].second - v) / 8, v};  // x_i(1/8) = x_0(1/8): v − v0 is a multiple of 8
    }
  std::sort(m.begin(), m.end());
  m.erase(std::unique(m.begin(), m.end()), m.end());
  std::vector<Polynomial> x;
  for (auto& [x0, v] : m) x.emplace_back(std::vector<Integer>{Integer(x0), Integer(v)});
  return x;
}

StudyRun run_lattice_sort(const std::vector<Polynomial>& x, int bits, const Dyadic& until, bool machine) {
  MotionSimulator sim(bits, until, SimulatorOptions{machine});
  KineticSort sort(x, sim);
  const auto& c = sim.counters();
  long long sturm0 = c.sturm_queries, machine0 = c.filter_decided + c.filter_fallbacks + c.machine_sign_evaluations;
  double t0 = cpu_seconds();
  sort.run_until(until);
  StudyRun r;
  r.seconds = cpu_seconds() - t0;
  r.simulator = machine ? "lattice (machine)" : "lattice (exact)";
  r.events = sim.counters().events;
  r.batches = sim.counters().batches;
  r.crossings = sort.swaps();
  r.sturm_queries = c.sturm_queries - sturm0;
  r.machine_steps = c.filter_decided + c.filter_fallbacks + c.machine_sign_evaluations - machine0;
  r.order = sort.order();
  return r;
}

StudyRun run_classic_sort(const std::vector<Polynomial>& x, int bits, const Dyadic& until) {
  ClassicKineticSort sort(x, bits, until);
  const auto& c = sort.counters();
  long long lattice0 = c.lattice_sturm_queries, bisection0 = c.bisection_steps;
  double t0 = cpu_seconds();
  sort.run_until(until);
  StudyRun r;
  r.seconds = cpu_seconds() - t0;
  r.simulator = "classic";
  r.events = r.batches = sort.counters().events;
  r.crossings = sort.swaps();
  r.sturm_queries = c.lattice_sturm_queries - lattice0;
  r.bisection_steps = c.bisection_steps - bisection0;
  r.ties = c.ties;
  r.order = sort.order();
  return r;
}

}  // namespace kmr::kinetic
