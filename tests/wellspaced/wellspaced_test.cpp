// StableWS (Fig. 3.4) and its updates (Fig. 3.8), judged by the exact brute force of src/wsjudge
// (no quadtree, no scan, no code shared with the library) and by from-scratch runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <cmath>

#include "exact/dyadic.hpp"
#include "exact/error.hpp"
#include "wellspaced/generators.hpp"
#include "wellspaced/well_spaced_set.hpp"
#include "wsjudge/brute_force.hpp"

using namespace kmr::wellspaced;
using kmr::wsjudge::is_well_spaced;
using kmr::wsjudge::is_size_conforming;

namespace {

// The output as doubles, for the brute-force judges of src/wsjudge: a vertex finer than a double
// (near-duplicate inputs) would be judged rounded, so none may occur here (outputs with such
// vertices are judged on their exact text: T3_3_4_OneUlpPairOutputJudgedExactly, and by the CGAL
// oracle).
template <std::size_t D>
std::vector<Point<D>> coords(const std::vector<Vertex<D>>& vs) {
  std::vector<Point<D>> out;
  for (auto& v : vs) {
    EXPECT_TRUE(v.exact.is_double()) << "a vertex finer than a double: judge it exactly (CGAL oracle)";
    out.push_back(v.x);
  }
  return out;
}

template <std::size_t D>
void check_output(const std::vector<Point<D>>& input, const WellSpacedSet<D>& ws, const std::string& what) {
  auto vs = ws.vertices();
  auto M = coords<D>(vs);
  std::string why;
  EXPECT_TRUE(is_well_spaced<D>(M, ws.params().rho, &why)) << what << ": " << why;
  EXPECT_TRUE(is_size_conforming<D>(input, M, ws.params().rho, &why)) << what << ": " << why;
  // superset of the input, Steiner flags right
  std::size_t inputs = 0;
  for (auto& v : vs) {
    bool is_input = std::binary_search(input.begin(), input.end(), v.x);
    EXPECT_EQ(is_input, !v.is_steiner) << what;
    inputs += is_input;
  }
  EXPECT_EQ(inputs, input.size()) << what;
}

template <std::size_t D>
void static_case(gen::Kind k, std::size_t n, std::uint64_t seed) {
  auto input = gen::points<D>(k, n, seed);
  WellSpacedSet<D> ws(input);
  check_output<D>(input, ws, std::string(gen::name(k)) + " D=" + std::to_string(D));
}

template <std::size_t D>
void clipped_case(gen::Kind k, std::size_t n, std::uint64_t seed, std::size_t samples) {
  auto input = gen::points<D>(k, n, seed);
  WellSpacedSet<D> ws(input);
  auto M = coords<D>(ws.vertices());
  std::mt19937_64 rng(seed);
  for (std::size_t s = 0; s < samples; ++s) {
    std::size_t v = rng() % M.size();
    auto scan = ws.clipped_voronoi_neighbors(M[v]);
    std::vector<VertexPoint<D>> brute;  // these inputs have double outputs
    for (auto u : kmr::wsjudge::clipped_voronoi_neighbors<D>(M, v, ws.params().beta)) brute.push_back(M[u]);
    std::sort(brute.begin(), brute.end());
    EXPECT_EQ(scan, brute) << gen::name(k) << " D=" << D << " vertex " << v;
  }
}

}  // namespace

TEST(WellspacedStatic, T3_3_4_WellSpacedAndSizeConforming2D) {
  RecordProperty("claim", "T3.3.4");
  for (auto k : gen::kAllKinds) static_case<2>(k, 30, 1);
}
TEST(WellspacedStatic, T3_3_4_WellSpacedAndSizeConforming3D) {
  RecordProperty("claim", "T3.3.4");
  // clustered and close pairs make thousands of Steiner vertices in 3D (Ω(log Δ) rings): 2D only
  for (auto k : {gen::Kind::uniform, gen::Kind::plane, gen::Kind::sphere, gen::Kind::grid, gen::Kind::boundary})
    static_case<3>(k, 10, 2);
  static_case<3>(gen::Kind::line, 4, 2);
}
TEST(WellspacedStatic, T3_3_4_WellSpacedAndSizeConforming4D) {
  RecordProperty("claim", "T3.3.4");
  for (auto k : {gen::Kind::uniform, gen::Kind::boundary, gen::Kind::grid}) static_case<4>(k, 5, 3);
}
TEST(WellspacedStatic, T3_3_4_OtherParameters) {
  RecordProperty("claim", "T3.3.4");
  auto input = gen::points<2>(gen::Kind::uniform, 25, 9);
  for (Params p : {Params{1.25, 2.5}, Params{2.0, 4.0}, Params{1.5, 2.0}}) {
    WellSpacedSet<2> ws(input, p);
    check_output<2>(input, ws, "rho=" + std::to_string(p.rho));
  }
}

TEST(WellspacedClippedVoronoi, L3_2_1_ScanEqualsBruteForce) {
  RecordProperty("claim", "L3.2.1");
  for (auto k : gen::kAllKinds) clipped_case<2>(k, 25, 4, 8);
  for (auto k : {gen::Kind::uniform, gen::Kind::grid, gen::Kind::sphere, gen::Kind::boundary}) clipped_case<3>(k, 10, 5, 6);
  clipped_case<4>(gen::Kind::uniform, 5, 6, 3);
}

// The two-tier filter (spec/wellspaced.md, "Exactness"): the interval tier decides exactly what the
// exact tier decides, so a run with the interval tier equals an exact-only run, vertex for vertex
// and graph line for graph line; both tiers are exercised (the grid forces exact fallbacks).
template <std::size_t D>
void tiers_case(gen::Kind k, std::size_t n, std::uint64_t seed, bool expect_fallbacks, Params p = {}) {
  auto in = gen::points<D>(k, n, seed);
  Params exact = p;
  exact.exact_only = true;
  WellSpacedSet<D> fast(in, p), slow(in, exact);
  std::string what = std::to_string(D) + "D " + gen::name(k);
  ASSERT_EQ(coords<D>(fast.vertices()), coords<D>(slow.vertices())) << what;
  EXPECT_EQ(fast.canonical_graph(), slow.canonical_graph()) << what;
  const auto& s = fast.stats();
  if (expect_fallbacks) EXPECT_GT(s.exact_fallbacks, 0u) << what;  // degenerate: cocircular vertices
  else EXPECT_LT(s.exact_fallbacks, (s.cv_calls + s.fills) / 10) << what << ": the interval tier decided too little";
}
TEST(WellspacedStatic, IntervalTierEqualsExactTier) {
  tiers_case<2>(gen::Kind::uniform, 60, 3, false);
  tiers_case<2>(gen::Kind::clustered, 60, 4, false);
  tiers_case<2>(gen::Kind::close_pair, 40, 5, false);
  tiers_case<2>(gen::Kind::grid, 49, 6, true);
  tiers_case<3>(gen::Kind::uniform, 12, 7, false);
  tiers_case<3>(gen::Kind::grid, 27, 8, true);
}
// Issue 11 §5: 3D/4D clip vertices solved from their tight constraints (double_filter::solve_rows)
// on the families whose chained enclosures made many calls fall back (main: 77 of 467 calls on the
// 4D case, 16 %, over the bound of tiers_case; now 2): 4D clustered at ρ = 6, β = 12 (|M| = 99)
// and a 3D pair 2^-30 apart at ρ = 4, β = 8 (|M| = 232); small outputs: the exact-only runs are
// the cost.
TEST(WellspacedStatic, IntervalTierEqualsExactTierClusteredAndClosePairs3D4D) {
  tiers_case<4>(gen::Kind::clustered, 4, 1, false, Params{6.0, 12.0});
  tiers_case<3>(gen::Kind::close_pair, 3, 2, false, Params{4.0, 8.0});
}

