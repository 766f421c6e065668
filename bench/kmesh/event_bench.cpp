// kmr_bench_kmesh_event N [SEED] [scratch|noscratch]: one kinetic event and one insertion at size N
// against a from-scratch construction (issue 10: "one event vs a from-scratch construction, target
// ≥ 100× at n = 10^4"). N seeded uniform integer points in [0, 2^20]^2. The event is what the
// kinetic KDS does for a failed certificate (kmesh/kds.hpp): Updater::relocate of one nucleus
// (Fig. 4.5 stages 1–2), then Updater::repair_delaunay (stage 3, local), then Updater::mesh() (the
// canonical renumbering and listing of the output, Θ(|M|)); the insertion is Updater::insert of a
// new point, then the same. Printed: wall seconds of each part, Fig. 4.5's operations, stars
// recomputed, and the ratios construction ÷ (stages 1–3) and construction ÷ (stages 1–3 + listing). With `noscratch` the construction is not run apart: the
// Updater's constructor (the construction plus S_N) stands for it. Single runs on a loaded
// machine: compare the ratios, or count instructions with callgrind (--toggle-collect).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <set>
#include <string>

#include "kmesh/update.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
using Clock = std::chrono::steady_clock;

namespace {
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 1;
  const bool scratch = !(argc > 3 && std::string(argv[3]) == "noscratch");
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> d(0, 1LL << 20);
  std::vector<InputPoint> pts;
  std::set<InputPoint> have;
  while (static_cast<int>(pts.size()) < n) {
    InputPoint p{Integer(d(rng)), Integer(d(rng))};
    if (have.insert(p).second) pts.push_back(p);
  }
  double t_scratch = 0;
  std::size_t size = 0;
  if (scratch) {
    auto a = Clock::now();
    Mesh m = construct(pts);
    t_scratch = since(a);
    size = m.size();
  }
  auto a = Clock::now();
  Updater U(pts);
  const double t_ctor = since(a);
  Mesh m0 = U.mesh();
  if (!scratch) t_scratch = t_ctor, size = m0.size();
  std::printf("n %d |M| %zu construct %.3f s (Updater constructor %.3f s)\n", n, size, t_scratch, t_ctor);

  // An update: Fig. 4.5 stages 1–2, stage 3 (Updater::repair_delaunay, local), then the listing of
  // the output (Updater::mesh(): renumbering and triangles, Θ(|M|)).
  auto run = [&](const char* what, const std::function<void()>& update) {
    auto a = Clock::now();
    update();
    const double t_upd = since(a);
    a = Clock::now();
    U.repair_delaunay();
    const double t_del = since(a);
    const UpdateStats s = U.last();
    a = Clock::now();
    Mesh m = U.mesh();
    const double t_list = since(a);
    std::printf("%-9s fig4.5 %.4f s (%llu ops, %zu affected), stage 3 %.4f s (%llu ops, %zu stars), listing %.4f s; "
                "construct / (fig4.5 + stage 3) %.1f, construct / (all three) %.1f\n",
                what, t_upd, (unsigned long long)s.ops, s.affected, t_del, (unsigned long long)s.ops_delaunay, s.stars,
                t_list, t_scratch / (t_upd + t_del), t_scratch / (t_upd + t_del + t_list));
    return m;
  };
  Mesh m1 = run("event", [&] { U.relocate({pts[n / 2]}); });
  InputPoint p;
  do p = InputPoint{Integer(d(rng)), Integer(d(rng))};
  while (have.count(p));
  Mesh m2 = run("insertion", [&] { U.insert(p); });
  std::printf("triangles %zu %zu %zu\n", m0.triangles.size(), m1.triangles.size(), m2.triangles.size());
}
