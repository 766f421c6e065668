// §4.3, Fig. 4.5: the dynamic update (kmesh/update.hpp). After every insertion and deletion the
// brute-force checks of kmesh/invariants.hpp hold on the updated mesh (spanner S1–S4, U1 active
// satellites, L4.3.2 as the maximal-independent-set check per rank, L4.2.6, L4.2.9, L4.2.10,
// Delaunay, 9/2-well-spacedness); the checks share no code with the update. Stability is measured
// against a from-scratch construction of the same input (the fraction of Steiner vertices shared).
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

#include "exact/error.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/update.hpp"
#include "mesh_checks.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;
using kmr::kmesh::test::failures;
using kmr::kmesh::test::steiner_positions;

namespace {

InputPoint ip(long long x, long long y) { return {Integer(x), Integer(y)}; }

// Families: 0 uniform, 1 grid, 2 collinear, 3 cocircular (radius 25), 4 two clusters 2^30 apart.
InputPoint draw(int family, std::mt19937_64& rng) {
  std::uniform_int_distribution<long long> d(0, 64), g(0, 4), b(0, 1);
  static const long long circle[][2] = {{25, 0},  {24, 7},   {20, 15},  {15, 20},  {7, 24},  {0, 25},
                                        {-7, 24}, {-15, 20}, {-20, 15}, {-24, 7},  {-25, 0}, {-24, -7},
                                        {-20, -15}, {-15, -20}, {-7, -24}, {0, -25}};
  switch (family) {
    case 0: return ip(d(rng), d(rng));
    case 1: return ip(8 * g(rng), 8 * g(rng));
    case 2: return ip(d(rng), 0);
    case 3: {
      auto& c = circle[std::uniform_int_distribution<int>(0, 15)(rng)];
      return ip(c[0], c[1]);
    }
    default: return ip(d(rng) % 8 + (b(rng) << 30), d(rng) % 8);
  }
}

// Runs `steps` random updates from `n0` points, checking after each; returns the mean stability.
double run(int family, int n0, int steps, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<InputPoint> pts;
  std::set<InputPoint> have;
  while (static_cast<int>(pts.size()) < n0) {
    InputPoint p = draw(family, rng);
    if (have.insert(p).second) pts.push_back(p);
  }
  Updater U(pts);
  double stab = 0;
  int counted = 0;
  for (int step = 0; step < steps; ++step) {
    std::string what;
    if (pts.size() > 2 && step % 2 == 1) {
      std::size_t i = std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng);
      U.erase(pts[i]);
      have.erase(pts[i]);
      what = "delete (" + pts[i].x.str() + ", " + pts[i].y.str() + ")";
      pts.erase(pts.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      InputPoint p = draw(family, rng);
      if (!have.insert(p).second) continue;
      U.insert(p);
      pts.push_back(p);
      what = "insert (" + p.x.str() + ", " + p.y.str() + ")";
    }
    Mesh m = U.mesh();
    std::string f = failures(check_all_updated(m));
    EXPECT_EQ(f, "") << "family " << family << " step " << step << " " << what;
    if (!f.empty()) return -1;
    stab += kmr::kmesh::test::shared_steiner_fraction(m, construct(pts));
    ++counted;
  }
  return counted ? stab / counted : 1;
}

}  // namespace

TEST(Update, ConstructionSatisfiesTheUpdateInvariants) {
  // The order-free checks accept the construction's own result (U1, L4.2.5 as U2).
  Mesh m = construct({ip(0, 0), ip(5, 1), ip(2, 7), ip(9, 9)});
  EXPECT_EQ(failures(check_all_updated(m)), "");
  Updater U({ip(0, 0), ip(5, 1), ip(2, 7), ip(9, 9)});
  Mesh u = U.mesh();
  EXPECT_EQ(steiner_positions(u), steiner_positions(m));
  EXPECT_EQ(u.triangles, m.triangles);
}

TEST(Update, BadUpdatesAreRefusedAndChangeNothing) {
  // The mesh as a user sees it: vertex positions and kinds, triangles (ids into the vertices).
  auto seen = [](const Mesh& m) {
    std::vector<std::tuple<Dyadic, Dyadic, bool>> v;
    for (std::size_t i = 0; i < m.size(); ++i)
      v.emplace_back(m.spanner.position(int(i))[0], m.spanner.position(int(i))[1], m.info[i].steiner);
    return std::pair{v, m.triangles};
  };
  // U is refused three updates; V, the same updater that never saw them. A refused update must leave
  // no trace: the mesh right after it, and after the valid updates that follow, equals V's.
  Updater U({ip(0, 0), ip(5, 1)}), V({ip(0, 0), ip(5, 1)});
  EXPECT_THROW(U.insert(ip(5, 1)), kmr::InputError);
  EXPECT_THROW(U.erase(ip(7, 7)), kmr::InputError);
  EXPECT_TRUE(seen(U.mesh()) == seen(V.mesh())) << "a refused update changed the mesh";
  for (Updater* w : {&U, &V}) w->insert(ip(2, 7));
  EXPECT_TRUE(seen(U.mesh()) == seen(V.mesh())) << "a refused update changed the next insertion";
  for (Updater* w : {&U, &V}) w->erase(ip(0, 0)), w->erase(ip(2, 7));
  EXPECT_THROW(U.erase(ip(5, 1)), kmr::InputError);  // the last point
  EXPECT_TRUE(seen(U.mesh()) == seen(V.mesh())) << "the refused deletion of the last point changed the mesh";
  EXPECT_EQ(seen(U.mesh()).first.size(), 1u);  // one point is its own mesh
  for (Updater* w : {&U, &V}) w->insert(ip(0, 0));
  EXPECT_TRUE(seen(U.mesh()) == seen(V.mesh())) << "a refused update changed the next insertion";
  EXPECT_EQ(failures(check_all_updated(U.mesh())), "");
  EXPECT_GT(seen(U.mesh()).first.size(), 2u);
}

