// §4.3 certificates of the constructed mesh as polynomials of time: hand-derived failure times,
// all certificates hold at t = 0 (L4.3.1 at the construction), and before the first failure the
// moved mesh still passes the brute-force spanner, ball and Delaunay checks (L4.3.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <tuple>

#include "kmesh/certificates.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/update.hpp"
#include "poly/sturm.hpp"

using namespace kmr::kmesh;
using kmr::exact::Integer;

TEST(Certificates, HandDerivedFailureTimes) {
  // (0,0) at rest and (3,0) moving by (1,0): vertex 1 is a 1-center whose parent is the root, so its
  // parent-child certificate |x p| ≤ 2^2 fails when 3 + t = 4 (t = 1, lattice index 1024 at B = 10);
  // their edge at rank −2, |x y| ≤ 20·2^−2 = 5, fails at t = 2 (index 2048).
  Mesh m = construct({{Integer(0), Integer(0)}, {Integer(3), Integer(0), Integer(1), Integer(0)}});
  auto certs = certificates(m);
  bool pc = false, edge = false;
  for (auto& c : certs) {
    if (c.kind == Certificate::ParentChild && c.a == 1) {
      kmr::poly::LatticeRootSolver s(c.value, 10);
      pc = true;
      EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(8)), Integer(1024));
    }
    if (c.kind == Certificate::Edge && c.a == 0 && c.b == 1 && c.rank == -2) {
      kmr::poly::LatticeRootSolver s(c.value, 10);
      edge = true;
      EXPECT_EQ(s.next_failure_after(Dyadic(0), Dyadic(8)), Integer(2048));
    }
  }
  EXPECT_TRUE(pc);
  EXPECT_TRUE(edge);
}

namespace {
Integer I(int v) { return Integer(v); }
}  // namespace

// A strict certificate is violated where its polynomial vanishes, also where it only touches 0 at a
// lattice time without changing sign (an even-multiplicity root: the solver alone sees no failure
// there). Lattice 2^−2; (t − 1)² vanishes at t = 1 = 4δ, so the strict certificate fails in
// (3δ, 4δ], batch 3, repaired at 1; a non-strict one and a Delaunay in-circle one never fail; from
// t = 1 itself the zero is no failure. (t − 1)²(3 − t): the touch at 1 comes first (batch 3); for
// the non-strict certificate the sign change in [3, 3 + δ) is the failure (batch 12). A simple zero
// at 1 with a second root in the same lattice interval is no sign change either.
TEST(Certificates, L4_3_1_StrictZeroAtALatticeTimeWithoutSignChangeFailsThere) {
  RecordProperty("claim", "L4.3.1");
  const kmr::poly::Polynomial touch(std::vector<Integer>{I(1), I(-2), I(1)});
  const kmr::poly::Polynomial touch_then_cross = touch * kmr::poly::Polynomial(std::vector<Integer>{I(3), I(-1)});
  Certificate sep{Certificate::Separation, 0, 1, 0, true, touch};
  Certificate edge{Certificate::Edge, 0, 1, 0, false, touch};
  Certificate circle{Certificate::Delaunay, 0, 1, 0, true, touch};
  EXPECT_FALSE(holds_at(sep, Dyadic(1)));
  EXPECT_TRUE(holds_at(edge, Dyadic(1)));
  EXPECT_TRUE(holds_at(circle, Dyadic(1)));
  kmr::poly::LatticeRootSolver s(touch, 2);
  EXPECT_EQ(failure_batch(s, fails_at_zero(sep), Dyadic(0), Dyadic(4)), std::optional<Integer>(I(3)));
  EXPECT_EQ(failure_batch(s, fails_at_zero(edge), Dyadic(0), Dyadic(4)), std::nullopt);
  EXPECT_EQ(failure_batch(s, fails_at_zero(circle), Dyadic(0), Dyadic(4)), std::nullopt);
  EXPECT_EQ(failure_batch(s, fails_at_zero(sep), Dyadic(1), Dyadic(4)), std::nullopt) << "a zero at `from`";
  // The horizon 1 still sees the batch that repairs at 1 (interval (3δ, 4δ]); the horizon 3δ does not.
  EXPECT_EQ(failure_batch(s, fails_at_zero(sep), Dyadic(0), Dyadic(1)), std::optional<Integer>(I(3)));
  EXPECT_EQ(failure_batch(s, fails_at_zero(sep), Dyadic(0), Dyadic(3, -2)), std::nullopt);
  // A simple zero at 1 and another at 9/8 in the same interval [4δ, 5δ): no sign change across it.
  const kmr::poly::Polynomial two_in_one(std::vector<Integer>{I(9), I(-17), I(8)});
  kmr::poly::LatticeRootSolver s1(two_in_one, 2);
  Certificate sep2{Certificate::Separation, 0, 1, 0, true, two_in_one};
  EXPECT_FALSE(holds_at(sep2, Dyadic(1)));
  EXPECT_EQ(failure_batch(s1, fails_at_zero(sep2), Dyadic(0), Dyadic(4)), std::optional<Integer>(I(3)));
  kmr::poly::LatticeRootSolver s2(touch_then_cross, 2);
  sep.value = edge.value = touch_then_cross;
  EXPECT_EQ(failure_batch(s2, fails_at_zero(sep), Dyadic(0), Dyadic(8)), std::optional<Integer>(I(3)));
  EXPECT_EQ(failure_batch(s2, fails_at_zero(edge), Dyadic(0), Dyadic(8)), std::optional<Integer>(I(12)));
  EXPECT_EQ(failure_batch(s2, fails_at_zero(sep), Dyadic(1), Dyadic(8)), std::optional<Integer>(I(11)));
}

