// The brute-force judges of kmesh/invariants.hpp must be able to fail: each check, given a mesh
// broken on purpose in the way its invariant forbids, reports that violation (and names the vertex,
// satellite or rank involved), while the unbroken mesh passes all of them. The breakages are
// hand-made edits of a constructed mesh (a flipped conversion, a raised rank, a reversed or doubled
// triangle, a moved vertex, a wrong parent), so each expectation comes from the edit, not from the
// code being judged.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/satellites.hpp"

using namespace kmr::kmesh;
using kmr::exact::Dyadic;
using kmr::exact::Integer;

namespace {

// Eight input points with spread ≈ 10^3 (no four cocircular among the corners' neighbours matters
// here: only the edits decide the violations).
Mesh eight() {
  std::vector<InputPoint> in;
  for (auto [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {1000, 0}, {0, 1000}, {1000, 1000}, {500, 480}, {200, 700}, {810, 300}, {300, 90}})
    in.push_back({Integer(x), Integer(y)});
  return construct(in);
}

bool starts(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool all_start(const CheckResult& r, const std::string& prefix) {
  return !r.violations.empty() &&
         std::all_of(r.violations.begin(), r.violations.end(), [&](const std::string& v) { return starts(v, prefix); });
}
std::string first(const CheckResult& r) { return r.ok() ? "(none)" : r.violations.front(); }

class Invariants : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { mesh_ = new Mesh(eight()); }
  static void TearDownTestSuite() { delete mesh_; }
  static Mesh* mesh_;
  const Mesh& m = *mesh_;
};
Mesh* Invariants::mesh_ = nullptr;

TEST_F(Invariants, TheUnbrokenMeshPassesEveryCheck) {
  ASSERT_GT(m.size(), m.n());  // Steiner vertices were added
  ASSERT_FALSE(m.considered.empty());
  for (auto& r : check_all(m)) EXPECT_TRUE(r.ok()) << r.claim << ": " << first(r);
  EXPECT_TRUE(check_active_satellites(m).ok()) << first(check_active_satellites(m));
}

// L4.2.4: converted iff the ball was empty. Flipping any one satellite's decision is exactly one
// violation, naming that satellite and the way it is wrong.
TEST_F(Invariants, L4_2_4_EveryFlippedConversionIsReportedAsThatSatellite) {
  RecordProperty("claim", "L4.2.4");
  for (std::size_t i = 0; i < m.considered.size(); i += 7) {
    Mesh b = m;
    Considered& c = b.considered[i];
    c.converted = !c.converted;
    auto r = check_ball_empty(b);
    ASSERT_EQ(r.violations.size(), 1u) << i;
    std::string want = "satellite (nucleus " + std::to_string(c.nucleus) + ", ray " + std::to_string(c.ray) + ", rank " +
                       std::to_string(c.rank) + "): ball " + (c.converted ? "not empty but converted" : "empty but not converted");
    EXPECT_EQ(r.violations[0], want);
  }
}

// L4.2.5: a maximal independent set. Un-converting a converted satellite leaves it unblocked (its
// neighbours are unconverted): not maximal. Converting an unconverted one puts it outside the graph
// or next to a converted neighbour (that is why it was not converted).
TEST_F(Invariants, L4_2_5_FlippedConversionsBreakIndependenceOrMaximality) {
  RecordProperty("claim", "L4.2.5");
  int unconverted = 0, converted = 0;
  for (std::size_t i = 0; i < m.considered.size(); ++i) {
    const Considered& c = m.considered[i];
    if (c.converted ? converted >= 12 : unconverted >= 12) continue;
    Mesh b = m;
    b.considered[i].converted = !c.converted;
    auto r = check_independent_set(b);
    std::string rank = "rank " + std::to_string(c.rank) + ": ";
    if (c.converted) {
      ++converted;
      EXPECT_TRUE(all_start(r, rank + "not maximal at ")) << i << ": " << first(r);
    } else {
      ++unconverted;
      EXPECT_TRUE(all_start(r, rank + "converted a satellite outside the proximity graph") ||
                  all_start(r, rank + "two adjacent satellites converted"))
          << i << ": " << first(r);
    }
  }
  EXPECT_GT(converted, 0);
  EXPECT_GT(unconverted, 0);
}

// L4.2.6 and L4.2.10 read the rank a vertex was activated or converted at: raising it by 10 puts
// its nearest neighbour inside B(v, 2^(rank−2)) and its minimum rank below rank − 6.
TEST_F(Invariants, L4_2_6_And_L4_2_10_RaisedRanksAreReported) {
  int s = -1;
  for (int v = 0; v < static_cast<int>(m.size()) && s < 0; ++v)
    if (m.info[v].steiner) s = v;
  ASSERT_GE(s, 0);
  Mesh b = m;
  b.info[s].rank += 10;
  auto balls = check_empty_balls(b);
  ASSERT_EQ(balls.violations.size(), 1u) << first(balls);
  EXPECT_EQ(balls.violations[0], "vertex " + std::to_string(s) + " of rank " + std::to_string(b.info[s].rank) + " has a vertex within 2^(rank-2)");
  auto ranks = check_min_ranks(b);
  ASSERT_EQ(ranks.violations.size(), 1u) << first(ranks);
  EXPECT_TRUE(starts(ranks.violations[0], "satellite " + std::to_string(s) + " converted at rank " + std::to_string(b.info[s].rank) + " has minimum rank "))
      << ranks.violations[0];
  EXPECT_TRUE(check_min_ranks(m).ok());
}

// L4.2.9: with a rank far above every spanner rank, no neighbour pair exists at ranks ℓ−6 … ℓ−3:
// every Delaunay edge at that vertex is reported.
TEST_F(Invariants, L4_2_9_AnEdgeAtAVertexOfImpossibleRankIsReported) {
  RecordProperty("claim", "L4.2.9");
  const int v = m.triangles.at(0)[0];
  Mesh b = m;
  b.info[v].rank += 1000;
  auto r = check_voronoi_candidates(b);
  int edges_at_v = 0;
  std::set<int> nbrs;
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      if (t[i] == v) nbrs.insert(t[(i + 1) % 3]), nbrs.insert(t[(i + 2) % 3]);
  edges_at_v = static_cast<int>(nbrs.size());
  ASSERT_GT(edges_at_v, 0);
  EXPECT_EQ(static_cast<int>(r.violations.size()), std::min(edges_at_v, 20));
  for (auto& s : r.violations) {
    EXPECT_TRUE(starts(s, "Delaunay edge " + std::to_string(v) + "-")) << s;
    EXPECT_NE(s.find("is not a neighbour pair at ranks l-6..l-3"), std::string::npos) << s;
  }
}

// The Delaunay judge: a clockwise triangle, a triangle listed twice, a missing triangle (the
// boundary is no longer the hull), and triangles on fewer than 3 vertices.
TEST_F(Invariants, DelaunayJudgeReportsOrientationDuplicatesHolesAndTooFewVertices) {
  {
    Mesh b = m;
    std::swap(b.triangles[0][1], b.triangles[0][2]);
    auto r = check_delaunay(b);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.violations[0], "triangle not counter-clockwise");
  }
  {
    Mesh b = m;
    b.triangles.push_back(b.triangles[0]);
    auto r = check_delaunay(b);
    EXPECT_EQ(std::count(r.violations.begin(), r.violations.end(), "a directed edge is used twice"), 3) << first(r);
    EXPECT_EQ(std::count(r.violations.begin(), r.violations.end(), "the triangles' area differs from the hull's"), 1) << first(r);
  }
  {
    // Remove an interior triangle (no edge on the hull): a hole, so the boundary has 3 more edges.
    Mesh b = m;
    std::set<std::pair<int, int>> directed;
    for (auto& t : m.triangles)
      for (int i = 0; i < 3; ++i) directed.insert({t[i], t[(i + 1) % 3]});
    auto interior = std::find_if(b.triangles.begin(), b.triangles.end(), [&](const std::array<int, 3>& t) {
      for (int i = 0; i < 3; ++i)
        if (!directed.count({t[(i + 1) % 3], t[i]})) return false;
      return true;
    });
    ASSERT_NE(interior, b.triangles.end());
    b.triangles.erase(interior);
    auto r = check_delaunay(b);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(starts(r.violations[0], "the triangles' boundary is not the convex hull (")) << r.violations[0];
    EXPECT_EQ(r.violations.back(), "the triangles' area differs from the hull's");
  }
  {
    std::vector<InputPoint> two{{Integer(0), Integer(0)}, {Integer(5), Integer(1)}};
    Mesh b = construct(two);
    EXPECT_TRUE(check_delaunay(b).ok());
    b.triangles.push_back({0, 1, 0});
    auto r = check_delaunay(b);
    if (b.size() < 3) {
      ASSERT_EQ(r.violations.size(), 1u);
      EXPECT_EQ(r.violations[0], "triangles on fewer than 3 vertices");
    } else {
      EXPECT_FALSE(r.ok());  // Steiner vertices made it a real mesh: the degenerate triangle is not ccw
    }
  }
}

