// Lemma 3.4.2 (isomorphism) as a state machine: random sequences of input insertions and deletions
// applied with PropagateWS; after every command the output equals, and the computation graph is
// identical in canonical form to (i.e. isomorphic to), a from-scratch StableWS on the current input;
// the 2^D-tree equals the from-scratch tree. Inputs come from every generator kind (RC_CLASSIFY).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "wellspaced/generators.hpp"
#include "wellspaced/well_spaced_set.hpp"

using namespace kmr::wellspaced;

namespace {

template <std::size_t D>
void compare_with_scratch(const std::vector<Point<D>>& cur, const WellSpacedSet<D>& ws, int step, const Params& params) {
  // the indexes the canonical graph does not show
  const std::string bad = ws.check_internal_indexes();
  if (!bad.empty()) RC_FAIL("after command " + std::to_string(step) + ": " + bad);
  WellSpacedSet<D> fresh(cur, params);
  auto a = ws.vertices(), b = fresh.vertices();
  RC_ASSERT(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    RC_ASSERT(a[i].exact == b[i].exact);
    RC_ASSERT(a[i].is_steiner == b[i].is_steiner);
  }
  RC_ASSERT(ws.tree_internal_nodes() == fresh.tree_internal_nodes());
  RC_ASSERT(ws.canonical_graph() == fresh.canonical_graph());
}

// A pool of `pool_size` points of one generator kind, `start` of them built from scratch, then
// exactly `length` commands (insert a pool point not present / erase a present one, ≥ 2 kept),
// each followed by the comparison above.
template <std::size_t D>
void run_commands(gen::Kind kind, std::uint64_t seed, std::size_t pool_size, std::size_t start, int length,
                  const Params& params = Params{});

template <std::size_t D>
void property(std::size_t pool_size, std::size_t start, int length) {
  std::vector<gen::Kind> kinds(std::begin(gen::kAllKinds), std::end(gen::kAllKinds));
  kinds.insert(kinds.end(), std::begin(gen::kDegenerateKinds), std::end(gen::kDegenerateKinds));
  // clustered inputs, 2^-30 pairs and the diagonal line make thousands of Steiner vertices beyond
  // 2D (exact arithmetic makes them slow); 4D keeps the cheap kinds only (ctest time budget)
  auto heavy = [](gen::Kind k) {
    if (k == gen::Kind::clustered || k == gen::Kind::close_pair || k == gen::Kind::line ||
        k == gen::Kind::collinear || k == gen::Kind::axis_line || k == gen::Kind::cospherical)
      return D > 2;
    if (k == gen::Kind::plane || k == gen::Kind::sphere || k == gen::Kind::cocircular) return D > 3;
    return false;
  };
  kinds.erase(std::remove_if(kinds.begin(), kinds.end(), heavy), kinds.end());
  const auto kind = *rc::gen::elementOf(kinds);
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  RC_CLASSIFY(true, gen::name(kind));
  run_commands<D>(kind, seed, pool_size, start, length);
}

// One case: the pool of `kind` from generator seed `seed`, then the commands (drawn by rapidcheck).
template <std::size_t D>
void run_commands(gen::Kind kind, std::uint64_t seed, std::size_t pool_size, std::size_t start, int length,
                  const Params& params) {
  auto pool = gen::points<D>(kind, pool_size, seed);
  RC_PRE(pool.size() >= 3);
  std::vector<Point<D>> cur(pool.begin(), pool.begin() + std::min(start, pool.size() - 1));
  WellSpacedSet<D> ws(cur, params);
  for (int step = 0; step < length; ++step) {
    const auto& p = pool[*rc::gen::inRange<std::size_t>(0, pool.size())];
    auto at = std::find(cur.begin(), cur.end(), p);
    if (at != cur.end() && cur.size() > 2) {
      ws.erase(p);
      cur.erase(at);
    } else if (at == cur.end()) {
      ws.insert(p);
      cur.push_back(p);
    } else {
      continue;  // erasing would leave < 2 points: draw again (does not count)
    }
    compare_with_scratch<D>(cur, ws, step, params);
  }
}

}  // namespace

// Issue 11: 2D pool ≥ 60 and ≥ 30 commands, 3D ≥ 20 / ≥ 15, 4D ≥ 8 / ≥ 6 (runs per property set
// in CMakeLists.txt; KMR_WS_PROP_SCALE=k multiplies pools and commands for an opt-in campaign).
static int scale() {
  const char* s = std::getenv("KMR_WS_PROP_SCALE");
  return s ? std::max(1, std::atoi(s)) : 1;
}
RC_GTEST_PROP(WellspacedProp, L3_4_2_Isomorphism2D, ()) { property<2>(60 * scale(), 30 * scale(), 30 * scale()); }
RC_GTEST_PROP(WellspacedProp, L3_4_2_Isomorphism3D, ()) { property<3>(20 * scale(), 10 * scale(), 15 * scale()); }
RC_GTEST_PROP(WellspacedProp, L3_4_2_Isomorphism4D, ()) { property<4>(8 * scale(), 5 * scale(), 6 * scale()); }
// Issue 11 §5: the clustered family in 3D (3 clusters of radius 2^-12: spread ≈ 2^11), excluded
// from the properties above for D > 2 (a 3D clustered input of 20 points has ≈ 3 200 Steiner
// vertices at ρ = 1.5; 2 cases of pool 8 / 8 commands took 56 s CPU). Here at ρ = 2, β = 4 (a few
// hundred Steiner vertices) with a pool of 6 and 5 commands. The generator seed is printed
// (rapidcheck prints its own seed and the commands on failure): replay with RC_PARAMS="seed=N", or
// rebuild the pool with gen::points<3>(clustered, 6, seed).
RC_GTEST_PROP(WellspacedProp, L3_4_2_Isomorphism3DClustered, ()) {
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  std::printf("  3D clustered pool of %d, generator seed %llu, rho 2, beta 4\n", 6 * scale(), (unsigned long long)seed);
  run_commands<3>(gen::Kind::clustered, seed, 6 * scale(), 4 * scale(), 5 * scale(), Params{2.0, 4.0});
}
