// kmr simulate hull: the kinetic 3D convex hull (§2.2–§2.3) on the lattice motion simulator (§2.1).
#include <chrono>
#include <fstream>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "exact/error.hpp"
#include "hull/hull_at_time.hpp"
#include "hull/kinetic_hull.hpp"

namespace kmr::cli {

int simulate_hull_command(const Argv& argv) {
  Args args(argv, {"until", "lattice-bits", "check-every", "stats"}, {"integrated"});
  if (args.help() || args.positional().size() < 2) {
    std::cout
        << "usage: kmr simulate hull FILE [--until T] [--lattice-bits B] [--check-every K] [--integrated] [--stats FILE]\n"
           "FILE has one point per line, 'x y z vx vy vz' (decimal integers): position (x, y, z) + (vx, vy, vz)·t\n"
           "('#' comments). Simulates the kinetic convex hull (thesis §2.2, Appendix A, run as a self-adjusting\n"
           "program) from time 0 to T (a decimal dyadic, a multiple of δ = 2^-B; default T = 2^27, B = 10),\n"
           "repairing the failures of each lattice interval as one batch by change propagation.\n"
           "Prints JSON: events, batches, max_batch, batch_sizes (size → count), certificates (live at the end),\n"
           "certificates_created, integrated_changes, and vertices/facets of the hull just before T in the\n"
           "format of `kmr hull`. --check-every K compares the hull with the exact static hull after every K-th\n"
           "batch (K = 1: all) and exits 1 on a difference. --stats FILE writes timings and trace counts.\n"
           "--integrated runs §2.4's integrated experiment: after each batch, for each of its events, the motion\n"
           "r(t) of the next point in input order becomes ¾·r(t) (coefficients 3c/4 rounded toward zero), each\n"
           "change followed by one propagation, until every point has been changed once.\n";
    return args.help() ? 0 : 2;
  }
  const auto& pos = args.positional();
  if (pos.size() != 2) throw InputError("kmr simulate hull takes exactly one FILE");
  int bits = static_cast<int>(args.integer("lattice-bits", 10, 0, 62));
  long long check_every = args.integer("check-every", 0, 0, 1LL << 62);
  exact::Dyadic until = args.value("until") ? exact::Dyadic::parse(*args.value("until")) : exact::Dyadic::pow2(27);
  if (until.sign() < 0) throw InputError("--until must be >= 0");
  if (!until.shifted(bits).is_integer())
    throw InputError("--until " + until.to_decimal() + " is not a multiple of the lattice step 2^-" + std::to_string(bits));
  std::ifstream file(pos[1]);
  if (!file) throw InputError("cannot open '" + pos[1] + "'");
  std::vector<hull::MovingPoint> points = hull::parse_hull_motions(file, pos[1]);
  std::ofstream stats;
  if (auto f = args.value("stats")) {
    stats.open(*f);
    if (!stats) throw InputError("cannot write --stats file '" + *f + "'");
  }

  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a) { return std::chrono::duration<double>(clock::now() - a).count(); };
  kinetic::MotionSimulator sim(bits, until);
  auto start = clock::now();
  hull::KineticHull kh(points, sim);
  const double initial_seconds = seconds(start);
  double propagate_seconds = 0, check_seconds = 0, integrated_seconds = 0;
  const bool integrated = args.has("integrated");
  std::size_t next_change = 0;  // the next point whose motion changes (input order)
  long long checks = 0;
  auto check = [&](long long batch) {
    auto c = clock::now();
    kh.check_simulator_counts();  // the hull's certificate counts equal the simulator's (else exit 3)
    auto facets = kh.facets();
    auto expected = hull::static_hull_before(kh.points(), sim.now());
    std::string failure = facets == expected ? hull::hull_certificate_failure(kh.points(), sim.now(), facets)
                                             : std::string("differs from the exact static hull");
    check_seconds += seconds(c);
    ++checks;
    if (!failure.empty()) {
      std::cerr << "kmr simulate hull: check failed after batch " << batch << " (time " << sim.now().to_decimal()
                << "): the kinetic hull " << failure << "\n";
      return false;
    }
    return true;
  };
  if (check_every > 0 && !check(0)) return 1;
  long long batch = 0;
  while (auto b = sim.next_batch(until)) {
    auto p = clock::now();
    kh.update(*b);
    propagate_seconds += seconds(p);
    if (integrated) {
      auto q = clock::now();
      for (std::size_t e = 0; e < b->size() && next_change < points.size(); ++e, ++next_change)
        kh.change_motion(static_cast<int>(next_change), hull::three_quarters(kh.points()[next_change]));
      integrated_seconds += seconds(q);
    }
    ++batch;
    if (check_every > 0 && batch % check_every == 0 && !check(batch)) return 1;
  }
  const auto& c = sim.counters();
  const auto facets = kh.facets();
  const auto vertices = kh.vertices();
  std::cout << "{\"n\": " << points.size() << ", \"events\": " << c.events << ", \"batches\": " << c.batches
            << ", \"max_batch\": " << c.max_batch << ", \"batch_sizes\": {";
  bool first = true;
  for (const auto& [size, count] : c.batch_sizes) {
    std::cout << (first ? "" : ", ") << "\"" << size << "\": " << count;
    first = false;
  }
  std::cout << "}, \"certificates\": " << kh.live_certificates()
            << ", \"certificates_created\": " << kh.counters().certificates_created
            << ", \"integrated_changes\": " << kh.counters().integrated_changes << ", \"checks\": " << checks << ", \"vertices\": [";
  for (std::size_t i = 0; i < vertices.size(); ++i) std::cout << (i ? ", " : "") << vertices[i];
  std::cout << "], \"facets\": [";
  for (std::size_t i = 0; i < facets.size(); ++i)
    std::cout << (i ? ", " : "") << "[" << facets[i][0] << ", " << facets[i][1] << ", " << facets[i][2] << "]";
  std::cout << "]}\n";
  if (stats.is_open()) {
    const sac::Stats s = kh.runtime().stats();
    stats << "{\"initial_run_seconds\": " << initial_seconds << ", \"propagation_seconds\": " << propagate_seconds
          << ", \"integrated_seconds\": " << integrated_seconds << ", \"rebuilds\": " << kh.counters().rebuilds
          << ", \"check_seconds\": " << check_seconds << ", \"checks\": " << checks
          << ", \"trace_nodes\": " << s.trace_nodes << ", \"reads_reexecuted\": " << s.reads_reexecuted
          << ", \"allocs_reused\": " << s.allocs_reused << ", \"nodes_discarded\": " << s.nodes_discarded
          << ", \"hooks_run\": " << s.hooks_run << ", \"exact_certificates\": " << c.exact_certificates
          << ", \"sturm_queries\": " << c.sturm_queries << ", \"filter_searches\": " << c.poly_filter_decided
          << ", \"filter_fallbacks\": " << c.poly_filter_fallbacks << ", \"lazy_no_root\": " << c.lazy_no_root
          << ", \"lazy_deferred\": " << c.lazy_deferred << ", \"lazy_checkpoints_reached\": " << c.lazy_checkpoints_reached << "}\n";
  }
  return 0;
}

}  // namespace kmr::cli
