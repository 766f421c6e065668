// The library's StableWS output (src/wellspaced, WellSpacedSet<D>) judged by the independent CGAL
// oracle of ws_oracle.hpp:
//  * T3.3.4: the output is a ρ-well-spaced superset of the input (exact clipped Voronoi cells);
//  * L3.3.3: size conformity NN_M(v) ≥ lfs(v)/c, c = 2ρ/(ρ−1) (exact);
//  * T3.4.3: the same after dynamic insertions and deletions (PropagateWS);
//  * L3.2.1: the library's β-clipped Voronoi neighbours agree with the oracle's (CGAL Delaunay
//    search + exact face distances).
// Inputs come from this folder's own generators (uniform, clustered, collinear, grids, pairs
// 2^-30 apart, boundary and corners), not from the library's.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <random>
#include <sstream>
#include <tuple>
#include <type_traits>

#include "wellspaced/generators.hpp"
#include "wellspaced/well_spaced_set.hpp"
#include "wsjudge/brute_force.hpp"
#include "ws_generators.hpp"
#include "ws_oracle.hpp"

namespace ws = kmr::oracle::ws;
namespace lib = kmr::wellspaced;
using kmr::exact::Dyadic;

namespace {

// The output exactly (Vertex::exact: coordinates finer than doubles included).
template <std::size_t D>
std::vector<ws::XPoint<D>> output_points(const lib::WellSpacedSet<D>& S) {
  std::vector<ws::XPoint<D>> pts;
  for (const auto& v : S.vertices()) {
    ws::XPoint<D> x;
    for (std::size_t i = 0; i < D; ++i) x[i] = v.exact.coord(i);
    pts.push_back(x);
  }
  return pts;
}

template <std::size_t D>
std::vector<ws::XPoint<D>> input_points(const lib::WellSpacedSet<D>& S) {
  std::vector<ws::DPoint<D>> pts;
  for (const auto& p : S.input()) pts.push_back(p);
  return ws::to_exact<D>(pts);
}

ws::Rho rho_of(const lib::Params& p) { return ws::Rho::exactly(Dyadic::from_double(p.rho)); }

// Judges one output; returns a one-line summary for the test log.
template <std::size_t D>
std::string judge(const lib::WellSpacedSet<D>& S, const std::string& what) {
  const auto M = output_points<D>(S);
  const auto N = input_points<D>(S);
  const ws::Rho rho = rho_of(S.params());
  auto w = ws::judge_well_spaced<D>(M, rho);
  EXPECT_TRUE(w.ok) << what << ": " << w.violations << " vertices not ρ-well-spaced; worst R/NN = "
                    << w.worst_ratio << " at vertex " << w.worst_vertex << ", ρ = " << rho.approx();
  auto s = ws::judge_size_conforming<D>(M, N, rho);
  EXPECT_TRUE(s.ok) << what << ": " << s.violations << " vertices violate NN ≥ lfs/c; worst lfs/NN = "
                    << s.worst_ratio << " > c = " << s.c;
  // Every Steiner vertex is inside the domain and the input is kept (checked by the oracle).
  return what + ": |N| = " + std::to_string(N.size()) + ", |M| = " + std::to_string(M.size()) +
         ", max R/NN = " + std::to_string(w.worst_ratio) + " (ρ = " + std::to_string(rho.approx()) +
         "), max lfs/NN = " + std::to_string(s.worst_ratio) + " (c = " + std::to_string(s.c) + ")";
}

template <std::size_t D>
void judge_generated(std::vector<std::pair<ws::gen::Kind, std::size_t>> cases,
                     std::initializer_list<double> rhos, std::uint64_t seeds) {
  for (auto [kind, n] : cases)
    for (double rho : rhos)
      for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        auto in = ws::gen::make<D>(kind, n, seed);
        lib::Params p;
        p.rho = rho;
        p.beta = std::max(p.beta, 2 * rho);
        auto t0 = std::chrono::steady_clock::now();
        lib::WellSpacedSet<D> S(in, p);
        auto t1 = std::chrono::steady_clock::now();
        std::string line = judge<D>(S, ws::gen::name(kind) + " seed " + std::to_string(seed));
        auto t2 = std::chrono::steady_clock::now();
        if (::testing::Test::HasFailure()) return;
        std::printf("  [%zuD] %s; build %.2fs, judge %.2fs\n", D, line.c_str(),
                    std::chrono::duration<double>(t1 - t0).count(),
                    std::chrono::duration<double>(t2 - t1).count());
      }
}

}  // namespace

