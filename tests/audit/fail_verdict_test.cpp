// The audit's judges (src/audit/*_checks.cpp) given a wrong measured result must say FAIL and name
// what is wrong: each test runs one quick check with Options::tamper (the seam of audit.hpp)
// replacing the result the check is about to judge by a deliberately broken one — a swapped sorted
// order, a hull with a facet missing or turned inside out, an extra output of a self-adjusting
// program, a mesh with a clockwise triangle or a wrongly converted satellite, a well-spaced output
// with a near-duplicate vertex. audit.quick runs the same checks untampered (they PASS there).
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <sstream>
#include <stdexcept>
#include <string>

#include "audit/audit.hpp"
#include "hull/hull.hpp"
#include "kmesh/construction.hpp"
#include "sacprograms/session.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace {

using namespace kmr::audit;

struct Tampered {
  Result result;
  int calls = 0;  // measured values of the chosen name the check passed through the seam
};

// Runs the quick check `claim` (exactly), with f(value, call index) applied to every measured value
// named `name` (typed T); other names are left alone.
template <class T, class F>
Tampered run_tampered(const std::string& claim, const std::string& name, F f) {
  Tampered t;
  Options o;
  o.quick = true;
  o.only = claim + "$";
  o.tamper = [&](const std::string& n, std::any& value) {
    if (n != name) return;
    f(std::any_cast<T&>(value), t.calls++);
  };
  auto results = run_checks(o);
  EXPECT_EQ(results.size(), 1u);
  if (!results.empty()) t.result = results.front();
  return t;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(FailVerdict, KineticSortWithTwoPointsSwappedFails) {
  // The order is judged at t = 0 and after every batch: a swap at the third look (after batch 2).
  auto t = run_tampered<std::vector<std::size_t>>("A2.1-batch", "A2.1-batch order", [](std::vector<std::size_t>& order, int call) {
    if (call == 2) std::swap(order[0], order[1]);
  });
  EXPECT_FALSE(t.result.verdict.pass);
  EXPECT_EQ(t.calls, 3);  // the check stops at the first wrong order
  EXPECT_TRUE(has(t.result.verdict.summary, "order differs from the exact sort at t = ")) << t.result.verdict.summary;
  auto first = run_tampered<std::vector<std::size_t>>("A2.1-batch", "A2.1-batch order", [](std::vector<std::size_t>& order, int call) {
    if (call == 0) std::reverse(order.begin(), order.end());
  });
  EXPECT_FALSE(first.result.verdict.pass);
  EXPECT_EQ(first.result.verdict.summary, "initial order differs from the exact sort");
}

TEST(FailVerdict, HullCertifierRefusesAnOpenAnInvertedAndAnOverfullHull) {
  const std::string claim = "C2.2-static-hull-correct", name = claim + " hull";
  using kmr::hull::Hull;
  auto open = run_tampered<Hull>(claim, name, [](Hull& h, int call) {
    if (call == 0) h.facets.pop_back();
  });
  EXPECT_FALSE(open.result.verdict.pass);
  EXPECT_EQ(open.result.verdict.summary, "grid: the facets do not form a closed oriented surface");
  auto inverted = run_tampered<Hull>(claim, name, [](Hull& h, int call) {
    if (call == 1)  // the coplanar input's hull, turned inside out: closed, Euler 2, but points outside
      for (auto& f : h.facets) std::swap(f[1], f[2]);
  });
  EXPECT_FALSE(inverted.result.verdict.pass);
  EXPECT_TRUE(has(inverted.result.verdict.summary, "coplanar: point ")) << inverted.result.verdict.summary;
  EXPECT_TRUE(has(inverted.result.verdict.summary, " lies outside a facet")) << inverted.result.verdict.summary;
  auto extra = run_tampered<Hull>(claim, name, [](Hull& h, int call) {
    if (call == 0) {  // a vertex listed that no facet uses: V − E + F = 3
      for (int i = 0; i < h.n; ++i)
        if (std::find(h.vertices.begin(), h.vertices.end(), i) == h.vertices.end()) {
          h.vertices.push_back(i);
          break;
        }
    }
  });
  EXPECT_FALSE(extra.result.verdict.pass);
  EXPECT_EQ(extra.result.verdict.summary, "grid: Euler characteristic 3");
}

TEST(FailVerdict, PropagationWithAWrongOutputFailsNamingTheRound) {
  auto t = run_tampered<kmr::sacprograms::Snapshot>("S1.3.1-change-propagation", "S1.3.1-change-propagation snapshot",
                                                    [](kmr::sacprograms::Snapshot& s, int call) {
                                                      if (call == 4) s.output.push_back(7);
                                                    });
  EXPECT_FALSE(t.result.verdict.pass);
  EXPECT_GT(t.calls, 4);
  EXPECT_TRUE(has(t.result.verdict.summary, " round 4")) << t.result.verdict.summary;
  const auto& f = t.result.verdict.figures;
  auto mismatches = std::find_if(f.begin(), f.end(), [](auto& p) { return p.first == "mismatches"; });
  ASSERT_NE(mismatches, f.end());
  EXPECT_EQ(mismatches->second, "1");
}

TEST(FailVerdict, MeshJudgesCatchAClockwiseTriangleAndAWrongConversion) {
  using kmr::kmesh::Mesh;
  const std::string claim = "T4.2.12", name = "T4.2.12 mesh";
  auto cw = run_tampered<Mesh>(claim, name, [](Mesh& m, int call) {
    if (call == 1) std::swap(m.triangles.at(0)[1], m.triangles.at(0)[2]);
  });
  EXPECT_FALSE(cw.result.verdict.pass);
  EXPECT_EQ(cw.calls, 3);  // two uniform sizes and the 3-point cluster
  EXPECT_EQ(cw.result.verdict.summary.rfind("lemma check failed: n=8 uniform: delaunay: triangle not counter-clockwise", 0), 0u)
      << cw.result.verdict.summary;
  auto conv = run_tampered<Mesh>(claim, name, [](Mesh& m, int call) {
    if (call == 0) m.considered.at(0).converted = !m.considered.at(0).converted;
  });
  EXPECT_FALSE(conv.result.verdict.pass);
  EXPECT_TRUE(has(conv.result.verdict.summary, "lemma check failed: n=4 uniform: L4.2.4: satellite (nucleus ")) << conv.result.verdict.summary;
}

TEST(FailVerdict, WellSpacedJudgeCatchesANearDuplicateVertex) {
  using P = kmr::wellspaced::Point<2>;
  auto t = run_tampered<std::vector<P>>("T3.3.4", "T3.3.4 output 2D", [](std::vector<P>& M, int call) {
    if (call == 0) M.push_back({M[0][0] + 1e-9, M[0][1]});
  });
  EXPECT_FALSE(t.result.verdict.pass);
  EXPECT_EQ(t.calls, 5);  // the five 2D inputs; only the first is broken
  EXPECT_EQ(t.result.verdict.summary.rfind("6/7 outputs", 0), 0u) << t.result.verdict.summary;
}

// A check that throws is a FAIL whose summary carries the message (run_checks), also when the check
// runs on the sac checks' large-stack thread (the exception crosses the thread); run_audit's status
// is then 1 and its table says FAIL.
TEST(FailVerdict, AThrowingCheckFailsWithItsMessageAlsoAcrossTheLargeStackThread) {
  auto boom = [](const std::string&, std::any&) { throw std::runtime_error("tampered: boom"); };
  for (const char* claim : {"A2.1-batch$", "S1.3.1-change-propagation$"}) {
    Options o;
    o.quick = true;
    o.only = claim;
    o.tamper = boom;
    std::ostringstream table;
    EXPECT_EQ(run_audit(o, table, nullptr), 1) << claim;
    std::string t = table.str();
    EXPECT_TRUE(has(t, " FAIL  ")) << t;
    EXPECT_TRUE(has(t, "threw: tampered: boom")) << t;
    EXPECT_TRUE(has(t, "0 passed, 1 failed")) << t;
  }
}

}  // namespace
