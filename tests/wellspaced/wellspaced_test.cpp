// StableWS (Fig. 3.4) and its updates (Fig. 3.8), judged by the library's exact brute force
// (Voronoi cells of all vertices clipped to the domain, no quadtree, no scan) and by from-scratch runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>

#include "exact/error.hpp"
#include "wellspaced/generators.hpp"
#include "wellspaced/well_spaced_set.hpp"

using namespace kmr::wellspaced;

namespace {

template <std::size_t D>
std::vector<Point<D>> coords(const std::vector<Vertex<D>>& vs) {
  std::vector<Point<D>> out;
  for (auto& v : vs) out.push_back(v.x);
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
  // determinism: the reversed input gives the same output and graph
  std::vector<Point<D>> rev(input.rbegin(), input.rend());
  WellSpacedSet<D> ws2(rev);
  EXPECT_EQ(ws.canonical_graph(), ws2.canonical_graph());
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
    std::vector<Point<D>> brute;
    for (auto u : brute_clipped_voronoi_neighbors<D>(M, v, ws.params().beta)) brute.push_back(M[u]);
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
void tiers_case(gen::Kind k, std::size_t n, std::uint64_t seed, bool expect_fallbacks) {
  auto in = gen::points<D>(k, n, seed);
  Params exact;
  exact.exact_only = true;
  WellSpacedSet<D> fast(in), slow(in, exact);
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
const RhoBeta kSweep4Small[] = {{2, 3}, {2, 4}};  // not cospherical: |M| ≈ 110, 20 s each

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
  degenerate_sweep<4>(5, {std::begin(kSweep4Small), std::end(kSweep4Small)},
                      {gen::Kind::grid_fine, gen::Kind::collinear, gen::Kind::axis_line, gen::Kind::cocircular});
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