// Coordinates far below the depth limit's scale (2^-600) are valid input: the exact tier's interval
// filters must bound tiny products, not throw (found in review: Uncertain escaped both tiers).
TEST(WellspacedStatic, TinyCoordinatesAreValidInput) {
  std::vector<Point<2>> in{{0x1p-600, 0.5}, {0.5, 0.5}, {0.3, 0.9}, {0x1p-1074, 0x1p-1000}};
  for (bool exact_only : {false, true}) {
    Params p;
    p.exact_only = exact_only;
    WellSpacedSet<2> ws(in, p);
    std::sort(in.begin(), in.end());
    check_output<2>(in, ws, exact_only ? "tiny, exact only" : "tiny");
  }
}

TEST(WellspacedDynamic, L3_4_2_UpdatesEqualFromScratch) {
  RecordProperty("claim", "L3.4.2");
  for (auto k : gen::kAllKinds) {
    auto pts = gen::points<2>(k, 24, 8);
    std::vector<Point<2>> cur(pts.begin(), pts.begin() + 12);
    WellSpacedSet<2> ws(cur);
    std::mt19937_64 rng(8);
    for (int step = 0; step < 6; ++step) {
      const auto& p = pts[rng() % pts.size()];
      bool present = std::find(cur.begin(), cur.end(), p) != cur.end();
      if (present && cur.size() <= 2) continue;
      if (present) {
        ws.erase(p);
        cur.erase(std::find(cur.begin(), cur.end(), p));
      } else {
        ws.insert(p);
        cur.push_back(p);
      }
      WellSpacedSet<2> fresh(cur);
      ASSERT_EQ(coords<2>(ws.vertices()), coords<2>(fresh.vertices())) << gen::name(k) << " step " << step;
      ASSERT_EQ(ws.canonical_graph(), fresh.canonical_graph()) << gen::name(k) << " step " << step;
      ASSERT_EQ(ws.tree_internal_nodes(), fresh.tree_internal_nodes());
    }
  }
}

TEST(WellspacedInput, BadInputIsRefusedAndNothingChanges) {
  std::vector<Point<2>> in{{0.25, 0.25}, {0.75, 0.5}, {0.5, 0.875}};
  EXPECT_THROW(WellSpacedSet<2>({{0.1, 0.2}}), kmr::InputError);
  EXPECT_THROW(WellSpacedSet<2>({{0.1, 0.2}, {0.1, 0.2}}), kmr::InputError);
  EXPECT_THROW(WellSpacedSet<2>({{0.1, 1.5}, {0.3, 0.2}}), kmr::InputError);
  EXPECT_THROW(WellSpacedSet<2>({{0.1, NAN}, {0.3, 0.2}}), kmr::InputError);
  EXPECT_THROW(WellSpacedSet<2>(in, Params{0.9, 2.0}), kmr::InputError);
  EXPECT_THROW(WellSpacedSet<2>(in, Params{1.5, 1.5}), kmr::InputError);
  WellSpacedSet<2> ws(in);
  auto g = ws.canonical_graph();
  EXPECT_THROW(ws.insert({0.25, 0.25}), kmr::InputError);
  EXPECT_THROW(ws.erase({0.3, 0.3}), kmr::InputError);
  EXPECT_THROW(ws.insert({-0.1, 0.3}), kmr::InputError);
  EXPECT_THROW(ws.insert({0.25 + std::ldexp(1.0, -60), 0.25}), kmr::InputError);
  EXPECT_EQ(ws.canonical_graph(), g);
  {  // erasing a Steiner vertex is refused (this input needs Steiner vertices; the 3 above do not)
    WellSpacedSet<2> big(gen::points<2>(gen::Kind::uniform, 12, 21));
    const auto vs = big.vertices();  // one copy: begin() and end() must come from the same vector
    auto steiner = std::find_if(vs.begin(), vs.end(), [](auto& v) { return v.is_steiner; });
    ASSERT_NE(steiner, vs.end());
    auto before = big.canonical_graph();
    EXPECT_THROW(big.erase(steiner->x), kmr::InputError);
    EXPECT_EQ(big.canonical_graph(), before);
  }
  ws.erase({0.25, 0.25});
  EXPECT_THROW(ws.erase({0.75, 0.5}), kmr::InputError);  // 2 must remain
}

TEST(WellspacedDynamic, InsertingAtASteinerVertex) {
  RecordProperty("claim", "L3.4.2");
  auto input = gen::points<2>(gen::Kind::uniform, 12, 21);
  WellSpacedSet<2> ws(input);
  Point<2> s{};
  for (auto& v : ws.vertices())
    if (v.is_steiner) s = v.x;
  ws.insert(s);
  input.push_back(s);
  WellSpacedSet<2> fresh(input);
  EXPECT_EQ(ws.canonical_graph(), fresh.canonical_graph());
}