// A triangle whose orientation reaches 0 is flat there, and that is no cocircularity the symbolic
// perturbation decides: (0, 0), (4, 0), (2, 2 − t) has orientation 8 − 4t, flat at t = 2 = 16δ
// (lattice 2^−3), so its certificate fails in (15δ, 16δ], batch 15, repaired at 2; an in-circle
// certificate with the same polynomial is excused at its zero (batch 16, the sign change). Every
// triangle of a constructed mesh has an orientation certificate (ccw), every interior edge an
// in-circle one.
TEST(Certificates, L4_3_1_FlatTriangleFailsAtItsZero) {
  RecordProperty("claim", "L4.3.1");
  const kmr::poly::Polynomial flat_at_2(std::vector<Integer>{I(8), I(-4)});
  Certificate tri{Certificate::Delaunay, 0, 1, 0, true, flat_at_2};
  tri.ccw = true;
  Certificate circle{Certificate::Delaunay, 0, 1, 0, true, flat_at_2};
  EXPECT_FALSE(holds_at(tri, Dyadic(2)));
  EXPECT_TRUE(holds_at(tri, Dyadic(15, -3)));
  EXPECT_TRUE(holds_at(circle, Dyadic(2)));
  kmr::poly::LatticeRootSolver s(flat_at_2, 3);
  EXPECT_EQ(failure_batch(s, fails_at_zero(tri), Dyadic(0), Dyadic(4)), std::optional<Integer>(I(15)));
  EXPECT_EQ(failure_batch(s, fails_at_zero(circle), Dyadic(0), Dyadic(4)), std::optional<Integer>(I(16)));

  Mesh m = construct({{I(0), I(0)}, {I(5), I(1), I(0), I(1)}, {I(2), I(7)}});
  std::size_t ccw = 0, in_circle = 0;
  for (auto& c : certificates(m))
    if (c.kind == Certificate::Delaunay) (c.ccw ? ccw : in_circle) += 1;
  std::map<std::pair<int, int>, int> sides;  // undirected edge → triangles having it
  for (auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) sides[std::minmax(t[i], t[(i + 1) % 3])] += 1;
  std::size_t interior = 0;
  for (auto& [e, n] : sides) interior += n == 2;
  EXPECT_GT(m.triangles.size(), 0u);
  EXPECT_EQ(ccw, m.triangles.size());
  EXPECT_EQ(in_circle, interior);
}