TEST(WsJudge, T3_3_4_StableWS2DIsWellSpacedAndSizeConforming) {
  RecordProperty("claim", "T3.3.4");
  std::vector<std::pair<ws::gen::Kind, std::size_t>> cases;
  for (auto kind : ws::gen::kAllKinds) cases.emplace_back(kind, 60);
  judge_generated<2>(cases, {1.5, 2.0}, 1);
}

TEST(WsJudge, T3_3_4_StableWS3DIsWellSpacedAndSizeConforming) {
  RecordProperty("claim", "T3.3.4");
  // Sizes keep the run short: large spread (clusters, collinear, 2^-30 pairs) yields many Steiner
  // vertices in 3D.
  using K = ws::gen::Kind;
  judge_generated<3>({{K::Uniform, 12}, {K::Grid, 12}, {K::Boundary, 12}, {K::Clustered, 12},
                      {K::Line, 6}, {K::ClosePairs, 4}},
                     {1.5, 2.0}, 1);
}

TEST(WsJudge, T3_3_4_StableWS4DJudgedWithCgalEpeckD) {
  RecordProperty("claim", "T3.3.4");
  // Small inputs: 4D outputs grow fast with the spread (a 5-point clustered input ran > 5 min).
  for (auto [kind, n] : std::vector<std::pair<ws::gen::Kind, std::size_t>>{
           {ws::gen::Kind::Uniform, 8}, {ws::gen::Kind::Boundary, 20}, {ws::gen::Kind::Line, 4}}) {
    auto in = ws::gen::make<4>(kind, n, 1);
    lib::Params p;
    p.rho = 2.0;
    p.beta = 4.0;
    lib::WellSpacedSet<4> S(in, p);
    std::string line = judge<4>(S, ws::gen::name(kind));
    if (HasFailure()) return;
    std::printf("  [4D] %s\n", line.c_str());
  }
}

// Issue 11 §5: the 4D clustered family (spread ≈ 2^12), skipped before its construction took
// minutes at n = 4 (half of the interval tier's calls fell back to exact arithmetic: the vertices of
// the clipped cells were chained through the edge's ends; now solved from their tight
// constraints). Judged at ρ = 4, β = 8 (|M| = 150) and, as the other 4D families, at ρ = 2,
// β = 4 (|M| = 946; a test of its own: ≈ 25 s CPU, most of it the judge).
static void judge_4d_clustered(double rho, double beta) {
  auto in = ws::gen::make<4>(ws::gen::Kind::Clustered, 4, 1);
  lib::Params p;
  p.rho = rho;
  p.beta = beta;
  lib::WellSpacedSet<4> S(in, p);
  EXPECT_LT(S.stats().exact_fallbacks, (S.stats().cv_calls + S.stats().fills) / 20);
  std::string line = judge<4>(S, "clustered");
  if (::testing::Test::HasFailure()) return;
  std::printf("  [4D, rho %g] %s, %llu exact fallbacks of %llu calls\n", rho, line.c_str(),
              (unsigned long long)S.stats().exact_fallbacks, (unsigned long long)(S.stats().cv_calls + S.stats().fills));
}

TEST(WsJudge, T3_3_4_StableWS4DClusteredJudgedWithCgalEpeckD) {
  RecordProperty("claim", "T3.3.4");
  judge_4d_clustered(4.0, 8.0);
}

TEST(WsJudge, T3_3_4_StableWS4DClusteredAtRho2JudgedWithCgalEpeckD) {
  RecordProperty("claim", "T3.3.4");
  judge_4d_clustered(2.0, 4.0);
}

