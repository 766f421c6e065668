// Audit checks of the lattice motion simulator (§2.1) through kinetic sorting, judged by sorting
// exact positions x0 + v·t (ties: larger velocity first, the order just before t).
#include <algorithm>
#include <chrono>
#include <numeric>
#include <random>
#include <sstream>

#include "audit/audit.hpp"
#include "kinetic/kinetic_sort.hpp"
#include "kinetic/separation_study.hpp"

namespace kmr::audit {

namespace {

using exact::Dyadic;
using exact::Integer;

Verdict kinetic_sorting(const Options& options) {
  std::mt19937_64 rng(options.seed);
  const int n = options.quick ? 200 : 1000, bits = 10;
  // §2.4-style input: positions of 20 bits, velocities of 8 bits; few identical pairs by chance.
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 8), 1LL << 8);
  std::vector<std::pair<long long, long long>> m;
  while (static_cast<int>(m.size()) < n) {
    std::pair<long long, long long> c{pos(rng), vel(rng)};
    if (std::find(m.begin(), m.end(), c) == m.end()) m.push_back(c);
  }
  // Force simultaneous crossings: every 10th point passes through the place of point 0 at t = 64.
  for (std::size_t i = 10; i < m.size(); i += 10) {
    do {
      m[i].second += 1;  // distinct velocities keep the trajectories distinct
      m[i].first = m[0].first + (m[0].second - m[i].second) * 64;
    } while (std::count(m.begin(), m.end(), m[i]) > 1 || m[i].second == m[0].second);
  }
  std::vector<poly::Polynomial> x;
  for (auto& [x0, v] : m) x.emplace_back(std::vector<Integer>{Integer(x0), Integer(v)});
  Dyadic until(Integer(4096));
  // Timed run without checks first, then the checked run on the same input.
  double unchecked_seconds = 0;
  {
    kinetic::MotionSimulator timed(bits, until);
    auto t0 = std::chrono::steady_clock::now();
    kinetic::KineticSort s(x, timed);
    s.run_until(until);
    unchecked_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  kinetic::MotionSimulator sim(bits, until);
  kinetic::KineticSort sort(x, sim);
  // The exact positions at t, each computed once (n products, not two per comparison), then sorted.
  auto expected = [&](const Dyadic& t) {
    std::vector<Dyadic> at;
    at.reserve(m.size());
    for (const auto& [x0, v] : m) at.push_back(Dyadic(x0) + Dyadic(v) * t);
    std::vector<std::size_t> idx(m.size());
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
      return at[a] != at[b] ? at[a] < at[b] : m[a].second > m[b].second;
    });
    return idx;
  };
  auto order = [&] { return measured(options, "A2.1-batch order", sort.order()); };  // the seam of tests
  Verdict v;
  v.pass = order() == expected(Dyadic(0));
  if (!v.pass) v.summary = "initial order differs from the exact sort";
  long long checked = 0;
  while (v.pass) {
    auto batch = sim.next_batch(until);
    if (!batch) break;
    sort.update(*batch);
    // Check every batch in quick mode, every 64th otherwise (§2.4 also samples checks on large runs).
    if (options.quick || sim.counters().batches % 64 == 0) {
      ++checked;
      if (order() != expected(sim.now())) {
        v.pass = false;
        v.summary = "order differs from the exact sort at t = " + sim.now().to_decimal();
      }
    }
  }
  if (v.pass && order() != expected(until)) v.pass = false, v.summary = "final order differs from the exact sort";
  const auto& c = sim.counters();
  if (v.pass)
    v.summary = std::to_string(n) + " points, δ = 2^-10, until t = " + until.to_decimal() + ", " +
                std::to_string(checked) + " batches checked against the exact sort";
  v.figure("events", std::to_string(c.events));
  v.figure("batches", std::to_string(c.batches));
  v.figure("mean batch size", fmt(c.batches ? static_cast<double>(c.events) / c.batches : 0.0));
  v.figure("max batch", std::to_string(c.max_batch));
  v.figure("certificates live at end", std::to_string(c.live()));
  v.figure("events per second (unchecked run)", fmt(unchecked_seconds > 0 ? c.events / unchecked_seconds : 0.0));
  return v;
}

// §2.1: lattice batching vs exact separation (kinetic/separation_study.hpp) on §2.4 sort motions,
// with and without simultaneous events. Passes when all simulators end in the exact same order with
// the same crossings, the classic one spends more root-solver work per crossing in both cases, and
// it had to establish equal failure times (ties) when events are simultaneous.
Verdict batching_avoids_separation(const Options& options) {
  const std::size_t n = options.quick ? 200 : 600;
  const int bits = 10;
  Dyadic until(Integer(1), -2);  // t = 1/4: 256 lattice intervals, past the meeting at t = 1/8
  Verdict v;
  v.pass = true;
  std::ostringstream why;
  for (bool simultaneous : {false, true}) {
    auto x = kinetic::section_2_4_sort_motions(n, simultaneous, options.seed);
    auto machine = kinetic::run_lattice_sort(x, bits, until, true);
    auto exact = kinetic::run_lattice_sort(x, bits, until, false);
    auto classic = measured(options, "A2.1-batching-avoids-separation classic", kinetic::run_classic_sort(x, bits, until));
    std::string tag = simultaneous ? " (simultaneous)" : " (generic)";
    if (machine.order != classic.order || exact.order != classic.order || machine.crossings != classic.crossings)
      v.pass = false, why << "simulators disagree" << tag << "; ";
    auto per = [&](const kinetic::StudyRun& r, double x) { return fmt(r.crossings ? x / r.crossings : 0.0); };
    double lattice_work = static_cast<double>(exact.root_work()), classic_work = static_cast<double>(classic.root_work());
    if (!(classic_work > lattice_work)) v.pass = false, why << "classic needed no more root work" << tag << "; ";
    if (simultaneous && classic.ties == 0) v.pass = false, why << "no tie established" << tag << "; ";
    v.figure("crossings" + tag, std::to_string(classic.crossings));
    v.figure("lattice batches / classic events" + tag, std::to_string(exact.batches) + " / " + std::to_string(classic.events));
    v.figure("Sturm queries per crossing, lattice" + tag, per(exact, lattice_work));
    v.figure("Sturm queries per crossing, classic (of which bisection)" + tag,
             per(classic, classic_work) + " (" + per(classic, static_cast<double>(classic.bisection_steps)) + ")");
    v.figure("ties established by classic" + tag, std::to_string(classic.ties));
    v.figure("us per crossing: lattice machine / lattice exact / classic" + tag,
             per(machine, 1e6 * machine.seconds) + " / " + per(exact, 1e6 * exact.seconds) + " / " +
                 per(classic, 1e6 * classic.seconds));
  }
  v.summary = v.pass ? std::to_string(n) + " §2.4 points, δ = 2^-10, until t = 1/4; with and without a meeting point at t = 1/8"
                     : why.str();
  return v;
}

}  // namespace

std::vector<Check> kinetic_checks() {
  return {
      {"A2.1-batch", "kinetic sorting on the lattice equals the exact sort after every batch", kinetic_sorting},
      {"A2.1-batching-avoids-separation", "lattice batching needs less root-solver work than exact separation",
       batching_avoids_separation},
  };
}

}  // namespace kmr::audit