// Issue 11, §1: degenerate inputs at every (ρ, β) a user may choose. The 100 collinear points at
// ρ = 2, β = 4 and ρ = 3, β = 6 ended in "no double-precision point found in the picking region"
// (the Steiner direction was truncated too coarsely to hit a cell that exceeds the ρ-ball by a
// sliver); each output is judged by the exact brute force.
namespace {
struct RhoBeta {
  double rho, beta;
};
// ρ ∈ [1.1, 4], β from just above ρ to 2ρ; ρ near 1 makes large outputs in 3D/4D, so the
// sweeps narrow with the dimension (the CLI sweep in spec/wellspaced.md covers the rest)
const RhoBeta kSweep2[] = {{1.1, 1.2}, {1.1, 3}, {1.5, 3}, {2, 3}, {2, 4}, {2.5, 5}, {3, 6}, {4, 4.5}, {4, 8}};
const RhoBeta kSweep3[] = {{1.5, 3}, {2, 3}, {2, 4}, {3, 6}, {4, 4.5}, {4, 8}};
const RhoBeta kSweep4[] = {{3, 6}, {4, 4.5}, {4, 8}};
const RhoBeta kSweep4Small[] = {{2, 3}, {2, 4}};  // collinear only: cospherical makes |M| ≈ 110, 20 s each

template <std::size_t D>
void degenerate_sweep(std::size_t n, const std::vector<RhoBeta>& sweep,
                      std::vector<gen::Kind> kinds = {std::begin(gen::kDegenerateKinds), std::end(gen::kDegenerateKinds)}) {
  for (auto k : kinds)
    for (auto [rho, beta] : sweep) {
      auto input = gen::points<D>(k, n, 1);
      std::sort(input.begin(), input.end());
      Params p;
      p.rho = rho;
      p.beta = beta;
      std::string what = std::string(gen::name(k)) + " D=" + std::to_string(D) + " n=" + std::to_string(input.size()) +
                         " rho=" + std::to_string(rho) + " beta=" + std::to_string(beta);
      try {
        auto t0 = std::chrono::steady_clock::now();
        WellSpacedSet<D> ws(input, p);
        check_output<D>(input, ws, what);
        std::printf("  %s: |M| = %zu, %.2f s\n", what.c_str(), ws.vertices().size(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
      }
    }
}
}  // namespace

TEST(WellspacedStatic, T3_3_4_DegenerateFamiliesOverRhoBeta2D) {
  RecordProperty("claim", "T3.3.4");
  degenerate_sweep<2>(40, {std::begin(kSweep2), std::end(kSweep2)});
}
TEST(WellspacedStatic, T3_3_4_DegenerateFamiliesOverRhoBeta3D) {
  RecordProperty("claim", "T3.3.4");
  degenerate_sweep<3>(8, {std::begin(kSweep3), std::end(kSweep3)});
}
TEST(WellspacedStatic, T3_3_4_DegenerateFamiliesOverRhoBeta4D) {
  RecordProperty("claim", "T3.3.4");
  degenerate_sweep<4>(5, {std::begin(kSweep4), std::end(kSweep4)});
  degenerate_sweep<4>(5, {std::begin(kSweep4Small), std::end(kSweep4Small)}, {gen::Kind::collinear, gen::Kind::axis_line});
}
TEST(WellspacedStatic, T3_3_4_HundredCollinearPointsIssue11) {
  RecordProperty("claim", "T3.3.4");
  for (auto k : {gen::Kind::collinear, gen::Kind::axis_line})
    for (auto [rho, beta] : {RhoBeta{2, 3}, RhoBeta{2, 4}, RhoBeta{3, 6}}) {
      auto input = gen::points<2>(k, 100, 1);
      Params p;
      p.rho = rho;
      p.beta = beta;
      WellSpacedSet<2> ws(input, p);
      check_output<2>(input, ws, std::string(gen::name(k)) + " rho=" + std::to_string(rho) + " beta=" + std::to_string(beta));
    }
  auto grid = gen::points<2>(gen::Kind::grid_fine, 400, 1);
  ASSERT_EQ(grid.size(), 400u);
  for (auto [rho, beta] : {RhoBeta{2, 3}, RhoBeta{2, 4}}) {
    Params p;
    p.rho = rho;
    p.beta = beta;
    WellSpacedSet<2> ws(grid, p);
    check_output<2>(grid, ws, "20x20 grid rho=" + std::to_string(rho) + " beta=" + std::to_string(beta));
  }
}
// ρ close to 1: the exact rank thresholds ρ^{2r} grow to millions of bits; the run is refused with
// a message instead of running for minutes (issue 11).
TEST(WellspacedInput, RhoTooCloseToOneIsRefused) {
  std::vector<Point<2>> three = {{0.5, 0.5}, {0.52, 0.5}, {0.9, 0.1}};
  Params p;
  p.rho = 1.0000001;
  p.beta = 3;
  try {
    WellSpacedSet<2> ws(three, p);
    ADD_FAILURE() << "rho = 1.0000001 was accepted";
  } catch (const kmr::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too close to 1"), std::string::npos) << e.what();
  }
  p.rho = 1.01;  // reachable: runs
  WellSpacedSet<2> ws(three, p);
  check_output<2>(three, ws, "rho=1.01");
}

// The output-size estimate (issue 11 §1; spec/wellspaced.md, "Output-size estimate") is an
// envelope of measured outputs: on pairs 2^-10 … 1 ulp apart, uniform, clustered and collinear
// inputs, 2D and 3D, ρ from 1.1 to 4, it is at least |M| and at most 15·|M|, and it counts the
// construction's own tree (leaves = the squares StableWS builds).
template <std::size_t D>
void estimate_case(const std::vector<Point<D>>& input, double rho, double beta, const std::string& what) {
  Params p;
  p.rho = rho;
  p.beta = beta;
  const OutputEstimate e = estimate_output<D>(input, rho);
  WellSpacedSet<D> ws(input, p);
  const double m = double(ws.vertices().size());
  EXPECT_EQ(e.leaves, ws.stats().squares) << what;
  EXPECT_EQ(e.input, input.size()) << what;
  EXPECT_GE(e.vertices, m) << what << ": the estimate is below the output";
  EXPECT_LE(e.vertices, 15 * m) << what << ": the estimate is more than 15x the output";
}
TEST(WellspacedInput, OutputEstimateIsAnEnvelopeOfTheOutput) {
  const std::vector<Point<2>> ulp = {{0.5, 0.5}, {std::nextafter(0.5, 1.0), 0.5}};
  for (auto [rho, beta] : {RhoBeta{1.1, 2.2}, RhoBeta{1.2, 3}, RhoBeta{1.2, 4}, RhoBeta{1.5, 8}, RhoBeta{4, 8}})
    estimate_case<2>(ulp, rho, beta, "1-ulp pair rho=" + std::to_string(rho) + " beta=" + std::to_string(beta));
  for (auto [rho, beta] : {RhoBeta{1.2, 3}, RhoBeta{2, 4}}) {
    const std::string r = " rho=" + std::to_string(rho);
    estimate_case<2>(gen::near_duplicate_pairs<2>(2, 0x1p-30, 3), rho, beta, "2^-30 pair" + r);
    estimate_case<2>(gen::points<2>(gen::Kind::uniform, 100, 1), rho, beta, "uniform 100" + r);
    estimate_case<2>(gen::points<2>(gen::Kind::clustered, 40, 1), rho, beta, "clustered 40" + r);
    estimate_case<2>(gen::points<2>(gen::Kind::collinear, 40, 1), rho, beta, "collinear 40" + r);
    estimate_case<3>(gen::points<3>(gen::Kind::uniform, 30, 1), rho, beta, "3D uniform 30" + r);
  }
  estimate_case<3>(gen::near_duplicate_pairs<3>(2, 0x1p-10, 3), 1.5, 3, "3D 2^-10 pair rho=1.5");
  // ρ → 1: the output saturates (3 points: 268 vertices at ρ = 1.05, 440 at 1 + 2^-9); the
  // estimate stays finite and above it
  const std::vector<Point<2>> three = {{0.5, 0.5}, {0.52, 0.5}, {0.9, 0.1}};
  for (double rho : {1.05, 1.0078125}) {
    const OutputEstimate e = estimate_output<2>(three, rho);
    Params p;
    p.rho = rho;
    WellSpacedSet<2> ws(three, p);
    EXPECT_GE(e.vertices, double(ws.vertices().size())) << "three points rho=" << rho;
    EXPECT_LE(e.vertices, 15.0 * double(ws.vertices().size())) << "three points rho=" << rho;
  }
}
// The progress hook sees the vertex count grow, and its last report does not exceed the output.
TEST(WellspacedInput, ProgressHookReportsGrowingVertexCounts) {
  Params p;
  p.rho = 1.2;
  std::vector<std::size_t> seen;
  p.progress = [&](std::size_t vertices, std::size_t) { seen.push_back(vertices); };
  const std::vector<Point<2>> ulp = {{0.5, 0.5}, {std::nextafter(0.5, 1.0), 0.5}};
  WellSpacedSet<2> ws(ulp, p);
  ASSERT_GE(seen.size(), 2u) << "a run of " << ws.stats().ops << " operations reported " << seen.size() << " times";
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_LT(seen.front(), seen.back());
  EXPECT_LE(seen.back(), ws.vertices().size());
}

// Order matters to PropagateWS (construct sorts its input, so reversing the input tests nothing):
// the same final input set reached by two different histories — (a) built from S ∪ X, then X
// erased in one order; (b) built from S minus Y, then Y inserted in the reverse order and X
// inserted and erased in between — gives identical vertices, computation graphs and trees.
template <std::size_t D>
void histories_case(gen::Kind k, std::size_t n, std::size_t extra, std::uint64_t seed) {
  auto pts = gen::points<D>(k, n + extra, seed);
  std::mt19937_64 rng(seed);
  std::shuffle(pts.begin(), pts.end(), rng);
  std::vector<Point<D>> S(pts.begin(), pts.begin() + n), X(pts.begin() + n, pts.end());
  const std::size_t ny = std::min<std::size_t>(extra, n - 2);
  std::vector<Point<D>> Y(S.begin(), S.begin() + ny);
  std::vector<Point<D>> SX = S;
  SX.insert(SX.end(), X.begin(), X.end());
  WellSpacedSet<D> a(SX);
  for (const auto& x : X) a.erase(x);
  WellSpacedSet<D> b(std::vector<Point<D>>(S.begin() + ny, S.end()));
  for (std::size_t i = 0; i < std::max(Y.size(), X.size()); ++i) {
    if (i < Y.size()) b.insert(Y[Y.size() - 1 - i]);
    if (i < X.size()) b.insert(X[i]);
  }
  for (std::size_t i = X.size(); i-- > 0;) b.erase(X[i]);
  const std::string what = std::string(gen::name(k)) + " D=" + std::to_string(D);
  ASSERT_EQ(a.input(), b.input()) << what;
  EXPECT_EQ(coords<D>(a.vertices()), coords<D>(b.vertices())) << what;
  EXPECT_EQ(a.canonical_graph(), b.canonical_graph()) << what;
  EXPECT_EQ(a.tree_internal_nodes(), b.tree_internal_nodes()) << what;
}

TEST(WellspacedDynamic, L3_4_2_DifferentHistoriesSameGraph) {
  RecordProperty("claim", "L3.4.2");
  for (auto k : {gen::Kind::uniform, gen::Kind::clustered, gen::Kind::close_pair, gen::Kind::grid, gen::Kind::boundary})
    histories_case<2>(k, 20, 6, 3);
  histories_case<3>(gen::Kind::uniform, 8, 3, 4);
}

// Issue 11 §1 / Lemma 3.4.2's (I1): the order of the operations within one time bucket of the
// propagation queue does not matter — with Params::bucket_shuffle_seed, each bucket is processed
// in a seeded random order; the vertices, the canonical graph and the result of an insertion and
// a deletion equal those of the default (vertex) order. Non-vacuous: the runs have buckets with
// several executed fills (checked), where an operation seeing a same-time vertex would differ.
template <std::size_t D>
void bucket_order_case(const std::vector<Point<D>>& input, const Point<D>& extra, const std::string& what) {
  Params p;
  p.rho = 1.5;
  p.beta = 3;
  WellSpacedSet<D> ref(input, p);
  std::map<std::tuple<int, bool, std::int64_t>, int> fills_at;
  for (const auto& op : ref.computation_graph())
    if (op.executed && op.fill) ++fills_at[{op.rank, op.fill, op.color}];
  int crowded = 0;
  for (const auto& [t, c] : fills_at) crowded += c >= 2;
  ASSERT_GT(crowded, 0) << what << ": no time bucket with two fills";
  const auto ref_vertices = coords<D>(ref.vertices());
  const auto ref_graph = ref.canonical_graph();
  ref.insert(extra);
  const auto ref_ins = ref.canonical_graph();
  ref.erase(input.front());
  const auto ref_del = ref.canonical_graph();
  for (std::uint64_t seed : {1, 2, 3}) {
    Params q = p;
    q.bucket_shuffle_seed = seed;
    WellSpacedSet<D> ws(input, q);
    const std::string w = what + " seed " + std::to_string(seed);
    EXPECT_EQ(coords<D>(ws.vertices()), ref_vertices) << w;
    EXPECT_EQ(ws.canonical_graph(), ref_graph) << w;
    ws.insert(extra);
    EXPECT_EQ(ws.canonical_graph(), ref_ins) << w << " after an insertion";
    ws.erase(input.front());
    EXPECT_EQ(ws.canonical_graph(), ref_del) << w << " after a deletion";
    EXPECT_EQ(ws.check_internal_indexes(), "") << w;
  }
}
TEST(WellspacedDynamic, L3_4_2_OrderWithinATimeBucketDoesNotMatter) {
  RecordProperty("claim", "L3.4.2");
  bucket_order_case<2>(gen::points<2>(gen::Kind::uniform, 60, 5), {0.3141592653589793, 0.2718281828459045}, "2D uniform 60");
  bucket_order_case<2>(gen::points<2>(gen::Kind::clustered, 40, 5), {0.5, 0.125}, "2D clustered 40");
  bucket_order_case<2>(gen::near_duplicate_pairs<2>(6, 0x1p-20, 5), {0.75, 0.75}, "2D 2^-20 pairs");
  bucket_order_case<3>(gen::points<3>(gen::Kind::uniform, 20, 5), {0.3, 0.6, 0.2}, "3D uniform 20");
}

// Lemma 3.3.12, directly on the computation graph of a run: for two executed fills v_(t), u_(t)
// at the same time t = (r, F, c), (i) no Steiner vertex inserted by v_(t) lies in a square read by
// u_(t) (so filling them in either order reads the same data), and (ii) every Steiner vertex w of
// v_(t) has |uw| > 2β·ρ^{r+1}, outside the bound on u's certificate region the proof uses (and
// |vu| > 3βρ^{r+1}). Exact in dyadic arithmetic.
namespace {
struct FillNode {
  std::string name, time;
  std::vector<double> v;
  int rank = 0;
  std::vector<std::vector<double>> steiner;
  std::set<std::string> reads, written;  // squares read; squares of the Steiner vertices inserted
};
std::vector<double> parse_coords(const std::string& s, std::size_t D) {
  std::vector<double> out;
  const char* p = s.c_str();
  for (std::size_t i = 0; i < D; ++i) {
    char* end = nullptr;
    out.push_back(std::strtod(p, &end));
    p = end;
  }
  return out;
}
kmr::exact::Dyadic dist2_exact(const std::vector<double>& a, const std::vector<double>& b) {
  using kmr::exact::Dyadic;
  Dyadic s;
  for (std::size_t i = 0; i < a.size(); ++i) {
    Dyadic d = Dyadic::from_double(a[i]) - Dyadic::from_double(b[i]);
    s += d * d;
  }
  return s;
}
// |ab|² > (k·β·ρ^{r+1})², exactly
bool farther_than(const std::vector<double>& a, const std::vector<double>& b, int k, double beta, double rho, int r) {
  using kmr::exact::Dyadic;
  Dyadic lhs = dist2_exact(a, b), rhs = Dyadic(k * k) * Dyadic::from_double(beta) * Dyadic::from_double(beta);
  const Dyadic r2 = Dyadic::from_double(rho) * Dyadic::from_double(rho);
  for (int i = 0; i < std::abs(r + 1); ++i) (r + 1 >= 0 ? rhs : lhs) *= r2;
  return lhs > rhs;
}
template <std::size_t D>
std::size_t check_same_colour_fills(const WellSpacedSet<D>& ws, const std::string& what) {
  std::map<std::string, FillNode> fills;  // by operation name
  for (const std::string& line : ws.canonical_graph()) {
    auto name_at = [&](std::size_t from) {
      auto a = line.find('(', from), b = line.find(')', a);
      return line.substr(a, b - a + 1);
    };
    if (line.rfind("O ", 0) == 0 && line.size() > 2 && line.back() == 'x' && line.find(",F,") != std::string::npos) {
      FillNode f;
      f.name = name_at(0);
      auto at = f.name.find(" @");
      f.time = f.name.substr(at + 2, f.name.size() - at - 3);
      f.rank = std::stoi(f.time);
      f.v = parse_coords(f.name.substr(1), D);
      fills[f.name] = f;
    }
  }
  for (const std::string& line : ws.canonical_graph()) {
    if (line.rfind("R ", 0) == 0) {
      auto arrow = line.find(" -> ");
      auto it = fills.find(line.substr(arrow + 4));
      if (it != fills.end()) it->second.reads.insert(line.substr(2, arrow - 2));
    } else if (line.rfind("W ", 0) == 0) {
      auto arrow = line.find(" -> ");
      auto it = fills.find(line.substr(2, arrow - 2));
      if (it == fills.end()) continue;
      auto rest = line.substr(arrow + 4);
      auto br = rest.find(" [");
      it->second.steiner.push_back(parse_coords(rest.substr(br + 2), D));
      it->second.written.insert(rest.substr(0, br));
    }
  }
  std::map<std::string, std::vector<const FillNode*>> by_time;
  for (auto& [n, f] : fills) by_time[f.time].push_back(&f);
  std::size_t pairs = 0;
  const double beta = ws.params().beta, rho = ws.params().rho;
  for (auto& [t, fs] : by_time)
    for (const FillNode* v : fs)
      for (const FillNode* u : fs) {
        if (v == u) continue;
        ++pairs;
        for (const std::string& sq : v->written)
          EXPECT_FALSE(u->reads.count(sq)) << what << ": " << v->name << " inserted into square " << sq << " read by " << u->name;
        for (const auto& w : v->steiner)
          EXPECT_TRUE(farther_than(w, u->v, 2, beta, rho, v->rank)) << what << ": Steiner vertex of " << v->name << " within 2βρ^{r+1} of " << u->name;
        // the proof's distance bound, for pairs where v was not ρ-well-spaced (it inserted vertices;
        // two well-spaced vertices are independent trivially and may share a tile)
        if (!v->steiner.empty()) {
          EXPECT_TRUE(farther_than(v->v, u->v, 3, beta, rho, v->rank)) << what << ": " << v->name << ", " << u->name;
        }
      }
  return pairs;
}
}  // namespace

TEST(WellspacedStatic, L3_3_12_SameColourFillsAreIndependent) {
  RecordProperty("claim", "L3.3.12");
  std::size_t pairs = 0;
  for (auto k : gen::kAllKinds) {
    auto input = gen::points<2>(k, 100, 5);
    WellSpacedSet<2> ws(input);
    pairs += check_same_colour_fills<2>(ws, std::string(gen::name(k)) + " 2D");
  }
  {
    Params p;
    p.rho = 2;
    p.beta = 4;
    WellSpacedSet<2> ws(gen::points<2>(gen::Kind::collinear, 100, 1), p);
    pairs += check_same_colour_fills<2>(ws, "collinear 2D rho 2");
  }
  WellSpacedSet<3> ws3(gen::points<3>(gen::Kind::uniform, 30, 5));
  pairs += check_same_colour_fills<3>(ws3, "uniform 3D");
  std::printf("  same-time fill pairs checked: %zu\n", pairs);
  EXPECT_GT(pairs, 100u) << "too few same-colour fill pairs: the check would be vacuous";
  RecordProperty("pairs", std::to_string(pairs));
}

// Locality (Theorem 3.4.3, Lemma 3.3.16) by counts: inserting and erasing a point 2^-k from an
// input vertex of 1500 uniform points touches (obsolete + fresh + inconsistent operations) at most
// C·log₂ Δ operations, C = 80 (measured ≤ 61, spec/wellspaced.md), Δ = the spread of the input with
// the point; the bound is far below the operations of the graph, so marking every reader (or
// re-running everything) is caught.
TEST(WellspacedDynamic, T3_4_3_TouchedOperationsPerUpdateWithinCLogSpread) {
  RecordProperty("claim", "T3.4.3");
  auto input = gen::points<2>(gen::Kind::uniform, 1500, 17);
  WellSpacedSet<2> ws(input);
  const std::uint64_t ops = ws.stats().ops;
  for (int k : {10, 20, 30}) {
    Point<2> p = input[input.size() / 2];
    p[0] += std::ldexp(p[0] < 0.5 ? 1.0 : -1.0, -k);
    double dmin = 1e300, dmax = 0;
    for (const auto& a : input) {
      double d = std::hypot(a[0] - p[0], a[1] - p[1]);
      dmin = std::min(dmin, d);
      for (const auto& b : {input.front(), input.back()}) dmax = std::max(dmax, std::hypot(a[0] - b[0], a[1] - b[1]));
    }
    const double log_spread = std::log2(dmax / dmin);
    for (const UpdateStats& u : {ws.insert(p), ws.erase(p)}) {
      std::printf("  k = %d: touched %llu, log2 spread %.1f, ratio %.1f (graph: %llu operations)\n", k,
                  static_cast<unsigned long long>(u.touched()), log_spread, double(u.touched()) / log_spread,
                  static_cast<unsigned long long>(ops));
      EXPECT_LE(double(u.touched()), 80 * log_spread) << "k = " << k;
    }
    ASSERT_LT(80 * log_spread, 0.5 * double(ops)) << "the bound would not catch a global re-run";
  }
}

// The Steiner-choice fallbacks of issue 11 (fine direction, fraction ladder) run in both tiers:
// the collinear inputs at ρ = 2, β = 4 and ρ = 3, β = 6 need them; output and graph equal the
// exact-only run.
TEST(WellspacedStatic, IntervalTierEqualsExactTierOnSliverCells) {
  for (auto [rho, beta] : {std::pair{2.0, 4.0}, std::pair{3.0, 6.0}})
    for (auto k : {gen::Kind::collinear, gen::Kind::axis_line}) {
      auto in = gen::points<2>(k, 100, 1);
      Params p, exact;
      p.rho = exact.rho = rho;
      p.beta = exact.beta = beta;
      exact.exact_only = true;
      WellSpacedSet<2> fast(in, p), slow(in, exact);
      const std::string what = std::string(gen::name(k)) + " rho " + std::to_string(rho);
      ASSERT_EQ(coords<2>(fast.vertices()), coords<2>(slow.vertices())) << what;
      EXPECT_EQ(fast.canonical_graph(), slow.canonical_graph()) << what;
    }
}

// Near-duplicate pairs (issue 11) at separations 2^-20 … 2^-45, over ρ and β: the output is
// ρ-well-spaced and size-conforming (brute force; outputs here are all doubles). Closer pairs (a few
// ulps) need finer Steiner vertices: NearDuplicatePairOneUlpApartAnswersWithFinerSteinerVertices.
namespace {
template <std::size_t D>
void near_duplicate_sweep(std::size_t n, std::initializer_list<int> ks, std::initializer_list<RhoBeta> sweep) {
  for (int k : ks)
    for (auto [rho, beta] : sweep) {
      auto input = gen::near_duplicate_pairs<D>(n, std::ldexp(1.0, -k), 3);
      Params p;
      p.rho = rho;
      p.beta = beta;
      std::string what = "near-duplicate pairs 2^-" + std::to_string(k) + " D=" + std::to_string(D) +
                         " rho=" + std::to_string(rho) + " beta=" + std::to_string(beta);
      try {
        auto t0 = std::chrono::steady_clock::now();
        WellSpacedSet<D> ws(input, p);
        check_output<D>(input, ws, what);
        std::printf("  %s: |M| = %zu, %.2f s\n", what.c_str(), ws.vertices().size(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
      }
    }
}
}  // namespace

// Small, to keep the default run short (the brute force is quadratic in |M|): one or two pairs;
// ρ = 1.5 at 2^-45 (|M| = 1485) and ρ = 1.1 at 2^-30 (|M| = 4527) passed once, by hand (24 s,
// 165 s loaded), as did 3D 2^-30 at ρ = 2 (|M| = 964, 123 s).
TEST(WellspacedStatic, T3_3_4_NearDuplicatePairsOverRhoBeta2D) {
  RecordProperty("claim", "T3.3.4");
  near_duplicate_sweep<2>(4, {20}, {RhoBeta{3, 6}, RhoBeta{4, 8}});
  near_duplicate_sweep<2>(2, {45}, {RhoBeta{3, 6}, RhoBeta{4, 8}});
}
TEST(WellspacedStatic, T3_3_4_NearDuplicatePairsOverRhoBeta3D) {
  RecordProperty("claim", "T3.3.4");
  near_duplicate_sweep<3>(2, {30}, {RhoBeta{4, 8}});
}

// Two points 1 ulp apart (0.5 and its successor, 2^-53; issue 11 §1): some picking regions contain
// no double at all (step 4 of pick enumerates every double of the box), so Steiner vertices finer
// than doubles are needed (VertexPoint, pick step 5). Checked here: the run answers with some such
// vertices; the interval tier makes the exact tier's choices (output and graph equal to an
// exact-only run); an insertion and a deletion reach the from-scratch output and graph
// (Lemma 3.4.2 with fine vertices); hex texts are exact (parsed back by hand). The output is judged
// well-spaced by the CGAL oracle (WsJudge.T3_3_4_NearDuplicatePairsFinerThanDoubles2D and the CLI
// test WsCli.T3_3_4_OneUlpPairCliOutputJudgedByOracle2D).
TEST(WellspacedStatic, NearDuplicatePairOneUlpApartAnswersWithFinerSteinerVertices) {
  RecordProperty("claim", "L3.4.2");
  std::vector<Point<2>> pair = {{0.5, 0.5}, {std::nextafter(0.5, 1.0), 0.5}};
  WellSpacedSet<2> ws(pair);
  Params ex;
  ex.exact_only = true;
  WellSpacedSet<2> slow(pair, ex);
  auto M = ws.vertices();
  std::size_t fine = 0;
  for (const auto& v : M) {
    if (v.exact.is_double()) continue;
    ++fine;
    for (std::size_t i = 0; i < 2; ++i) {
      // the text 0x1.<h>p<e> read back: (16^n + h)·2^(e − 4n) equals the coordinate
      const std::string t = v.exact.text(i);
      if (t.rfind("0x1.", 0) != 0) continue;  // a double coordinate (%a)
      const auto pp = t.find('p');
      const std::string h = t.substr(4, pp - 4);
      kmr::exact::Integer m = 1;
      for (char c : h) m = m * 16 + (c <= '9' ? c - '0' : c - 'a' + 10);
      const kmr::exact::Dyadic back(m, std::stoll(t.substr(pp + 1)) - 4 * std::int64_t(h.size()));
      EXPECT_EQ(back, v.exact.coord(i)) << t;
      EXPECT_LE(kmr::exact::Dyadic::from_double(v.x[i]), v.exact.coord(i));  // x is below()
    }
  }
  EXPECT_GT(fine, 0u);
  ASSERT_EQ(M.size(), slow.vertices().size());
  for (std::size_t i = 0; i < M.size(); ++i) EXPECT_TRUE(M[i].exact == slow.vertices()[i].exact) << i;
  EXPECT_EQ(ws.canonical_graph(), slow.canonical_graph());
  for (std::size_t i = 1; i < M.size(); ++i) EXPECT_TRUE(M[i - 1].exact < M[i].exact) << i;  // sorted, distinct
  const Point<2> extra{0.25, 0.75};
  ws.insert(extra);
  std::vector<Point<2>> three = pair;
  three.push_back(extra);
  WellSpacedSet<2> scratch(three);
  EXPECT_EQ(ws.canonical_graph(), scratch.canonical_graph());
  ws.erase(extra);
  EXPECT_EQ(ws.canonical_graph(), slow.canonical_graph());
  EXPECT_EQ(ws.check_internal_indexes(), "");
  std::printf("  |M| = %zu, %zu finer than doubles\n", M.size(), fine);
}

// The brute-force judges of src/wsjudge against hand-derived values (they share no code with the
// library, so these are what make their verdicts trustworthy; the CGAL oracle cross-checks the
// neighbour judge too: WsJudge.L3_2_1_ClippedVoronoiScanAgreesWithOracle).
// Two points v = (½, …, ½), u = v + ⅛e_1: Vor(v) ∩ [0,1]^D = {x_1 ≤ 9/16}, farthest from v at the
// corners x_1 = 0 (|xv|² = D/4), NN² = 1/64; Vor(u)'s corners are nearer. So the set is
// ρ-well-spaced iff ρ² ≥ 16·D: ρ* = 4√D.
template <std::size_t D>
void judge_two_points_case() {
  Point<D> v, u;
  v.fill(0.5);
  u = v;
  u[0] = 0.625;
  const double rho_star = 4 * std::sqrt(double(D));
  const double below = std::nextafter(rho_star, 0.0), above = std::nextafter(rho_star, 10.0);
  // rho_star is rounded: decide which double side is exact by ρ² vs 16·D in exact dyadics
  auto ge = [](double r) { return kmr::exact::Dyadic::from_double(r) * kmr::exact::Dyadic::from_double(r) >= kmr::exact::Dyadic(16 * int(D)); };
  for (double r : {below, rho_star, above, 2.0, 10.0})
    EXPECT_EQ(is_well_spaced<D>({v, u}, r), ge(r)) << D << "D, rho = " << r;
}
TEST(WsJudgeBruteForce, WellSpacedTwoPointsHandDerived) {
  judge_two_points_case<2>();
  judge_two_points_case<3>();
  judge_two_points_case<4>();
}
// v = (½, ½), a = v + (1/16, 0) (NN = 1/16), w = v + (0, h): the face of Vor(v) on the bisector of
// v, w is nearest to v at v + (0, h/2) (a's bisector x = ½ + 1/32 does not cut it), so w is a
// β-clipped neighbour iff h/2 ≤ β/16: with β = 3, iff h ≤ 3/8 (closed). a always is. In 3D the
// same with a third coordinate ½.
template <std::size_t D>
void judge_neighbour_case() {
  for (double h : {0.375, 0.375 + 0x1p-20, 0.25, 0.4375}) {
    Point<D> v, a, w;
    v.fill(0.5);
    a = v;
    a[0] += 1.0 / 16;
    w = v;
    w[1] += h;
    std::vector<std::size_t> want{1};
    if (h <= 0.375) want.push_back(2);
    EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<D>({v, a, w}, 0, 3.0), want) << D << "D, h = " << h;
  }
  // a square of side s around v's corner: the four sites are cocircular with v's cell corner
  // (degenerate); the diagonal site shares only a vertex of the cell, at distance s/√2 · … :
  // v = (¼, ¼), others at (¼+s, ¼), (¼, ¼+s), (¼+s, ¼+s); the diagonal's face is the single
  // point v + (s/2, s/2), |·| = s/√2, NN = s, so it is a neighbour iff β ≥ 1/√2 (always here).
  if constexpr (D == 2) {
    const double s = 1.0 / 8;
    std::vector<Point<2>> M{{0.25, 0.25}, {0.25 + s, 0.25}, {0.25, 0.25 + s}, {0.25 + s, 0.25 + s}};
    EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(M, 0, 1.5), (std::vector<std::size_t>{1, 2, 3}));
    EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(M, 0, 0.70703125), (std::vector<std::size_t>{1, 2}));  // < 1/√2
    EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(M, 0, 0.70715332), (std::vector<std::size_t>{1, 2, 3}));  // > 1/√2
  }
}
TEST(WsJudgeBruteForce, ClippedNeighboursHandDerived) {
  judge_neighbour_case<2>();
  judge_neighbour_case<3>();
}
// Removing the Steiner vertices of a real output leaves a set that is not well-spaced (grid input
// at ρ = 1.5 has fills), and a vertex moved onto another's bisector breaks size conformity.
TEST(WsJudgeBruteForce, RejectsOutputWithoutItsSteinerVertices) {
  auto input = gen::points<2>(gen::Kind::uniform, 20, 7);
  WellSpacedSet<2> ws(input);
  std::vector<Point<2>> M, inputs_only;
  for (const auto& v : ws.vertices()) {
    M.push_back(v.x);
    if (!v.is_steiner) inputs_only.push_back(v.x);
  }
  ASSERT_GT(M.size(), inputs_only.size());
  EXPECT_TRUE(is_well_spaced<2>(M, 1.5));
  EXPECT_FALSE(is_well_spaced<2>(inputs_only, 1.5));
  // a point at 2^-20 from an input vertex: NN tiny against lfs of the input
  auto M2 = M;
  M2.push_back({M[0][0] + (M[0][0] < 0.5 ? 0x1p-20 : -0x1p-20), M[0][1]});
  EXPECT_FALSE(is_size_conforming<2>(input, M2, 1.5));
}

