// §3.1.2: the balanced 2^D-tree is the minimal tree with crowding and grading (checked by brute
// force over the input set, not by the tree's own rules), and dynamic insert/delete give the tree
// built from scratch (Lemmas 3.1.1–3.1.4 make the local update sufficient).
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

#include "wellspaced/generators.hpp"
#include "wellspaced/quadtree.hpp"

using namespace kmr::wellspaced;

namespace {

// Brute force: number of points in the closed-open cell c (same convention as the tree).
template <std::size_t D>
int brute_count(const std::vector<Point<D>>& pts, const Key<D>& c) {
  int n = 0;
  for (auto& p : pts) n += cell_contains<D>(c, p);
  return n;
}

template <std::size_t D>
void check_invariants(const Quadtree<D>& T, const std::vector<Point<D>>& pts) {
  // crowding: every leaf has ≤ 1 input, and a leaf with one input has no input in its neighbours
  for (auto& l : T.leaves()) {
    int n = brute_count<D>(pts, l);
    ASSERT_LE(n, 1) << l.str();
    if (n == 1) {
      for_block<D>(l, 1, [&](const Key<D>& m) {
        if (!(m == l)) {
          EXPECT_EQ(brute_count<D>(pts, m), 0) << "crowding " << l.str();
        }
      });
    }
  }
  // grading: every neighbour of an internal node exists
  for (auto& s : T.internal_nodes())
    for_block<D>(s, 1, [&](const Key<D>& m) { EXPECT_TRUE(T.exists(m)) << "grading " << s.str(); });
  // minimality: merging any internal node whose children are all leaves breaks crowding or grading
  for (auto& s : T.internal_nodes()) {
    bool all_leaf_children = true;
    for (unsigned m = 0; m < (1u << D); ++m) all_leaf_children &= !T.internal(s.child(m));
    if (!all_leaf_children) continue;
    int n = brute_count<D>(pts, s);
    bool crowded = n >= 2;
    if (n == 1)
      for_block<D>(s, 1, [&](const Key<D>& m) {
        if (!(m == s) && brute_count<D>(pts, m) > 0) crowded = true;
      });
    bool graded_needed = false;  // some internal node at level+1 has a neighbour among s's children
    for (auto& t : T.internal_nodes())
      if (t.level == s.level + 1)
        for_block<D>(t, 1, [&](const Key<D>& m) {
          if (m.parent() == s) graded_needed = true;
        });
    EXPECT_TRUE(crowded || graded_needed) << "not minimal: " << s.str();
  }
}

template <std::size_t D>
void run_dynamic(gen::Kind kind, std::size_t n, std::uint64_t seed) {
  auto pts = gen::points<D>(kind, n, seed);
  std::vector<Point<D>> cur(pts.begin(), pts.begin() + pts.size() / 2);
  Quadtree<D> T;
  T.build(cur);
  std::map<Point<D>, bool> in;
  for (auto& p : cur) in[p] = true;
  auto leaf_input = [&](const Key<D>& l) -> const Point<D>* {
    for (auto& p : cur)
      if (cell_contains<D>(l, p)) return &p;
    return nullptr;
  };
  std::mt19937_64 rng(seed);
  for (std::size_t step = 0; step < pts.size(); ++step) {
    const Point<D>& p = pts[rng() % pts.size()];
    bool present = std::find(cur.begin(), cur.end(), p) != cur.end();
    if (present && cur.size() <= 2) continue;
    T.update(p, present ? -1 : +1, leaf_input);
    if (present) cur.erase(std::find(cur.begin(), cur.end(), p));
    else cur.push_back(p);
    Quadtree<D> S;
    S.build(cur);
    ASSERT_EQ(T.internal_nodes(), S.internal_nodes()) << gen::name(kind) << " step " << step;
  }
  check_invariants<D>(T, cur);
}

}  // namespace