// Issue 11 §5: the 4D pair 2^-30 apart (the library's close_pair generator at n = 2: spread 2^30),
// at ρ = 4, β = 8 (|M| = 484). In the default run since session 25 (was opt-in, KMR_WS_SLOW=1):
// ≈ 8 s construction + ≈ 8 s judge CPU, within the default run's budget; at ρ = 2, β = 4 the
// construction alone is 26 s and |M| = 2 819, and the judge more (spec/wellspaced.md, "Speed of the degenerate families").
TEST(WsJudge, T3_3_4_StableWS4DClosePairJudgedWithCgalEpeckD) {
  RecordProperty("claim", "T3.3.4");
  const auto in = kmr::wellspaced::gen::points<4>(kmr::wellspaced::gen::Kind::close_pair, 2, 1);
  ASSERT_EQ(in.size(), 2u);
  lib::Params p;
  p.rho = 4.0;
  p.beta = 8.0;
  lib::WellSpacedSet<4> S(in, p);
  EXPECT_LT(S.stats().exact_fallbacks, (S.stats().cv_calls + S.stats().fills) / 20);
  std::string line = judge<4>(S, "close_pair 2^-30");
  if (HasFailure()) return;
  std::printf("  [4D] %s, %llu exact fallbacks of %llu calls\n", line.c_str(),
              (unsigned long long)S.stats().exact_fallbacks, (unsigned long long)(S.stats().cv_calls + S.stats().fills));
}

TEST(WsJudge, L3_3_3_SizeConformingWithDefaultParameters) {
  RecordProperty("claim", "L3.3.3");
  auto in = ws::gen::make<2>(ws::gen::Kind::Clustered, 300, 42);
  lib::WellSpacedSet<2> S(in);
  const auto M = output_points<2>(S);
  auto s = ws::judge_size_conforming<2>(M, input_points<2>(S), rho_of(S.params()));
  EXPECT_TRUE(s.ok) << "worst lfs/NN = " << s.worst_ratio << " > c = " << s.c;
  RecordProperty("worst_lfs_over_nn", std::to_string(s.worst_ratio));
}

TEST(WsJudge, T3_4_3_OutputStaysWellSpacedUnderUpdates) {
  RecordProperty("claim", "T3.4.3");
  std::mt19937_64 rng(2012);
  for (auto kind : {ws::gen::Kind::Uniform, ws::gen::Kind::ClosePairs, ws::gen::Kind::Boundary}) {
    auto all = ws::gen::make<2>(kind, 120, 5);
    std::vector<ws::DPoint<2>> in(all.begin(), all.begin() + 100);
    lib::WellSpacedSet<2> S(in);
    for (std::size_t step = 0; step < 6; ++step) {
      if (step % 2 == 0) {
        S.insert(all[100 + step]);
      } else {
        auto cur = S.input();
        S.erase(cur[rng() % cur.size()]);
      }
      judge<2>(S, ws::gen::name(kind) + " after update " + std::to_string(step));
      if (HasFailure()) return;
    }
  }
}

// The library's scan (QTClippedVoronoi, Fig. 3.6, exposed as clipped_voronoi_neighbors) and its
// brute-force definition must both equal the oracle's β-clipped neighbours. The library's
// convention (well_spaced_set.hpp): u is a β-clipped neighbour of v iff some ball with v, u on its
// boundary and no vertex inside has radius ≤ β·NN(v), the centre not confined to Ω: the oracle
// with clip_to_domain = false, closed ball.
constexpr ws::BetaOptions kLibraryConvention{false, false, false};

// Empty when the library's list (indices into M, any order) equals the oracle's; else a report.
std::string neighbour_mismatch(std::vector<std::size_t> got, const std::vector<std::uint32_t>& want) {
  std::sort(got.begin(), got.end());
  std::vector<std::size_t> w(want.begin(), want.end());
  if (got == w) return {};
  std::ostringstream r;
  r << "library {";
  for (auto i : got) r << ' ' << i;
  r << " } oracle {";
  for (auto i : w) r << ' ' << i;
  r << " }";
  return r.str();
}

template <std::size_t D>
std::vector<std::size_t> scan_indices(const lib::WellSpacedSet<D>& S, const std::vector<lib::Point<D>>& M,
                                      std::size_t v) {
  std::vector<std::size_t> scan;
  for (const auto& p : S.clipped_voronoi_neighbors(M[v]))
    scan.push_back(static_cast<std::size_t>(std::lower_bound(M.begin(), M.end(), p.below()) - M.begin()));  // double outputs
  return scan;
}

struct ScanCounts {
  std::size_t vertices = 0, neighbours = 0;
  std::size_t clipped_away = 0;  // Delaunay neighbours (CGAL) that are not β-clipped neighbours
};