// The judges on exact points (outputs with vertices finer than a double, issue 11 §1).
namespace {
using kmr::wsjudge::ExactPoint;
using kmr::wsjudge::Rational;
using kmr::wsjudge::read_hex_float;
Rational pow2(int e) {
  Rational x = 1;
  for (int i = 0; i < std::abs(e); ++i) x = e > 0 ? Rational(x * 2) : Rational(x / 2);
  return x;
}
// The library's exact text of every vertex, read back by the judge's own reader.
template <std::size_t D>
std::vector<ExactPoint<D>> exact_points(const std::vector<Vertex<D>>& vs) {
  std::vector<ExactPoint<D>> out;
  for (const auto& v : vs) {
    ExactPoint<D> x;
    for (std::size_t i = 0; i < D; ++i) x[i] = read_hex_float(v.exact.text(i));
    out.push_back(x);
  }
  return out;
}
}  // namespace

// Hand-derived values, the text of every "%a" double (as strtod reads it), and malformed texts.
TEST(WsJudgeBruteForce, ReadHexFloatIsExact) {
  EXPECT_EQ(read_hex_float("0x1.8p-3"), Rational(3, 16));
  EXPECT_EQ(read_hex_float("-0x1.0000000000001p+0"), -(1 + pow2(-52)));
  EXPECT_EQ(read_hex_float("0x1.00000000000000000001p-1"), Rational(1, 2) + pow2(-81));  // 20 digits
  EXPECT_EQ(read_hex_float("0x0p+0"), 0);
  EXPECT_EQ(read_hex_float("0xA.8p1"), 21);
  std::mt19937_64 rng(11);
  char buf[64];
  for (int i = 0; i < 2000; ++i) {
    double d;
    const std::uint64_t bits = rng();
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    std::snprintf(buf, sizeof buf, "%a", d);
    EXPECT_EQ(read_hex_float(buf), Rational(d)) << buf;
  }
  for (const char* bad : {"", "0x", "1.5", "0x1.8", "0x1.8q3", "0x1p", "0x1.8p-3x", "0x1..8p0", "0xp0", "0x1p-"})
    EXPECT_THROW(read_hex_float(bad), std::invalid_argument) << bad;
}

