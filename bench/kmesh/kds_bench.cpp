// kmr_bench_kmesh_kds [n] [max_lg_spread] [batches]: the kinetic KDS (kmesh/kds.hpp) — T4.3.7 for
// KINETIC events. For lg Δ = 10, 20, …: n − 2 seeded uniform integer points at rest in [0, 2^lgΔ]²
// plus (0, 0) at rest and (1, 0) moving by (0, 1), so the spread is about 2^lgΔ and the events are
// those of the close pair; the first `batches` batches (lattice 2^−3) are repaired by Fig. 4.5.
// Printed per Δ: events, nuclei relocated, the mean operations of Fig. 4.5's local stages per
// batch and per event (÷ lg Δ), the construction's operations and their ratio to one batch, and
// wall times (construction from scratch at the final time; one batch of run_until, which includes
// the global stages — renumbering, Delaunay, the enumeration of certificate names — and the new
// certificates built and isolated, so it is
// not the local repair's time). Single runs on a possibly loaded machine: compare within one line.
// Also: all certificates kept after the last batch, those built per batch (the rest were kept,
// kmesh/kds.hpp), and satellites taken from the F_ℓ per rank processed (L4.3.5: O(1) per rank).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>

#include "kmesh/kds.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  int n = argc > 1 ? std::atoi(argv[1]) : 6;
  int max_lg = argc > 2 ? std::atoi(argv[2]) : 40;
  int want = argc > 3 ? std::atoi(argv[3]) : 2;
  std::printf("%4s %5s %7s %7s %6s %12s %10s %12s %12s %8s %9s %9s %8s %8s %8s\n", "n", "lgD", "|M|", "events", "moved", "ops/batch",
              "/lgD", "ops/event", "ops_constr", "ratio", "t_constr", "t_batch", "certs", "created", "aff/rank");
  for (int lg = 10; lg <= max_lg; lg += 10) {
    std::mt19937_64 rng(2000 + lg);
    std::uniform_int_distribution<long long> d(0, (1LL << lg));
    std::vector<InputPoint> pts{{Integer(0), Integer(0)}, {Integer(1), Integer(0), Integer(0), Integer(1)}};
    std::set<std::pair<long long, long long>> have{{0, 0}, {1, 0}};
    while (static_cast<int>(pts.size()) < n) {
      long long x = d(rng), y = d(rng);
      if (x > 4 && have.insert({x, y}).second) pts.push_back({Integer(x), Integer(y)});
    }
    KineticMesh k(pts, 3);
    std::uint64_t ops = 0;
    std::size_t events = 0, moved = 0, batches = 0, created = 0, affected = 0, ranks = 0;
    double t_batch = 0, t_constr = 0;
    std::uint64_t ops_constr = 0;
    Dyadic T(0);
    while (static_cast<int>(batches) < want && T < Dyadic(4)) {
      T = T + Dyadic(1, -3);
      auto a = Clock::now();
      k.run_until(T, [&](const Batch& b) {
        ops += b.ops;
        events += b.events;
        moved += b.moved;
        batches += b.moved > 0;
        created += b.certs_created;
        if (b.moved > 0) affected += k.last().affected, ranks += k.last().ranks;
      });
      t_batch += std::chrono::duration<double>(Clock::now() - a).count();
    }
    auto c = Clock::now();
    Mesh m = construct(k.trajectories(), k.now());
    t_constr = std::chrono::duration<double>(Clock::now() - c).count();
    ops_constr = m.ops_spanner + m.ops_convert + m.ops_delaunay;
    double per = batches ? double(ops) / batches : 0;
    std::printf("%4d %5d %7zu %7zu %6zu %12.0f %10.0f %12.0f %12llu %8.1f %9.3f %9.3f %8zu %8.0f %8.1f\n", n, lg, k.mesh().size(), events,
                moved, per, per / lg, events ? double(ops) / events : 0, (unsigned long long)ops_constr,
                per ? double(ops_constr) / per : 0, t_constr, batches ? t_batch / batches : 0,
                k.current_certificates().size(), batches ? double(created) / batches : 0,
                ranks ? double(affected) / ranks : 0);
    std::fflush(stdout);
  }
}