TEST(Certificates, L4_3_1_HoldAtZeroAndCertifyUntilTheFirstFailure) {
  RecordProperty("claim", "L4.3.1 L4.4.1");
  std::mt19937_64 rng(17);
  int checked = 0;
  for (int trial = 0; trial < 4; ++trial) {
    std::uniform_int_distribution<int> d(-40, 40), v(-2, 2);
    std::vector<InputPoint> in;
    for (int i = 0; i < 4; ++i) in.push_back({Integer(d(rng)), Integer(d(rng)), Integer(v(rng)), Integer(v(rng))});
    std::sort(in.begin(), in.end());
    in.erase(std::unique(in.begin(), in.end()), in.end());
    Mesh m = construct(in);
    auto certs = certificates(m);
    for (auto& c : certs) EXPECT_TRUE(holds_at(c, Dyadic(0))) << kind_name(c.kind) << " " << c.a << " " << c.b;
    const int bits = 16;
    // Each group of certificates certifies one part of the output: before the group's own first
    // failure, that part (checked by brute force on the moved points) must still be valid.
    using K = Certificate::Kind;
    struct Group {
      std::vector<K> kinds;
      CheckResult (*check)(const Mesh&);
    };
    auto spanner_check = [](const Mesh& x) { return check_spanner(x.spanner); };
    std::vector<Group> groups{{{K::ParentChild, K::Separation, K::Edge, K::Potential}, +spanner_check},
                              {{K::ParentChild, K::Separation, K::Edge, K::Potential, K::BallNotEmpty, K::BallEmpty}, check_ball_empty},
                              {{K::Delaunay}, check_delaunay}};
    for (auto& g : groups) {
      std::vector<Certificate> sub;
      for (auto& c : certs)
        if (std::find(g.kinds.begin(), g.kinds.end(), c.kind) != g.kinds.end()) sub.push_back(c);
      auto f = first_failure(sub, bits, Dyadic(4));
      Integer k = f ? f->first : Integer(4) << bits;
      if (k < 2) continue;
      Dyadic t(k, -bits - 1);  // half-way to the group's first failing interval
      Mesh mt = moved_to(m, t);
      auto r = g.check(mt);
      EXPECT_TRUE(r.ok()) << "trial " << trial << " at t = " << t.to_decimal() << ": " << r.claim << ": " << (r.ok() ? "" : r.violations[0]);
          ++checked;
    }
  }
  EXPECT_GE(checked, 6);
}