// v = (½, ½), u = v + 2^-60·e_1 (not a double: rounded, u = v): Vor(v) ∩ [0,1]² = {x_1 ≤ ½ + 2^-61},
// farthest from v at the corners x_1 = 0 (|xv|² = ½), NN² = 2^-120: well-spaced iff ρ² ≥ 2^119
// (u's corners are nearer). And the neighbour case of judge_neighbour_case scaled by 2^-56.
TEST(WsJudgeBruteForce, ExactPointsFinerThanDoublesHandDerived) {
  const Rational h = Rational(1, 2);
  const std::vector<ExactPoint<2>> pair{{h, h}, {h + pow2(-60), h}};
  EXPECT_FALSE(is_well_spaced<2>(pair, 0x1p59));
  EXPECT_TRUE(is_well_spaced<2>(pair, 0x1p60));
  EXPECT_FALSE(is_well_spaced<2>(std::vector<Point<2>>{{0.5, 0.5}, {0.5 + 0x1p-60, 0.5}}, 0x1p60));  // rounded: a duplicate
  const Rational s = pow2(-56);
  for (double hh : {0.375, 0.375 + 0x1p-20, 0.25, 0.4375}) {
    const std::vector<ExactPoint<2>> M{{h, h}, {h + s / 16, h}, {h, h + Rational(hh) * s}};
    std::vector<std::size_t> want{1};
    if (hh <= 0.375) want.push_back(2);
    EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(M, 0, 3.0), want) << "h = " << hh;
  }
  // u1 = v − 2^-55·e_1 rounds to v itself (a tie, to even), u2 = v + 2^-53·e_1 is a double: NN = 2^-55
  // and Vor(v) is the strip ½ − 2^-56 ≤ x_1 ≤ ½ + 2^-54, so u2's face is 2^-54 from v: a β-clipped
  // neighbour at β = 8 (r = 2^-52), not at β = 1 (r = 2^-55); u1's face (2^-56) at both. A filter
  // reading the rounded points would see NN = 0 and drop u2.
  const std::vector<ExactPoint<2>> strip{{h, h}, {h - pow2(-55), h}, {h + pow2(-53), h}};
  EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(strip, 0, 8.0), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(kmr::wsjudge::clipped_voronoi_neighbors<2>(strip, 0, 1.0), (std::vector<std::size_t>{1}));
  // size conformity: input {v, v + 2^-60 e_1} exactly, lfs(v) = 2^-60; M adds w at 2^-70 from v:
  // NN_M(v) = 2^-70 < lfs/c (c = 6 at ρ = 1.5). Inputs are doubles in the API: scale the pair to
  // [0, 2^-60] (doubles), fine points in M.
  const std::vector<Point<2>> N{{0, 0}, {0x1p-60, 0}};
  std::vector<ExactPoint<2>> M{{0, 0}, {pow2(-60), 0}};
  EXPECT_TRUE(is_size_conforming<2>(N, M, 1.5));
  M.push_back({pow2(-70) + pow2(-130), 0});
  EXPECT_FALSE(is_size_conforming<2>(N, M, 1.5));
}

