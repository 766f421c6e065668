// §4.1.2 dynamic and kinetic maintenance of the deformable spanner (kmesh/spanner_repair.cpp):
// after every insertion, Remove and kinetic relocation the brute-force invariants S1–S4
// (kmesh/invariants.hpp, which finds nothing through spanner pointers) hold over the live vertices;
// random, grid, collinear, clustered (spread 2^30) and near-duplicate sets; a hand-derived case.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "exact/error.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/spanner.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

namespace {

Point2 pt(long long x, long long y) { return scaled({Integer(x), Integer(y)}); }

// Point families: 0 uniform, 1 grid, 2 collinear, 3 two clusters 2^30 apart, 4 near-duplicates.
Point2 draw(int family, std::mt19937_64& rng) {
  std::uniform_int_distribution<long long> d(0, 200), g(0, 9), b(0, 1);
  switch (family) {
    case 0: return pt(d(rng), d(rng));
    case 1: return pt(4 * g(rng), 4 * g(rng));
    case 2: return pt(d(rng), 0);
    case 3: return pt(d(rng) % 16 + (b(rng) << 30), d(rng) % 16);
    default: {
      // 1 + 2^−20 apart: exact dyadic offsets of the scaled coordinates
      Point2 p = pt(g(rng), g(rng));
      if (b(rng)) p[0] = p[0] + Dyadic(Integer(kScale), -20);
      return p;
    }
  }
}

std::string first(const CheckResult& r) { return r.ok() ? "" : r.violations[0]; }

}  // namespace

TEST(SpannerRepair, RemoveTheRootOfTwoPointsHandDerived) {
  // |pq| = 3: Λ = 2, root 0 at top 10, vertex 1 at top 1 (spanner_test). Removing the root makes 1
  // the root at the top rank, raised by 4 (every vertex within 2^(top+1) of the new root).
  Spanner S = Spanner::build({pt(0, 0), pt(3, 0)}, 8);
  S.remove(0);
  EXPECT_EQ(S.root(), 1);
  EXPECT_EQ(S.top_rank(), 14);
  EXPECT_EQ(S.top(1), 14);
  EXPECT_TRUE(S.all_neighbors(1).empty());
  EXPECT_TRUE(check_spanner(S).ok()) << first(check_spanner(S));
  // Re-inserting (0, 0) under it: covered first at rank 2 (3 ≤ 2^2), so top = 1, neighbours at
  // ranks −2 … 1 (20·2^r ≥ 3 iff r ≥ −2), parent 1.
  int id = S.insert_point(pt(0, 0), 0);
  EXPECT_EQ(id, 0);
  EXPECT_EQ(S.top(0), 1);
  EXPECT_EQ(S.parent(0), 1);
  EXPECT_EQ(S.min_rank(0), -2);
  EXPECT_EQ(S.neighbors(0, 1), std::vector<int>{1});
  EXPECT_TRUE(check_spanner(S).ok()) << first(check_spanner(S));
}

TEST(SpannerRepair, InsertAtAVertexIsRefused) {
  Spanner S = Spanner::build({pt(0, 0), pt(3, 0)}, 8);
  EXPECT_THROW(S.insert_point(pt(3, 0)), kmr::InputError);
  EXPECT_TRUE(check_spanner(S).ok());
}

TEST(SpannerRepair, RandomInsertionsAndRemovalsKeepTheInvariants) {
  for (int family = 0; family < 5; ++family) {
    std::mt19937_64 rng(100 + family);
    std::set<Point2> present;
    std::vector<Point2> init;
    while (init.size() < 12) {
      Point2 p = draw(family, rng);
      if (present.insert(p).second) init.push_back(p);
    }
    std::sort(init.begin(), init.end());
    Spanner S = Spanner::build(init, 8);
    for (int step = 0; step < 40; ++step) {
      std::uniform_int_distribution<int> coin(0, 2);
      std::string what;
      if (S.alive_count() > 2 && coin(rng) == 0) {
        std::vector<int> live;
        for (int x = 0; x < static_cast<int>(S.size()); ++x)
          if (S.alive(x)) live.push_back(x);
        // the root a quarter of the time, else a random live vertex
        int x = coin(rng) == 0 && step % 2 == 0 ? S.root() : live[std::uniform_int_distribution<std::size_t>(0, live.size() - 1)(rng)];
        present.erase(S.position(x));
        S.remove(x);
        what = "remove " + std::to_string(x);
      } else {
        Point2 p = draw(family, rng);
        if (!present.insert(p).second) continue;
        int id = S.insert_point(p);
        what = "insert " + std::to_string(id);
      }
      auto r = check_spanner(S);
      ASSERT_TRUE(r.ok()) << "family " << family << " step " << step << " (" << what << "): " << first(r);
    }
  }
}

TEST(SpannerRepair, RelocatingABatchKeepsTheInvariants) {
  // A kinetic batch: the vertices X move (the others stay, so their certificates still hold) and are
  // repaired together.
  for (int family = 0; family < 5; ++family) {
    std::mt19937_64 rng(200 + family);
    std::set<Point2> present;
    std::vector<Point2> init;
    while (init.size() < 14) {
      Point2 p = draw(family, rng);
      if (present.insert(p).second) init.push_back(p);
    }
    std::sort(init.begin(), init.end());
    Spanner S = Spanner::build(init, 8);
    for (int step = 0; step < 15; ++step) {
      std::uniform_int_distribution<int> pick(0, static_cast<int>(S.size()) - 1), many(1, step == 14 ? 14 : 3);
      std::vector<int> xs;
      std::vector<Point2> to;
      int k = many(rng);
      std::set<int> chosen;
      while (static_cast<int>(chosen.size()) < k) chosen.insert(pick(rng));
      for (int x : chosen) present.erase(S.position(x));
      for (int x : chosen) {
        Point2 p;
        do p = draw(family, rng);
        while (present.count(p));
        present.insert(p);
        xs.push_back(x);
        to.push_back(p);
      }
      S.relocate(xs, to);
      for (std::size_t i = 0; i < xs.size(); ++i) ASSERT_EQ(S.position(xs[i]), to[i]);
      auto r = check_spanner(S);
      ASSERT_TRUE(r.ok()) << "family " << family << " step " << step << ": " << first(r);
      ASSERT_EQ(S.alive_count(), 14u);
    }
  }
}
