// Root-solver benchmark, thesis §2.4 input: four points moving linearly in 3D, each coordinate
// x(t) = X + V·2^12·t with X = x0·2^20 (B_ℓ = 20 position bits) and V = v·2^8 (B_v = 8 velocity bits),
// x0, v uniform in [−1, 1]; certificate = orientation_value of the four points (a cubic in t);
// lattice δ = 2^−10, horizon M_t = 2^27, query next_failure_after(0).
//
// Compared, on the same polynomials in the same run:
//  * kmr:  LatticeRootSolver(p, 10).next_failure_after(0, 2^27) (builds the Sturm sequence too);
//  * CGAL: Algebraic_kernel_d_1<CORE::BigInt>::Solve_1 (isolation with multiplicities, a fresh
//          kernel per polynomial so no cache is shared) and the first odd-multiplicity root ≥ 0
//          and < 2^27, by exact comparison with the bounds.
// Prints Google Benchmark timings, then the ratio kmr / CGAL (target ≤ 0.5) measured in pairs:
// each of 21 rounds times one pass of kmr and one pass of CGAL over all certificates back to back
// (alternating which goes first), in thread CPU time, and the ratio is the median of the rounds'
// ratios, so that both sides of a pair see the same machine load. Before timing, every kmr answer is checked against the CGAL oracle when it is
// built (KMR_BENCH_WITH_ORACLE), and the run aborts on a disagreement.
#include <benchmark/benchmark.h>

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_BigInt.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <string>
#include <cstdio>
#include <random>
#include <vector>

#include "geometry/predicates.hpp"
#include "poly/sturm.hpp"
#ifdef KMR_BENCH_WITH_ORACLE
#include "cgal_roots.hpp"
#include "roots_audit_json.hpp"
#endif

namespace {

using kmr::exact::Dyadic;
using kmr::exact::Integer;
using kmr::poly::LatticeRootSolver;
using kmr::poly::Polynomial;
using AK = CGAL::Algebraic_kernel_d_1<CORE::BigInt>;

constexpr int kLatticeBits = 10;
constexpr int kCount = 1000;

std::vector<Polynomial> make_certificates(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> pos(-(1LL << 20), 1LL << 20), vel(-(1LL << 8), 1LL << 8);
  std::vector<Polynomial> out;
  while (static_cast<int>(out.size()) < count) {
    std::array<kmr::geometry::Point<3, Polynomial>, 4> pts;
    for (auto& p : pts)
      for (auto& x : p) x = Polynomial(std::vector<Integer>{Integer(pos(rng)), Integer(vel(rng)) << 12});
    Polynomial c = kmr::geometry::orientation_value(pts[0], pts[1], pts[2], pts[3]);
    if (!c.is_zero()) out.push_back(std::move(c));
  }
  return out;
}

const std::vector<Polynomial>& certificates() {
  static const std::vector<Polynomial> c = make_certificates(kCount, 2012);
  return c;
}

AK::Polynomial_1 to_cgal(const Polynomial& p) {
  std::vector<CORE::BigInt> cs;
  for (const auto& c : p.coefficients()) cs.emplace_back(c.backend().data());
  return AK::Polynomial_1(cs.begin(), cs.end());
}

const std::vector<AK::Polynomial_1>& cgal_certificates() {
  static const std::vector<AK::Polynomial_1> c = [] {
    std::vector<AK::Polynomial_1> v;
    for (const auto& p : certificates()) v.push_back(to_cgal(p));
    return v;
  }();
  return c;
}

const Dyadic kFrom(0), kHorizon = Dyadic::pow2(27);

bool ours(const Polynomial& p) {
  LatticeRootSolver solver(p, kLatticeBits);
  return solver.next_failure_after(kFrom, kHorizon).has_value();
}

bool cgal(const AK::Polynomial_1& p) {
  AK ak;
  std::vector<std::pair<AK::Algebraic_real_1, AK::Multiplicity_type>> roots;
  ak.solve_1_object()(p, std::back_inserter(roots));
  const AK::Bound lo(0), hi(CORE::BigInt(1) << 27);
  for (const auto& [r, m] : roots) {
    if (m % 2 == 0) continue;
    if (ak.compare_1_object()(r, lo) == CGAL::SMALLER) continue;
    return ak.compare_1_object()(r, hi) == CGAL::SMALLER;
  }
  return false;
}

void BM_kmr_next_failure_after(benchmark::State& state) {
  const auto& ps = certificates();
  for (auto _ : state)
    for (const auto& p : ps) benchmark::DoNotOptimize(ours(p));
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(ps.size()));
}
void BM_cgal_isolate_first_odd_root(benchmark::State& state) {
  const auto& ps = cgal_certificates();
  for (auto _ : state)
    for (const auto& p : ps) benchmark::DoNotOptimize(cgal(p));
  state.SetItemsProcessed(state.iterations() * static_cast<long long>(ps.size()));
}
BENCHMARK(BM_kmr_next_failure_after)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_cgal_isolate_first_odd_root)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