// certificate_specs (kmesh12: stamps and sorted lists instead of per-vertex sets) against a
// brute-force enumeration sharing none of its loops: ball-empty pairs from the distances
// (|s v| ≤ c·2^ℓ′ at the highest ℓ′ ∈ [ℓ−6, ℓ−1] where both are centers). Compared as multisets of
// (kind, a, b, rank) on constructed meshes and on an updated one. (Its potential-neighbour half
// walked the ranks of x's neighbour lists, the rule it was checking, and missed the pairs at ranks
// without a list: PotentialNeighbourCertificatesEqualTheirDefinition below replaces it, kmesh17.)
TEST(Certificates, SpecsEqualABruteForceEnumeration) {
  using K = Certificate::Kind;
  using Row = std::tuple<int, int, int, Rank>;
  auto expected = [](const Mesh& m) {
    const Spanner& S = m.spanner;
    std::vector<Row> out;
    for (const Considered& c : m.considered) {
      if (!c.converted) continue;
      for (int v = 0; v < c.vertex; ++v) {
        const Rank l = std::min({c.rank - 1, S.top(v), S.top(c.vertex)});
        if (l >= c.rank - 6 && within(S.position(v), S.position(c.vertex), kC, l))
          out.push_back({K::BallEmpty, c.vertex, v, c.rank});
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  auto listed = [](const Mesh& m) {
    std::vector<Row> out;
    for (auto& s : certificate_specs(m))
      if (s.kind == K::BallEmpty) out.push_back({s.kind, s.a, s.b, s.rank});
    std::sort(out.begin(), out.end());
    return out;
  };
  std::mt19937_64 rng(29);
  std::size_t ball_empty = 0;
  for (int trial = 0; trial < 3; ++trial) {
    std::uniform_int_distribution<int> d(-60, 60);
    std::vector<InputPoint> in;
    for (int i = 0; i < 4 + trial; ++i) in.push_back({Integer(d(rng)), Integer(d(rng))});
    std::sort(in.begin(), in.end());
    in.erase(std::unique(in.begin(), in.end()), in.end());
    Updater u(in);
    Mesh m = u.mesh();
    auto want = expected(m);
    EXPECT_EQ(listed(m), want) << "seed 29, trial " << trial << ", construction";
    ball_empty += want.size();
    u.insert({Integer(d(rng) + 200), Integer(d(rng))});
    Mesh m2 = u.mesh();
    EXPECT_EQ(listed(m2), expected(m2)) << "seed 29, trial " << trial << ", after an insertion";
  }
  EXPECT_GT(ball_empty, 0u);
}

// Potential-neighbour certificates against their definition (§4.1.2, Gao–Guibas–Nguyen): one for
// every rank ℓ < top_rank and every two ℓ-centers x, y (top ≥ ℓ) more than c·2^ℓ apart whose
// parents at rank ℓ+1 (rep(·, ℓ+1): the vertex itself if it is an (ℓ+1)-center) are the same or
// within c·2^(ℓ+1) of each other. Decided from the distances and the parent pointers only, at every
// rank where both are centers — not from the neighbour lists (which have gaps between λ_x and
// top(x), and none below λ_x), as the old half of SpecsEqualABruteForceEnumeration did. Below the
// lowest rank with a neighbour pair minus one, no two parents are neighbours: the ranks are finite.
TEST(Certificates, PotentialNeighbourCertificatesEqualTheirDefinition) {
  using K = Certificate::Kind;
  using Row = std::tuple<int, int, Rank>;
  auto expected = [](const Mesh& m) {
    const Spanner& S = m.spanner;
    const int N = static_cast<int>(m.size());
    Rank low = S.top_rank();  // the lowest rank where two centers are within c·2^ℓ
    for (int x = 0; x < N; ++x)
      for (int y = x + 1; y < N; ++y)
        low = std::min(low, std::min({min_rank_within(S.position(x), S.position(y), kC), S.top(x), S.top(y)}));
    std::vector<Row> out;
    for (Rank l = low - 1; l < S.top_rank(); ++l)
      for (int x = 0; x < N; ++x) {
        if (S.top(x) < l) continue;
        for (int y = x + 1; y < N; ++y) {
          if (S.top(y) < l || within(S.position(x), S.position(y), kC, l)) continue;
          const int rx = S.rep(x, l + 1), ry = S.rep(y, l + 1);
          if (rx == ry || within(S.position(rx), S.position(ry), kC, l + 1)) out.push_back({x, y, l});
        }
      }
    std::sort(out.begin(), out.end());
    return out;
  };
  auto listed = [](const Mesh& m) {
    std::vector<Row> out;
    for (auto& s : certificate_specs(m))
      if (s.kind == K::Potential) out.push_back({std::min(s.a, s.b), std::max(s.a, s.b), s.rank});
    std::sort(out.begin(), out.end());
    return out;
  };
  auto diff = [](const std::vector<Row>& got, const std::vector<Row>& want) {
    std::vector<Row> missing, extra;
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
    std::string s = std::to_string(missing.size()) + " missing, " + std::to_string(extra.size()) + " extra";
    if (!missing.empty())
      s += "; first missing: (" + std::to_string(std::get<0>(missing[0])) + ", " + std::to_string(std::get<1>(missing[0])) +
           ") at rank " + std::to_string(std::get<2>(missing[0]));
    return s;
  };
  std::size_t total = 0;
  // Two points 3 apart (both activate at −2: at −3 they are cousins, 3 > 20·2^−3, and neither has a
  // list there), then random ones, constructed and updated.
  {
    Mesh m = construct({{Integer(0), Integer(0)}, {Integer(3), Integer(0)}});
    auto want = expected(m), got = listed(m);
    EXPECT_TRUE(got == want) << "two points: " << diff(got, want);
    total += want.size();
  }
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 3; ++trial) {
    std::uniform_int_distribution<int> d(-60, 60);
    std::vector<InputPoint> in;
    for (int i = 0; i < 3 + trial; ++i) in.push_back({Integer(d(rng)), Integer(d(rng))});
    std::sort(in.begin(), in.end());
    in.erase(std::unique(in.begin(), in.end()), in.end());
    Updater u(in);
    Mesh m = u.mesh();
    auto want = expected(m), got = listed(m);
    EXPECT_TRUE(got == want) << "seed 41, trial " << trial << ", construction: " << diff(got, want);
    total += want.size();
    u.insert({Integer(d(rng) + 200), Integer(d(rng))});
    Mesh m2 = u.mesh();
    auto want2 = expected(m2), got2 = listed(m2);
    EXPECT_TRUE(got2 == want2) << "seed 41, trial " << trial << ", after an insertion: " << diff(got2, want2);
  }
  EXPECT_GT(total, 0u);
}