// Checks every vertex (step 1) or about `max_checked` of them, evenly spaced.
template <std::size_t D>
ScanCounts expect_scan_matches_oracle(const std::vector<ws::DPoint<D>>& in, const std::string& what,
                                      lib::Params params = {}, std::size_t max_checked = 60) {
  lib::WellSpacedSet<D> S(in, params);
  std::vector<lib::Point<D>> M;
  for (const auto& v : S.vertices()) M.push_back(v.x);
  ws::CellOracle<D> O(ws::to_exact<D>(std::vector<ws::DPoint<D>>(M.begin(), M.end())));
  const double beta = S.params().beta;
  const std::size_t step = std::max<std::size_t>(1, M.size() / max_checked);
  ScanCounts n;
  for (std::size_t v = 0; v < M.size(); v += step) {
    auto want = O.beta_neighbors(v, Dyadic::from_double(beta), kLibraryConvention);
    EXPECT_EQ(neighbour_mismatch(scan_indices<D>(S, M, v), want), "")
        << what << ": scan vs oracle at vertex " << v << " (β = " << beta << ", |M| = " << M.size() << ")";
    EXPECT_EQ(neighbour_mismatch(kmr::wsjudge::clipped_voronoi_neighbors<D>(M, v, beta), want), "")
        << what << ": brute-force judge (wsjudge) vs oracle at vertex " << v;
    if (::testing::Test::HasFailure()) return n;
    ++n.vertices;
    n.neighbours += want.size();
    for (auto u : O.delaunay_neighbors(v))
      if (!std::binary_search(want.begin(), want.end(), u)) ++n.clipped_away;
  }
  return n;
}

TEST(WsJudge, L3_2_1_ClippedVoronoiScanAgreesWithOracle) {
  RecordProperty("claim", "L3.2.1");
  using K = ws::gen::Kind;
  for (auto kind : {K::Uniform, K::Grid, K::Boundary, K::Clustered, K::ClosePairs})
    expect_scan_matches_oracle<2>(ws::gen::make<2>(kind, 60, 3), "2D " + ws::gen::name(kind));
  for (auto kind : {K::Uniform, K::Grid, K::Boundary})
    expect_scan_matches_oracle<3>(ws::gen::make<3>(kind, 12, 3), "3D " + ws::gen::name(kind));
}