double thread_cpu_ns() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

struct PairedRatio {
  double median, min, max, kmr_us, cgal_us;  // ratios; median per-certificate pass times
};

template <class F, class G>
PairedRatio paired_ratio(F&& a, G&& b, std::size_t n, int rounds) {
  std::vector<double> ratios, ta, tb;
  auto pass = [&](auto&& f) {
    double t0 = thread_cpu_ns();
    for (std::size_t i = 0; i < n; ++i) benchmark::DoNotOptimize(f(i));
    return thread_cpu_ns() - t0;
  };
  for (int r = 0; r < rounds; ++r) {
    double x, y;
    if (r % 2 == 0) x = pass(a), y = pass(b);
    else y = pass(b), x = pass(a);
    ratios.push_back(x / y);
    ta.push_back(x / static_cast<double>(n) / 1e3);
    tb.push_back(y / static_cast<double>(n) / 1e3);
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
  return {median(ratios), *lo, *hi, median(ta), median(tb)};
}

// Per-certificate times in ns (mean of 5 repetitions each), sorted.
template <class F>
std::vector<double> times_ns(F&& f, std::size_t n) {
  std::vector<double> t;
  for (std::size_t i = 0; i < n; ++i) {
    auto a = std::chrono::steady_clock::now();
    for (int rep = 0; rep < 5; ++rep) benchmark::DoNotOptimize(f(i));
    auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::nano>(b - a).count() / 5);
  }
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::string audit_json;  // --audit-json FILE (removed before Google Benchmark reads the flags)
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--audit-json" && i + 1 < argc) {
      audit_json = argv[i + 1];
      for (int j = i; j + 2 <= argc; ++j) argv[j] = argv[j + 2];
      argc -= 2;
      break;
    }
  const auto& ps = certificates();
  const auto& cs = cgal_certificates();
  int failures = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
#ifdef KMR_BENCH_WITH_ORACLE
    auto oracle = kmr::oracles::oracle_real_roots(ps[i].coefficients(), kLatticeBits);
    auto want = kmr::oracles::first_sign_change(oracle, Integer(0), Integer(1) << (27 + kLatticeBits));
    auto have = LatticeRootSolver(ps[i], kLatticeBits).next_failure_after(kFrom, kHorizon);
    if (want != have) {
      std::fprintf(stderr, "DISAGREEMENT on certificate %zu: %s\n", i, ps[i].to_string().c_str());
      return 1;
    }
#endif
    failures += ours(ps[i]);
  }
  std::printf("certificates: %zu (cubics), with a failure in [0, 2^27): %d\n", ps.size(), failures);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  auto ta = times_ns([&](std::size_t i) { return ours(ps[i]); }, ps.size());
  auto tb = times_ns([&](std::size_t i) { return cgal(cs[i]); }, cs.size());
  double a = ta[ta.size() / 2], b = tb[tb.size() / 2];
  std::printf("median per certificate (wall clock, separate passes): kmr %.1f us, CGAL %.1f us, ratio %.3f\n", a / 1e3,
              b / 1e3, a / b);
  auto r = paired_ratio([&](std::size_t i) { return ours(ps[i]); }, [&](std::size_t i) { return cgal(cs[i]); },
                        ps.size(), 21);
  std::printf("paired rounds (thread CPU time, 21 rounds): kmr %.2f us, CGAL %.2f us per certificate; "
              "ratio kmr/CGAL = %.3f (rounds: %.3f .. %.3f) (target <= 0.5): %s\n",
              r.kmr_us, r.cgal_us, r.median, r.min, r.max, r.median <= 0.5 ? "met" : "NOT met");
  if (!audit_json.empty()) write_audit_json(audit_json, ta, tb, static_cast<int>(ps.size()), r.median, r.min, r.max);
  return 0;
}