// 9/2-well-spacedness: a triangle of three far-apart corners has a circumradius of ~707 at a
// vertex whose nearest neighbour is far closer than 707·2/9.
TEST_F(Invariants, WellSpacedJudgeReportsAHugeCircumcircle) {
  RecordProperty("claim", "L4.2.3");
  Mesh b = m;
  // Input vertices are sorted (x, then y): (0,0) is 0, (0,1000) is 1, (1000,0) is 6.
  ASSERT_EQ(b.input[0].x, 0);
  ASSERT_EQ(b.input[1].y, 1000);
  ASSERT_EQ(b.input[6].x, 1000);
  ASSERT_EQ(b.input[6].y, 0);
  b.triangles.push_back({0, 6, 1});  // ccw: (0,0), (1000,0), (0,1000)
  auto r = check_well_spaced(b);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.violations[0], "vertex 0 is not 9/2-well-spaced");
  EXPECT_GT(r.measured, 4.5);
  EXPECT_LE(check_well_spaced(m).measured, 4.5);
}

// U1: after a removed record, the active vertex at that rank has 11 satellites considered.
TEST_F(Invariants, U1_AMissingSatelliteRecordIsReported) {
  Mesh b = m;
  Considered gone = b.considered.back();
  b.considered.pop_back();
  auto r = check_active_satellites(b);
  ASSERT_EQ(r.violations.size(), 2u) << first(r);
  EXPECT_EQ(r.violations[0], "vertex " + std::to_string(gone.nucleus) + " active at rank " + std::to_string(gone.rank) +
                                 " has 11 satellites considered");
  EXPECT_EQ(r.violations[1], std::to_string(m.considered.size() - 1) + " satellites considered, " +
                                 std::to_string(m.considered.size()) + " belong to active vertices");
}

