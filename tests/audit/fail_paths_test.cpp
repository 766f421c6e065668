// More failure paths of the audit's judges (issue 13 §2), through the seam of audit.hpp
// (Options::tamper / measured()), as tests/audit/fail_verdict_test.cpp does: each test breaks the
// measured result in one way the judge must notice and checks the FAIL and the words that name the
// problem. The broken results are built here from hand-derived facts about the audit's built-in
// inputs (the 4×4×4 grid, the seeded duplicates, the planted roots), not from the code judged.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <array>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "hull/hull.hpp"
#include "hull/kinetic_hull.hpp"
#include "kinetic/separation_study.hpp"
#include "poly/sturm.hpp"
#include "sacprograms/session.hpp"

namespace {

using namespace kmr::audit;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Runs the quick check `claim` (exactly); tamper(name, value, call index of that name) sees every
// measured value. Returns the one result.
template <class F>
Result run_with(const std::string& claim, F tamper) {
  Options o;
  o.quick = true;
  o.only = claim + "$";
  std::map<std::string, int> calls;
  o.tamper = [&](const std::string& name, std::any& value) { tamper(name, value, calls[name]++); };
  auto results = run_checks(o);
  EXPECT_EQ(results.size(), 1u);
  return results.empty() ? Result{} : results.front();
}

// The audit's "grid" input of C2.2-static-hull-correct in quick mode: index x·16 + y·4 + z.
using P3 = std::array<long long, 3>;
P3 grid_point(int i) { return {i / 16, (i / 4) % 4, i % 4}; }
P3 sub(P3 a, P3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(P3 a, P3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
long long dot(P3 a, P3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A hull whose facet (a, b, c) is split at a grid point strictly inside it (Pick: a half face of the
// 4×4 grid square has exactly one interior grid point): still a closed oriented surface with
// V − E + F = 2 and no point outside, but the new vertex lies on three coplanar facets only.
TEST(AuditFailPaths, HullCertifierRefusesAVertexThatIsNotExtreme) {
  int added = -1;
  auto r = run_with("C2.2-static-hull-correct", [&](const std::string& name, std::any& value, int call) {
    if (name != "C2.2-static-hull-correct hull" || call != 0) return;
    auto& h = std::any_cast<kmr::hull::Hull&>(value);
    auto f = h.facets.front();
    P3 a = grid_point(f[0]), b = grid_point(f[1]), c = grid_point(f[2]);
    P3 n = cross(sub(b, a), sub(c, a));
    for (int i = 0; i < 64 && added < 0; ++i) {
      P3 p = grid_point(i);
      if (dot(n, sub(p, a)) != 0) continue;  // not in the facet's plane
      bool inside = dot(n, cross(sub(b, a), sub(p, a))) > 0 && dot(n, cross(sub(c, b), sub(p, b))) > 0 &&
                    dot(n, cross(sub(a, c), sub(p, c))) > 0;
      if (inside) added = i;
    }
    ASSERT_GE(added, 0);
    h.facets.front() = {f[0], f[1], added};
    h.facets.push_back({f[1], f[2], added});
    h.facets.push_back({f[2], f[0], added});
    h.vertices.push_back(added);
  });
  ASSERT_GE(added, 0);
  EXPECT_FALSE(r.verdict.pass);
  EXPECT_EQ(r.verdict.summary, "grid: vertex " + std::to_string(added) + " is not extreme");
}

// The "duplicates" input (the fifth): 400 draws of grid points from mt19937_64(seed) after no other
// draw. A hull vertex renamed to a later copy of its point is the same surface, but not the lowest index.
TEST(AuditFailPaths, HullCertifierRefusesAVertexThatIsNotTheLowestIndexOfItsPoint) {
  std::vector<int> dups;
  std::mt19937_64 rng(Options{}.seed);
  for (int i = 0; i < 400; ++i) dups.push_back(static_cast<int>(rng() % 64));
  int renamed = -1;
  auto r = run_with("C2.2-static-hull-correct", [&](const std::string& name, std::any& value, int call) {
    if (name != "C2.2-static-hull-correct hull" || call != 4) return;
    auto& h = std::any_cast<kmr::hull::Hull&>(value);
    ASSERT_EQ(h.n, 400);
    int v = h.vertices.front();
    for (int w = v + 1; w < 400 && renamed < 0; ++w)
      if (dups[w] == dups[v]) renamed = w;
    ASSERT_GE(renamed, 0);
    for (auto& f : h.facets)
      for (int& x : f)
        if (x == v) x = renamed;
    h.vertices.front() = renamed;
  });
  ASSERT_GE(renamed, 0);
  EXPECT_FALSE(r.verdict.pass);
  EXPECT_EQ(r.verdict.summary, "duplicates: vertex " + std::to_string(renamed) + " is not the lowest index of its point");
}

// The same facets listed from another corner: the certificate holds, but the run with the other seed
// (which the judge compares with) gives the output in its canonical form.
TEST(AuditFailPaths, HullJudgeRefusesAnOutputThatAnotherSeedDoesNotReproduce) {
  auto r = run_with("C2.2-static-hull-correct", [&](const std::string& name, std::any& value, int call) {
    if (name != "C2.2-static-hull-correct hull" || call != 0) return;
    auto& f = std::any_cast<kmr::hull::Hull&>(value).facets.front();
    std::rotate(f.begin(), f.begin() + 1, f.end());
  });
  EXPECT_FALSE(r.verdict.pass);
  EXPECT_EQ(r.verdict.summary, "grid: another seed gives another output");
}

// Each of the four things compared after a propagation, wrong in one round each (rounds 0–3 of the
// first program): four mismatches, the first named.
TEST(AuditFailPaths, PropagationJudgeComparesOutputSignatureTraceNodesAndLiveModifiables) {
  auto r = run_with("S1.3.1-change-propagation", [&](const std::string& name, std::any& value, int call) {
    if (name != "S1.3.1-change-propagation snapshot") return;
    auto& s = std::any_cast<kmr::sacprograms::Snapshot&>(value);
    if (call == 0) s.output.push_back(1);
    if (call == 1) s.signature += "R";
    if (call == 2) s.trace_nodes += 1;
    if (call == 3) s.live_mods += 1;
  });
  EXPECT_FALSE(r.verdict.pass);
  EXPECT_TRUE(has(r.verdict.summary, "; first failure: map round 0")) << r.verdict.summary;
  const auto& f = r.verdict.figures;
  auto mismatches = std::find_if(f.begin(), f.end(), [](auto& p) { return p.first == "mismatches"; });
  ASSERT_NE(mismatches, f.end());
  EXPECT_EQ(mismatches->second, "4");
}

// The lattice root solver's answers, wrong: one interval's sign change flipped (or an interval where
// the planted polynomial has no root), and a failure interval one later than the planted one.
TEST(AuditFailPaths, RootJudgesRefuseAWrongIsolationAndAWrongNextFailure) {
  using kmr::poly::LatticeInterval;
  auto iso = run_with("A2.1-lattice-isolation", [&](const std::string& name, std::any& value, int call) {
    if (name != "A2.1-lattice-isolation intervals" || call != 0) return;
    auto& got = std::any_cast<std::vector<LatticeInterval>&>(value);
    if (got.empty())
      got.push_back({kmr::exact::Integer(0), 1, true});
    else
      got.front().sign_change = !got.front().sign_change;
  });
  EXPECT_FALSE(iso.verdict.pass);
  EXPECT_EQ(iso.verdict.summary.rfind("isolation differs from the planted roots for p = ", 0), 0u) << iso.verdict.summary;
  auto next = run_with("A2.1-next-failure", [&](const std::string& name, std::any& value, int call) {
    if (name != "A2.1-next-failure interval" || call != 0) return;
    auto& k = std::any_cast<std::optional<kmr::exact::Integer>&>(value);
    k = k ? *k + 1 : kmr::exact::Integer(0);
  });
  EXPECT_FALSE(next.verdict.pass);
  EXPECT_EQ(next.verdict.summary.rfind("next_failure_after(", 0), 0u) << next.verdict.summary;
  EXPECT_TRUE(has(next.verdict.summary, ") wrong for p = ")) << next.verdict.summary;
}

// The kinetic hull's three judges (one sampled simulation): a facet turned over is not the static
// hull; a signature or a set of live certificates that differs from the from-scratch run's, at the
// third sampled batch (after 20 batches, so at a time after 0), is named with that time.
TEST(AuditFailPaths, KineticHullJudgesRefuseAWrongHullTraceAndCertificateSet) {
  auto turned = run_with("C2.2-hull-correct", [&](const std::string& name, std::any& value, int call) {
    if (name != "C2.2-hull-correct facets" || call != 0) return;
    auto& f = std::any_cast<std::vector<std::array<int, 3>>&>(value).front();
    std::swap(f[1], f[2]);
  });
  EXPECT_FALSE(turned.verdict.pass);
  EXPECT_TRUE(has(turned.verdict.summary, "the kinetic hull differs from the static hull at t = 0")) << turned.verdict.summary;
  auto trace = run_with("C2.2-stability", [&](const std::string& name, std::any& value, int call) {
    if (name == "C2.2-stability signature" && call == 2) std::any_cast<std::string&>(value) += "H";
  });
  EXPECT_FALSE(trace.verdict.pass);
  EXPECT_EQ(trace.verdict.summary.rfind("trace differs from a from-scratch run at t = ", 0), 0u) << trace.verdict.summary;
  EXPECT_NE(trace.verdict.summary, "trace differs from a from-scratch run at t = 0");  // the third look, not the first
  auto keys = run_with("F2.8-certificates", [&](const std::string& name, std::any& value, int call) {
    if (name == "F2.8-certificates keys" && call == 2)
      std::any_cast<std::vector<kmr::hull::KineticHull::CertificateKey>&>(value).pop_back();
  });
  EXPECT_FALSE(keys.verdict.pass);
  EXPECT_EQ(keys.verdict.summary.rfind("live certificates differ from a from-scratch run at t = ", 0), 0u) << keys.verdict.summary;
  EXPECT_TRUE(has(keys.verdict.summary, "; from-scratch certificate counts at t = 0")) << keys.verdict.summary;
  // Untampered, the same checks pass (the tampered runs were not cached for them).
  Options o;
  o.quick = true;
  o.only = "C2.2-hull-correct$";
  auto clean = run_checks(o);
  ASSERT_EQ(clean.size(), 1u);
  EXPECT_TRUE(clean.front().verdict.pass) << clean.front().verdict.summary;
}

// Lattice batching against exact separation: each of the three judgements, wrong on purpose in the
// classic simulator's run — its order (generic motions), its root-solver work set to nothing, no tie
// established where the simultaneous motions need one; then only its crossing count. Each reason is
// named with its input, in order.
TEST(AuditFailPaths, BatchingJudgeNamesEveryDisagreement) {
  const std::string claim = "A2.1-batching-avoids-separation", name = claim + " classic";
  auto r = run_with(claim, [&](const std::string& n, std::any& value, int call) {
    if (n != name) return;
    auto& run = std::any_cast<kmr::kinetic::StudyRun&>(value);
    if (call == 0) {
      std::swap(run.order.front(), run.order.back());
      run.sturm_queries = run.bisection_steps = run.machine_steps = 0;
    } else {
      run.ties = 0;
    }
  });
  EXPECT_FALSE(r.verdict.pass);
  EXPECT_EQ(r.verdict.summary,
            "simulators disagree (generic); classic needed no more root work (generic); no tie established (simultaneous); ");
  auto crossings = run_with(claim, [&](const std::string& n, std::any& value, int call) {
    if (n == name && call == 1) std::any_cast<kmr::kinetic::StudyRun&>(value).crossings += 1;
  });
  EXPECT_FALSE(crossings.verdict.pass);
  EXPECT_EQ(crossings.verdict.summary, "simulators disagree (simultaneous); ");
}

}  // namespace