// The 1-ulp pair's output (vertices finer than doubles), read from the library's exact text: the
// exact judges accept it (ρ-well-spaced, size-conforming; the CGAL oracle agrees:
// WsJudge.T3_3_4_NearDuplicatePairsFinerThanDoubles2D), and reject it without its Steiner vertices
// and with its fine vertices rounded to doubles.
TEST(WsJudgeBruteForce, T3_3_4_OneUlpPairOutputJudgedExactly) {
  RecordProperty("claim", "T3.3.4");
  std::vector<Point<2>> pair = {{0.5, 0.5}, {std::nextafter(0.5, 1.0), 0.5}};
  Params p;  // ρ = 4 keeps |M| small for the exact judge (the default ρ: |M| = 905, ~10 s)
  p.rho = 4;
  p.beta = 8;
  WellSpacedSet<2> ws(pair, p);
  const auto vs = ws.vertices();
  const auto M = exact_points<2>(vs);
  std::vector<ExactPoint<2>> inputs_only;
  std::vector<Point<2>> rounded;
  std::size_t fine = 0;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    if (!vs[i].is_steiner) inputs_only.push_back(M[i]);
    rounded.push_back(vs[i].x);
    fine += !vs[i].exact.is_double();
  }
  ASSERT_GT(fine, 0u);
  std::string why;
  EXPECT_TRUE(is_well_spaced<2>(M, ws.params().rho, &why)) << why;
  EXPECT_TRUE(is_size_conforming<2>(pair, M, ws.params().rho, &why)) << why;
  EXPECT_FALSE(is_well_spaced<2>(inputs_only, ws.params().rho));
  EXPECT_FALSE(is_well_spaced<2>(rounded, ws.params().rho) && is_size_conforming<2>(pair, rounded, ws.params().rho));
  std::printf("  |M| = %zu, %zu finer than doubles\n", M.size(), fine);
}
