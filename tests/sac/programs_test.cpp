// The benchmark programs against independent references (std::transform/copy_if/accumulate/sort,
// a monotone-chain hull, PlainTree::eval) on fixed inputs, including the degenerate ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "sacprograms/bench.hpp"
#include "sacprograms/exptree.hpp"
#include "sacprograms/session.hpp"

using namespace kmr::sacprograms;

namespace {

std::vector<std::vector<long long>> shapes(bool points) {
  std::mt19937_64 rng(11);
  auto v = [&](long long a) { return points ? encode_point(a % 13 - 6, (a * 7) % 11 - 5) : a; };
  std::vector<std::vector<long long>> out{{}, {v(3)}, {v(3), v(3)}};
  std::vector<long long> dup, sorted, rev, rnd;
  for (int i = 0; i < 60; ++i) {
    dup.push_back(v(static_cast<long long>(rng() % 4)));
    sorted.push_back(v(i));
    rev.push_back(v(60 - i));
    rnd.push_back(v(static_cast<long long>(rng() % 1000)));
  }
  out.insert(out.end(), {dup, sorted, rev, rnd});
  if (points) {  // all collinear; all equal
    std::vector<long long> line, same;
    for (int i = 0; i < 20; ++i) {
      line.push_back(encode_point(i % 7, 2 * (i % 7)));
      same.push_back(encode_point(1, 1));
    }
    out.insert(out.end(), {line, same});
  }
  return out;
}

TEST(SacPrograms, S1_3_FromScratchOutputsMatchIndependentReferences) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  for (const auto& p : list_programs()) {
    for (const auto& in : shapes(p.name == "quickhull")) {
      ListSession s(p, in);
      auto out = s.snapshot(false).output;
      EXPECT_EQ(out, reference_output(p.name, in)) << p.name << " n=" << in.size();
      EXPECT_EQ(out, s.static_output()) << p.name << " static twin, n=" << in.size();
    }
  }
}

// map at the ends of the 64-bit range: 3x + 1 wraps modulo 2^64 (hand-derived values; the old signed
// arithmetic was undefined behaviour there, reported by the UBSan run), self-adjusting and static.
TEST(SacPrograms, MapWrapsAtTheEndsOfTheRange) {
  const long long kMax = std::numeric_limits<long long>::max(), kMin = std::numeric_limits<long long>::min();
  std::vector<long long> in{kMax, kMin, kMax / 3 + 1, -1, 0};
  std::vector<long long> want{kMax - 1, kMin + 1, kMin + 2, -2, 1};
  ListSession s(list_program("map"), in);
  EXPECT_EQ(s.snapshot(false).output, want);
  EXPECT_EQ(s.static_output(), want);
  EXPECT_EQ(map_fn(kMin / 3 - 2), kMax - 2);  // 3 (−3074457345618258604) + 1 = −2^63 − 3 ≡ 2^63 − 3
}

TEST(SacPrograms, S1_3_QuickhullSquareWithInteriorAndEdgePoints) {
  std::vector<long long> in;
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y) in.push_back(encode_point(x, y));
  ListSession s(list_program("quickhull"), in);
  std::vector<long long> want{encode_point(0, 0), encode_point(4, 0), encode_point(4, 4), encode_point(0, 4)};
  EXPECT_EQ(s.snapshot(false).output, want);
  EXPECT_THROW(encode_point(1LL << 29, 0), kmr::InputError);
}

TEST(SacPrograms, S1_3_EditsMatchFromScratchRuns) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  for (const auto& p : list_programs()) {
    std::mt19937_64 rng(3);
    bool pts = p.name == "quickhull";
    auto val = [&] { return pts ? encode_point(static_cast<long long>(rng() % 21) - 10, static_cast<long long>(rng() % 21) - 10) : static_cast<long long>(rng() % 50); };
    std::vector<long long> in(40);
    for (auto& x : in) x = val();
    ListSession s(p, in);
    for (int e = 0; e < 60; ++e) {
      s.random_edit(rng, val);
      s.propagate();
      Snapshot a = s.snapshot(), b = from_scratch(p, s.values(), s.ids());
      ASSERT_EQ(a.output, reference_output(p.name, s.values())) << p.name << " edit " << e;
      ASSERT_EQ(a.signature, b.signature) << p.name << " edit " << e;
      ASSERT_EQ(a.trace_nodes, b.trace_nodes) << p.name << " edit " << e;
      ASSERT_EQ(a.live_mods, b.live_mods) << p.name << " edit " << e;
    }
  }
}

// A recursive evaluator, independent of PlainTree::eval's explicit stack.
long long eval_rec(const PlainTree& t, int i) {
  const auto& n = t.nodes[i];
  return n.leaf ? n.val : apply_op(n.op, eval_rec(t, n.l), eval_rec(t, n.r));
}

TEST(SacPrograms, S1_3_ExptreeEditsMatchEvaluationAndFromScratch) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  std::mt19937_64 rng(9);
  Runtime rt;
  TreeInput in(rt, PlainTree::random(33, 5));
  auto* out = sa_exptree(rt, in.root());
  EXPECT_EQ(rt.deref(out), eval_rec(in.tree(), 0));
  for (int e = 0; e < 60; ++e) {
    auto leaves = in.tree().leaves();
    auto merge = in.tree().mergeable();
    int kind = static_cast<int>(rng() % 3);
    if (kind == 0) in.set(leaves[rng() % leaves.size()], static_cast<long long>(rng() % 100));
    else if (kind == 1 || merge.empty()) in.split(leaves[rng() % leaves.size()], static_cast<int>(rng() % 3), static_cast<long long>(rng() % 100));
    else in.merge(merge[rng() % merge.size()]);
    in.propagate();
    ASSERT_EQ(rt.deref(out), eval_rec(in.tree(), 0)) << "edit " << e;
    Runtime fresh;
    TreeInput in2(fresh, in.tree());
    sa_exptree(fresh, in2.root());
    ASSERT_EQ(rt.signature(), fresh.signature()) << "edit " << e;
    ASSERT_EQ(rt.stats().trace_nodes, fresh.stats().trace_nodes);
    ASSERT_EQ(rt.stats().live_mods, fresh.stats().live_mods);
  }
}

// The benchmark's memory guard: estimates grow like the traces do, and a size that cannot fit is
// refused with an InputError naming the program, n and the availability.
TEST(SacBenchGuard, EstimatesScaleAndHugeSizesAreRefused) {
  double map6 = estimate_bench_bytes("map", 1000000, 20121);
  EXPECT_GT(map6, 1e8);   // at least ~100 bytes per element
  EXPECT_LT(map6, 5e9);   // and not absurd for a linear program
  double qs5 = estimate_bench_bytes("quicksort", 100000, 20121), qs6 = estimate_bench_bytes("quicksort", 1000000, 20121);
  EXPECT_GT(qs6, 10 * qs5);  // Θ(n log n) trace: more than linear growth
  EXPECT_NO_THROW(check_bench_memory("quicksort", kBenchProbeBelow, 20121));  // small sizes: no check
  if (available_memory() == 0) GTEST_SKIP() << "no /proc/meminfo";
  try {
    check_bench_memory("quicksort", 100000000, 20121);
    FAIL() << "quicksort at 10^8 was not refused";
  } catch (const kmr::InputError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("quicksort at n=100000000"), std::string::npos) << what;
    EXPECT_NE(what.find("available"), std::string::npos) << what;
  }
}

}  // namespace
