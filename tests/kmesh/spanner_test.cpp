// §4.1.2 deformable spanner: a hand-derived two-point hierarchy and the brute-force invariants
// (separation, covering, parents within 2^(ℓ+1), neighbours exactly within c·2^ℓ) on random sets.
#include <gtest/gtest.h>

#include <random>

#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/spanner.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

TEST(Spanner, TwoPointsHandDerived) {
  // |pq| = 3 (input units): Λ = 2; q is a 1-center (more than 2^1 from the root);
  // 20·2^r ≥ 3 iff r ≥ −2, so they are neighbours at ranks −2 … 1 only.
  std::vector<Point2> pts{scaled({Integer(0), Integer(0)}), scaled({Integer(3), Integer(0)})};
  Spanner S = Spanner::build(pts, 8);
  EXPECT_EQ(S.lambda(), 2);
  EXPECT_EQ(S.top(0), 10);
  EXPECT_EQ(S.top(1), 1);
  EXPECT_EQ(S.parent(1), 0);
  EXPECT_EQ(S.min_rank(1), -2);
  EXPECT_EQ(S.min_rank(0), -2);
  EXPECT_TRUE(S.neighbors(1, -3).empty());
  EXPECT_EQ(S.neighbors(1, 1), std::vector<int>{0});
  EXPECT_TRUE(check_spanner(S).ok());
}

TEST(Spanner, InvariantsOnRandomAndDegenerateSets) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<InputPoint> in;
    std::uniform_int_distribution<int> d(0, trial < 3 ? 100 : 1 << 20);
    for (int i = 0; i < 60; ++i) in.push_back({Integer(d(rng)), Integer(trial == 5 ? 0 : d(rng))});
    std::sort(in.begin(), in.end());
    in.erase(std::unique(in.begin(), in.end()), in.end());
    std::vector<Point2> pts;
    for (auto& p : in) pts.push_back(scaled(p));
    Spanner S = Spanner::build(pts, 8);
    auto r = check_spanner(S);
    EXPECT_TRUE(r.ok()) << trial << ": " << (r.ok() ? "" : r.violations[0]);
  }
}