// The rigid-boundary judge (no certificate watches the boundary's convexity, so the boundary must
// be the 12 top-rank satellites of one nucleus): the unbroken mesh's boundary, found here from the
// triangles' unpaired edges, is 12 Steiner vertices of one nucleus; relabelling one of them as another
// nucleus's, as an input vertex or as a lower rank, or dropping its triangles, is reported.
TEST_F(Invariants, L4_3_1_RigidBoundaryJudgeReportsAForeignOrMissingBoundaryVertex) {
  RecordProperty("claim", "L4.3.1");
  std::set<std::pair<int, int>> edges;
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) edges.insert({t[i], t[(i + 1) % 3]});
  std::set<int> boundary;
  for (auto& [a, b] : edges)
    if (!edges.count({b, a})) boundary.insert(a);
  ASSERT_EQ(boundary.size(), 12u);
  const int v = *boundary.begin();
  const int nucleus = m.info[v].nucleus;
  for (int w : boundary) ASSERT_TRUE(m.info[w].steiner && m.info[w].nucleus == nucleus && m.info[w].rank == m.info[v].rank);
  EXPECT_TRUE(check_rigid_boundary(m).ok()) << first(check_rigid_boundary(m));
  const std::string name = "boundary vertex " + std::to_string(v) + " ";
  Mesh other = m;
  other.info[v].nucleus = nucleus == 0 ? 1 : 0;
  EXPECT_TRUE(all_start(check_rigid_boundary(other), name + "(rank " + std::to_string(m.info[v].rank) + ", nucleus ")) << first(check_rigid_boundary(other));
  Mesh input = m;
  input.info[v].steiner = false;
  EXPECT_TRUE(all_start(check_rigid_boundary(input), name + "(an input vertex)")) << first(check_rigid_boundary(input));
  Mesh lower = m;
  lower.info[v].rank -= 1;
  EXPECT_TRUE(all_start(check_rigid_boundary(lower), name + "(rank " + std::to_string(m.info[v].rank - 1))) << first(check_rigid_boundary(lower));
  Mesh dropped = m;
  std::erase_if(dropped.triangles, [&](const std::array<int, 3>& t) { return t[0] == v || t[1] == v || t[2] == v; });
  auto r = check_rigid_boundary(dropped);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(starts(r.violations[0], "the boundary has ")) << r.violations[0];
}

// The spanner judge: two vertices moved onto one place coincide (S1); a parent that is no
// (top+1)-center within reach, and a vertex no center covers, are reported (S2).
TEST_F(Invariants, SpannerJudgeReportsCoincidingVerticesAndAWrongParent) {
  {
    Mesh b = m;
    std::vector<Point2> p;
    for (std::size_t i = 0; i < b.size(); ++i) p.push_back(b.spanner.position(static_cast<int>(i)));
    p[1] = p[0];
      b.spanner.move_to(p);
    auto r = check_spanner(b.spanner);
    EXPECT_NE(std::find(r.violations.begin(), r.violations.end(), "S1: vertices 0 and 1 coincide"), r.violations.end()) << first(r);
  }
  {
    // A non-root vertex moved far out (move_to keeps every pointer): its parent and every center of
    // the rank above are out of reach. A spanner of two input points: the non-root one is a leaf
    // with entries at a few ranks only, so the S3 reports the move also causes stay under the 20 kept.
    Spanner S = Spanner::build({scaled({Integer(0), Integer(0)}), scaled({Integer(5), Integer(2)})}, 0);
    ASSERT_TRUE(check_spanner(S).ok()) << first(check_spanner(S));
    const int x = S.root() == 0 ? 1 : 0;
    std::size_t entries = 0;
    for (auto& [l, list] : S.all_neighbors(x)) entries += list.size();
    ASSERT_LE(entries, 8u);
    std::vector<Point2> p{S.position(0), S.position(1)};
    p[x][0] = p[x][0] + Dyadic(Integer(kScale) << 30);  // 2^30 input units away: past the top rank
    S.move_to(p);
    auto r = check_spanner(S);
    const std::string t = std::to_string(S.top(x) + 1);
    for (std::string want : {"S2 covering: no " + t + "-center within 2^" + t + " of " + std::to_string(x),
                             "S2 parent of " + std::to_string(x) + " is not a " + t + "-center within 2^" + t})
      EXPECT_NE(std::find(r.violations.begin(), r.violations.end(), want), r.violations.end()) << want << "; first: " << first(r);
  }
}

}  // namespace
