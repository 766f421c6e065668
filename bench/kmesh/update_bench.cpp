// kmr_bench_kmesh_update [n] [max_lg_spread]: the dynamic update of Fig. 4.5 (kmesh/update.hpp)
// against a from-scratch construction (Fig. 4.2), T4.3.7. For lg Δ = 10, 20, 30, 40 (up to the
// second argument): n − 1 seeded uniform integer points in [0, 2^lgΔ]^2 plus one point at distance
// 1 of the first (so the spread is about 2^lgΔ); then 3 × (insert a random point, delete it).
// Printed per Δ: the mean operations of one update (stages 1–2: spanner and propagation, local)
// ÷ log2 Δ, the construction's operations, their ratio, and wall times: construct, one update
// (stages 1–2), and mesh() (renumbering + the Delaunay stage, global in this implementation). The
// machine may be loaded: times are single runs, compare them as ratios within one line.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>

#include "kmesh/update.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  int n = argc > 1 ? std::atoi(argv[1]) : 8;
  int max_lg = argc > 2 ? std::atoi(argv[2]) : 40;
  std::printf("%4s %5s %8s %12s %12s %12s %10s %10s %10s %10s\n", "n", "lgD", "|M|", "ops/update", "/lgD",
              "ops_constr", "ratio", "t_constr", "t_update", "t_mesh");
  for (int lg = 10; lg <= max_lg; lg += 10) {
    std::mt19937_64 rng(1000 + lg);
    std::uniform_int_distribution<long long> d(0, (1LL << lg));
    std::vector<InputPoint> pts;
    std::set<InputPoint> have;
    pts.push_back({Integer(0), Integer(0)});
    pts.push_back({Integer(1), Integer(0)});
    for (auto& p : pts) have.insert(p);
    while (static_cast<int>(pts.size()) < n) {
      InputPoint p{Integer(d(rng)), Integer(d(rng))};
      if (have.insert(p).second) pts.push_back(p);
    }
    auto t0 = Clock::now();
    Mesh m = construct(pts);
    double t_constr = std::chrono::duration<double>(Clock::now() - t0).count();
    std::uint64_t ops_constr = m.ops_spanner + m.ops_convert + m.ops_delaunay;
    Updater U(pts);
    std::uint64_t ops = 0;
    double t_upd = 0, t_mesh = 0;
    int updates = 0;
    for (int rep = 0; rep < 3; ++rep) {
      InputPoint p;
      do p = InputPoint{Integer(d(rng)), Integer(d(rng))};
      while (have.count(p));
      for (int k = 0; k < 2; ++k) {
        auto a = Clock::now();
        if (k == 0) U.insert(p);
        else U.erase(p);
        t_upd += std::chrono::duration<double>(Clock::now() - a).count();
        ops += U.last().ops;
        ++updates;
        auto b = Clock::now();
        Mesh mm = U.mesh();
        t_mesh += std::chrono::duration<double>(Clock::now() - b).count();
      }
    }
    double per = double(ops) / updates;
    std::printf("%4d %5d %8zu %12.0f %12.0f %12llu %10.1f %10.3f %10.4f %10.3f\n", n, lg, m.size(), per, per / lg,
                (unsigned long long)ops_constr, double(ops_constr) / per, t_constr, t_upd / updates, t_mesh / updates);
    std::fflush(stdout);
  }
}
