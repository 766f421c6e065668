// ws_probe KIND N DIM [UPDATES]: construction time and counts of StableWS on a generated input, then
// UPDATES random insert/delete pairs with their times and the from-scratch time (speed ratio).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

#include "wellspaced/generators.hpp"
#include "wellspaced/measure.hpp"
#include "wellspaced/well_spaced_set.hpp"

using namespace kmr::wellspaced;

template <std::size_t D>
int run(gen::Kind k, std::size_t n, int updates) {
  auto pts = gen::points<D>(k, n + updates, 1);
  std::vector<Point<D>> in(pts.begin(), pts.begin() + n);
  auto t0 = std::chrono::steady_clock::now();
  WellSpacedSet<D> ws(in);
  double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Stats& s = ws.stats();
  std::printf("%s D=%zu n=%zu build=%.3fs vertices=%zu steiner=%llu ops=%llu squares=%llu cv_mean=%.1f cv_max=%llu ranks=[%d,%d]\n",
              gen::name(k), D, in.size(), build, ws.vertices().size(), (unsigned long long)s.steiner,
              (unsigned long long)s.ops, (unsigned long long)s.squares, double(s.cv_squares_total) / s.cv_calls,
              (unsigned long long)s.cv_squares_max, s.min_rank, s.max_rank);
  if (updates) {
    auto u = sample_updates<D>(ws, std::vector<Point<D>>(pts.begin() + n, pts.end()));
    std::printf("updates=%llu mean_update=%.6fs mean_touched=%.1f speed_ratio=%.1f\n", (unsigned long long)u.updates,
                u.mean_seconds, u.mean_touched, build / u.mean_seconds);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc < 4) return 2;
  gen::Kind k = gen::Kind::uniform;
  for (auto kk : gen::kAllKinds)
    if (!std::strcmp(gen::name(kk), argv[1])) k = kk;
  std::size_t n = std::strtoul(argv[2], nullptr, 10);
  int d = std::atoi(argv[3]);
  int u = argc > 4 ? std::atoi(argv[4]) : 0;
  if (d == 2) return run<2>(k, n, u);
  if (d == 3) return run<3>(k, n, u);
  return run<4>(k, n, u);
}