// 4D: every output vertex of StableWS; oracle = CGAL Epeck_d Delaunay search + exact KKT face
// distances. Small inputs (the library's 4D construction is slow): uniform, boundary and corners,
// the 2^4 and 3^4 grids (cospherical), collinear.
TEST(WsJudge, L3_2_1_ClippedVoronoiScanAgreesWithOracle4D) {
  RecordProperty("claim", "L3.2.1");
  using K = ws::gen::Kind;
  std::size_t vertices = 0, neighbours = 0, clipped_away = 0;
  // (kind, n, seed, ρ, β); a collinear seed with a larger spread (4 points, seed 3: 249 output
  // vertices) takes ~100 s, so the line case uses seed 1 (22 output vertices).
  for (auto [kind, n, seed, rho, beta] :
       std::vector<std::tuple<K, std::size_t, std::uint64_t, double, double>>{
           {K::Uniform, 8, 3, 2.0, 4.0}, {K::Boundary, 20, 3, 2.0, 4.0}, {K::Grid, 16, 3, 2.0, 4.0},
           {K::Grid, 81, 3, 2.0, 4.0}, {K::Line, 4, 1, 2.0, 4.0}, {K::Uniform, 6, 3, 1.5, 3.0},
           {K::Boundary, 20, 5, 1.5, 3.0}}) {
    lib::Params p;
    p.rho = rho;
    p.beta = beta;
    const std::string what = "4D " + ws::gen::name(kind) + " n " + std::to_string(n) + " seed " +
                             std::to_string(seed) + " ρ " + std::to_string(rho) + " β " +
                             std::to_string(beta);
    auto t0 = std::chrono::steady_clock::now();
    auto c = expect_scan_matches_oracle<4>(ws::gen::make<4>(kind, n, seed), what, p, SIZE_MAX);
    if (HasFailure()) return;
    std::printf("  %s: %zu vertices agree, %zu β-clipped neighbours, %zu Delaunay neighbours "
                "clipped away (%.2fs)\n", what.c_str(), c.vertices, c.neighbours, c.clipped_away,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    vertices += c.vertices, neighbours += c.neighbours, clipped_away += c.clipped_away;
  }
  EXPECT_GT(clipped_away, 0u) << "the clipping condition (ball of radius β·NN) never mattered";
  RecordProperty("vertices_checked", std::to_string(vertices));
  RecordProperty("neighbours_checked", std::to_string(neighbours));
}

// The 4D comparison can fail (issue 11): the library's output is perturbed (one Steiner vertex u
// removed) and the oracle judges the perturbed set itself: its β-clipped neighbours must differ
// from the library's (computed on the unperturbed output, u dropped from the lists) at some vertex
// of every trial, and its well-spacedness judgment must reject some perturbed set.
TEST(WsJudge, L3_2_1_OracleJudgesPerturbedOutput4D) {
  RecordProperty("claim", "L3.2.1");
  lib::Params p;
  p.rho = 2.0;
  p.beta = 4.0;
  lib::WellSpacedSet<4> S(ws::gen::make<4>(ws::gen::Kind::Boundary, 20, 3), p);
  std::vector<lib::Point<4>> M;
  std::vector<std::size_t> steiner;
  for (const auto& v : S.vertices()) {
    if (v.is_steiner) steiner.push_back(M.size());
    M.push_back(v.x);
  }
  ASSERT_GE(steiner.size(), 4u);
  std::vector<std::vector<std::size_t>> lib_lists;
  for (std::size_t v = 0; v < M.size(); ++v) lib_lists.push_back(scan_indices<4>(S, M, v));
  std::size_t rejected = 0, trials = 0;
  for (std::size_t t = 0; t < 4; ++t) {
    const std::size_t u = steiner[t * steiner.size() / 4];
    std::vector<ws::DPoint<4>> Mp;
    for (std::size_t i = 0; i < M.size(); ++i)
      if (i != u) Mp.push_back(M[i]);
    auto at = [&](std::size_t i) { return i < u ? i : i - 1; };  // index in Mp
    ws::CellOracle<4> O(ws::to_exact<4>(Mp));
    std::size_t differ = 0;
    for (std::size_t v = 0; v < M.size(); ++v) {
      if (v == u) continue;
      std::vector<std::size_t> got;
      for (auto w : lib_lists[v])
        if (w != u) got.push_back(at(w));
      if (!neighbour_mismatch(got, O.beta_neighbors(at(v), Dyadic::from_double(p.beta), kLibraryConvention)).empty())
        ++differ;
    }
    EXPECT_GT(differ, 0u) << "removing Steiner vertex " << u << " changed no oracle neighbour list";
    if (!ws::judge_well_spaced<4>(ws::to_exact<4>(Mp), rho_of(p)).ok) ++rejected;
    ++trials;
    std::printf("  without Steiner vertex %zu: oracle lists differ at %zu of %zu vertices\n", u, differ, Mp.size());
  }
  EXPECT_GT(rejected, 0u) << "the oracle accepted every perturbed output";
  std::printf("  |M| = %zu; %zu of %zu perturbed outputs rejected as not well-spaced\n", M.size(), rejected, trials);
}

// Issue 11 §1: the degenerate families (grids with non-dyadic spacing, collinear points, exactly
// cocircular and cospherical integer points) over ρ ∈ [1.1, 4] and several β, judged by CGAL.
TEST(WsJudge, T3_3_4_DegenerateFamiliesOverRhoBeta) {
  RecordProperty("claim", "T3.3.4");
  namespace g = kmr::wellspaced::gen;
  auto run = [&](auto dim, std::size_t n, std::initializer_list<std::pair<double, double>> rb) {
    constexpr std::size_t D = decltype(dim)::value;
    for (auto kind : g::kDegenerateKinds)
      for (auto [rho, beta] : rb) {
        lib::Params p;
        p.rho = rho;
        p.beta = beta;
        lib::WellSpacedSet<D> S(g::points<D>(kind, n, 1), p);
        std::string line = judge<D>(S, std::string(g::name(kind)) + " β " + std::to_string(beta));
        if (::testing::Test::HasFailure()) return;
        std::printf("  [%zuD] %s\n", D, line.c_str());
      }
  };
  run(std::integral_constant<std::size_t, 2>{}, 40, {{1.1, 1.2}, {1.5, 3}, {2, 4}, {3, 6}, {4, 4.5}});
  run(std::integral_constant<std::size_t, 3>{}, 8, {{2, 3}, {3, 6}, {4, 8}});
  run(std::integral_constant<std::size_t, 4>{}, 5, {{3, 6}, {4, 8}});
}

// Issue 11 §1: near-duplicate pairs, ½ and ½ + 2^-k along x (k = 53 is 1 ulp), where some picking
// regions hold no double: before VertexPoint, k = 49 at ρ = 1.5 and k = 51, 53 at ρ = 1.5, 2 ended
// in "no double-precision Steiner vertex" (exit 3). Now every one answers, with Steiner vertices
// finer than doubles (at least one per run at k = 51, 53: the test is not vacuous), judged exactly by
// the oracle on the exact output. (ρ = 1.1 also answers, |M| ≈ 4 500, 6–8 s per run: CLI sweep in
// spec/wellspaced.md, not in the default run.)
namespace {
// The pair ½·1, ½·1 + 2^-k·e_1 in D dimensions at (ρ, β); expects some vertex finer than a double
// when want_fine, reads every such coordinate back with the oracle's own hex reader, and judges
// the exact output.
template <std::size_t D>
void near_duplicate_pair_case(int k, double rho, double beta, bool want_fine) {
  lib::Point<D> a, b;
  a.fill(0.5);
  b = a;
  b[0] += std::ldexp(1.0, -k);
  lib::Params p;
  p.rho = rho;
  p.beta = beta;
  const std::string what = std::to_string(D) + "D pair 2^-" + std::to_string(k) + " rho " + std::to_string(rho);
  lib::WellSpacedSet<D> S({a, b}, p);
  std::size_t fine = 0;
  for (const auto& v : S.vertices()) {
    fine += !v.exact.is_double();
    // the library's exact text (what the CLI prints) read back by the oracle's own reader
    for (std::size_t i = 0; i < D; ++i)
      if (!v.exact.is_double(i)) {
        EXPECT_EQ(ws::parse_hex_exact(v.exact.text(i)), v.exact.coord(i)) << v.exact.text(i);
      }
  }
  if (want_fine) {
    EXPECT_GT(fine, 0u) << what;
  }
  std::printf("  %s: |M| = %zu, %zu finer than doubles; %s\n", what.c_str(), S.vertices().size(), fine,
              judge<D>(S, what).c_str());
}
}  // namespace

TEST(WsJudge, T3_3_4_NearDuplicatePairsFinerThanDoubles2D) {
  RecordProperty("claim", "T3.3.4");
  for (int k : {49, 51, 53})
    for (auto [rho, beta] : {std::pair{1.5, 3.0}, std::pair{2.0, 4.0}}) near_duplicate_pair_case<2>(k, rho, beta, k >= 51);
}
// 3D: both ended in exit 3 before ("no double-precision Steiner vertex"); k = 48 is 2^5 ulps.
// (ρ ≤ 1.5 at k = 48 takes > 2 min in 3D: not in the default run.)
TEST(WsJudge, T3_3_4_NearDuplicatePairsFinerThanDoubles3D) {
  RecordProperty("claim", "T3.3.4");
  near_duplicate_pair_case<3>(53, 4.0, 8.0, true);
  near_duplicate_pair_case<3>(48, 3.0, 6.0, true);
}

TEST(WsJudge, T3_3_4_OracleRejectsOutputWithoutItsSteinerVertices) {
  RecordProperty("claim", "T3.3.4");
  // The judge is not vacuous on library data: dropping the Steiner vertices must be rejected.
  auto in = ws::gen::make<2>(ws::gen::Kind::Clustered, 60, 1);
  lib::WellSpacedSet<2> S(in);
  std::vector<ws::DPoint<2>> kept;
  std::size_t steiner = 0;
  for (const auto& v : S.vertices()) {
    if (v.is_steiner) ++steiner;
    else kept.push_back(v.x);
  }
  ASSERT_GT(steiner, 0u);
  EXPECT_FALSE(ws::judge_well_spaced_2d(ws::to_exact<2>(kept), rho_of(S.params())).ok);
}