// The boundary of a construction is the 12 top-rank satellites of one nucleus (check_rigid_boundary):
// a rigid 12-gon, whose convexity no certificate needs to watch. Inserting a far point raises the
// top rank and deleting it lowers it again; the new top rank, decided while it was an inner rank,
// had one boundary satellite of (6, −3) and eleven of (0, 0) until the updater re-decided a top rank
// that falls as a whole (session 32; a cold review's finding). Regression: the boundary is rigid
// again and equals the construction's.
TEST(Update, DeletingTheFarPointThatRaisedTheTopRankLeavesARigidBoundary) {
  RecordProperty("claim", "L4.3.1");
  std::vector<InputPoint> in{ip(0, 0), ip(1, 1), ip(0, 2), ip(6, -3)};
  Mesh fresh = construct(in);
  ASSERT_TRUE(check_rigid_boundary(fresh).ok());
  Updater U(in);
  const Rank top = U.mesh().highest;
  U.insert(ip(28, 30));
  ASSERT_GT(U.mesh().highest, top);  // the path under test: the top rank rises, then falls back
  EXPECT_TRUE(check_rigid_boundary(U.mesh()).ok()) << check_rigid_boundary(U.mesh()).violations[0];
  U.erase(ip(28, 30));
  Mesh m = U.mesh();
  ASSERT_EQ(m.highest, top);
  EXPECT_EQ(failures(check_all_updated(m)), "");  // includes check_rigid_boundary
  // Independent of that judge: the boundary's positions equal the construction's.
  auto boundary = [](const Mesh& x) {
    std::set<std::pair<int, int>> e;
    for (auto& t : x.triangles)
      for (int i = 0; i < 3; ++i) e.insert({t[i], t[(i + 1) % 3]});
    std::set<std::pair<std::string, std::string>> out;
    for (auto& [a, b] : e)
      if (!e.count({b, a})) out.insert({x.spanner.position(a)[0].to_decimal(), x.spanner.position(a)[1].to_decimal()});
    return out;
  };
  EXPECT_EQ(boundary(m), boundary(fresh));
}

// U4 with the top rank unchanged: deleting the owner of the top rank, (0, 0), keeps Λ (the farthest
// pair from the new smallest point (0, 2) is still within the same power of two), so the other top
// satellites, all witnessed by the owner's, are re-decided together and one nucleus owns all 12.
TEST(Update, DeletingTheOwnerOfTheTopRankLeavesARigidBoundary) {
  RecordProperty("claim", "L4.3.1");
  Updater U({ip(0, 0), ip(1, 1), ip(0, 2), ip(6, -3)});
  const Mesh before = U.mesh();
  ASSERT_TRUE(check_rigid_boundary(before).ok());
  std::set<int> owners_before;
  for (auto& in : before.info)
    if (in.steiner && in.rank == before.highest) owners_before.insert(in.nucleus);
  ASSERT_EQ(owners_before, std::set<int>{0});  // (0, 0), input 0 in sorted order
  U.erase(ip(0, 0));
  Mesh m = U.mesh();
  ASSERT_EQ(m.highest, before.highest);  // the path under test: same top rank
  EXPECT_EQ(failures(check_all_updated(m)), "");
  std::set<int> owners;
  for (auto& in : m.info)
    if (in.steiner && in.rank == m.highest) owners.insert(in.nucleus);
  EXPECT_EQ(owners.size(), 1u);  // counted here, not by check_rigid_boundary (in check_all_updated)
}

void family_case(int family, int n0, int steps) {
  const char* names[] = {"uniform", "grid", "collinear", "cocircular", "clusters 2^30"};
  double s = run(family, n0, steps, 300 + family);
  ASSERT_GE(s, 0) << names[family];
  testing::Test::RecordProperty("stability", std::to_string(s));
  std::printf("family %-14s mean Steiner fraction shared with a from-scratch construction: %.3f\n", names[family], s);
}

TEST(Update, RandomUniform) { family_case(0, 4, 3); }
TEST(Update, RandomGrid) { family_case(1, 4, 3); }
TEST(Update, RandomCollinear) { family_case(2, 4, 3); }
TEST(Update, RandomCocircular) { family_case(3, 4, 3); }
TEST(Update, RandomClusters2To30) { family_case(4, 3, 2); }