TEST(WellspacedQuadtree, L3_1_CrowdingGradingMinimal2D) {
  RecordProperty("claim", "L3.1.5");
  for (auto k : gen::kAllKinds) {
    Quadtree<2> T;
    auto pts = gen::points<2>(k, 40, 7);
    T.build(pts);
    check_invariants<2>(T, pts);
  }
}
TEST(WellspacedQuadtree, L3_1_CrowdingGradingMinimal3D4D) {
  for (auto k : {gen::Kind::uniform, gen::Kind::grid, gen::Kind::boundary, gen::Kind::close_pair}) {
    Quadtree<3> T3;
    auto p3 = gen::points<3>(k, 20, 3);
    T3.build(p3);
    check_invariants<3>(T3, p3);
    Quadtree<4> T4;
    auto p4 = gen::points<4>(k, 8, 4);
    T4.build(p4);
    check_invariants<4>(T4, p4);
  }
}
TEST(WellspacedQuadtree, L3_1_3_DynamicEqualsFromScratch) {
  RecordProperty("claim", "L3.1.3");
  for (auto k : gen::kAllKinds) run_dynamic<2>(k, 24, 11);
  for (auto k : gen::kAllKinds) run_dynamic<3>(k, 12, 12);
  for (auto k : {gen::Kind::uniform, gen::Kind::close_pair, gen::Kind::boundary}) run_dynamic<4>(k, 6, 13);
}
TEST(WellspacedQuadtree, ObsoleteSquaresAreNearTheUpdatedPoint) {
  RecordProperty("claim", "L3.1.3");
  // Lemmas 3.1.3/3.1.4: every obsolete square s has |s v̂| ≤ 2√D |s| (neighbour's neighbour).
  auto pts = gen::points<2>(gen::Kind::uniform, 60, 5);
  std::vector<Point<2>> cur(pts.begin(), pts.begin() + 30);
  Quadtree<2> T;
  T.build(cur);
  auto leaf_input = [&](const Key<2>& l) -> const Point<2>* {
    for (auto& p : cur)
      if (cell_contains<2>(l, p)) return &p;
    return nullptr;
  };
  for (std::size_t i = 30; i < 60; ++i) {
    auto ch = T.update(pts[i], +1, leaf_input);
    cur.push_back(pts[i]);
    for (auto& s : ch.obsolete) {
      double h = s.side(), d2 = 0;
      for (int j = 0; j < 2; ++j) {
        double lo = s.k[j] * h, hi = lo + h, x = pts[i][j] < lo ? lo - pts[i][j] : (pts[i][j] > hi ? pts[i][j] - hi : 0);
        d2 += x * x;
      }
      EXPECT_LE(std::sqrt(d2), 2 * std::sqrt(2.0) * h + 1e-12);
    }
  }
}
TEST(WellspacedQuadtree, L3_1_4_DeletedSquaresAreNearTheDeletedPoint) {
  RecordProperty("claim", "L3.1.4");
  // Lemma 3.1.4 (O(|s|), constant not given): a removed leaf s is a child of a node (size 2|s|) that
  // was split only because of v̂, hence within the neighbour's-neighbour bound 2√D·(2|s|) of v̂.
  auto pts = gen::points<3>(gen::Kind::close_pair, 30, 6);
  std::vector<Point<3>> cur(pts.begin(), pts.end());
  Quadtree<3> T;
  T.build(cur);
  std::size_t removed = 0;
  while (cur.size() > 2) {
    Point<3> p = cur.back();
    auto leaf_input = [&](const Key<3>& l) -> const Point<3>* {
      for (auto& q : cur)
        if (cell_contains<3>(l, q)) return &q;
      return nullptr;
    };
    auto ch = T.update(p, -1, leaf_input);
    cur.pop_back();
    for (auto& s : ch.obsolete) {
      double h = s.side(), d2 = 0;
      for (int j = 0; j < 3; ++j) {
        double lo = s.k[j] * h, hi = lo + h, x = p[j] < lo ? lo - p[j] : (p[j] > hi ? p[j] - hi : 0);
        d2 += x * x;
      }
      EXPECT_LE(std::sqrt(d2), 4 * std::sqrt(3.0) * h + 1e-12);
      ++removed;
    }
  }
  EXPECT_GT(removed, 0u);
}
TEST(WellspacedQuadtree, RefusesPointsBeyondDepthLimit) {
  Quadtree<2> T;
  std::vector<Point<2>> pts{{0.5, 0.5}, {0.5 + std::ldexp(1.0, -60), 0.5}};
  EXPECT_THROW(T.build(pts), kmr::InputError);
}

// Issue 11 §5: build and insert refuse at the same depth. Two points 2^-55 apart near 1/8 (the
// double spacing there) are crowded up to level 55 = kMaxLevel − 1, so their leaves are at level
// kMaxLevel exactly: accepted by both paths, with equal trees. Two points 2^-56 apart near 1/16
// are crowded at level kMaxLevel, so leaves would be at kMaxLevel + 1: refused by both paths
// (insert leaves the tree unchanged).
template <std::size_t D>
void depth_boundary_case(double a, double step, bool accepted) {
  Point<D> p{}, q{};
  p.fill(0.75);
  q.fill(0.75);
  p[0] = a;
  q[0] = a + step;
  std::vector<Point<D>> base{p, Point<D>{}};  // the origin keeps two inputs before the insertion
  base[1].fill(0.0);
  Quadtree<D> built;
  std::vector<Point<D>> all{p, q, base[1]};
  auto leaf_input = [&](const Key<D>& l) -> const Point<D>* {
    for (auto& x : base)
      if (cell_contains<D>(l, x)) return &x;
    return nullptr;
  };
  Quadtree<D> ins;
  ins.build(base);
  const auto before = ins.internal_nodes();
  if (accepted) {
    built.build(all);
    ins.update(q, +1, leaf_input);
    EXPECT_EQ(ins.internal_nodes(), built.internal_nodes()) << D << "D";
    int deepest = 0;
    for (const auto& l : built.leaves()) deepest = std::max(deepest, l.level);
    EXPECT_EQ(deepest, kMaxLevel) << D << "D: the pair should need exactly kMaxLevel levels";
  } else {
    EXPECT_THROW(built.build(all), kmr::InputError) << D << "D build";
    EXPECT_THROW(ins.update(q, +1, leaf_input), kmr::InputError) << D << "D insert";
    EXPECT_EQ(ins.internal_nodes(), before) << D << "D: a refused insertion changed the tree";
  }
}
TEST(WellspacedQuadtree, DepthLimitSameForBuildAndInsert) {
  depth_boundary_case<2>(0.125, std::ldexp(1.0, -55), true);
  depth_boundary_case<2>(0.0625, std::ldexp(1.0, -56), false);
  depth_boundary_case<3>(0.125, std::ldexp(1.0, -55), true);
  depth_boundary_case<3>(0.0625, std::ldexp(1.0, -56), false);
}
