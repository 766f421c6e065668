// The lean trace (issue 8 §2, spec/sac.md "Issue 8 §2, third pass"): memo_read, the memo_box call
// whose body is one read, fused into one trace node with its destination's write recorded inline.
// Each test compares against an independent expectation: a plain loop, or a from-scratch runtime.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "exact/error.hpp"
#include "sac/runtime.hpp"
#include "error_of.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kIn{"in"}, kStart{"start"}, kOut{"out"}, kMapL{"lean.map"}, kSuf{"lean.suffix"};

using kmr::sac::test::error_of;

struct Link {  // a cell of map's output: value and the next cell (by name in the signature)
  long long v = 0;
  Mod<Link>* next = nullptr;
  bool operator==(const Link&) const = default;
};
std::uint64_t canon_value(const Link& l) { return mix(mix(0x11, static_cast<std::uint64_t>(l.v)), canon_key(l.next)); }

// Over inputs a[0..n) and a start index s (an input), the program computes
//  * map(i) = memo_read of a[i]: Link{3 a[i] + 1, map(i + 1)} (its destination written inline by its
//    own closure), and a keyed cell Link{-1} at i = n;
//  * suffix(i) = memo_read of a[i]: a[i] + suffix(i + 1), its destination written inside a nested
//    read (an ordinary write node); a[n-1] at i = n - 1;
// and, inside a read of s: out_map = map(s), out_sum = suffix(s) (s < n).
struct Chain {
  Runtime rt;
  int n;
  std::vector<Mod<long long>*> a;
  Mod<int>* start;
  Mod<Mod<Link>*>* out_map = nullptr;
  Mod<long long>* out_sum = nullptr;
  Mod<Link>* map(int i) {
    if (i == n) {
      auto* m = rt.alloc<Link>(kOut, 7);
      rt.write(m, Link{-1, nullptr});
      return m;
    }
    return rt.memo_read<Link>(kMapL, i, a[i], [this, i](const long long& v, Mod<Link>* dest) {
      rt.write(dest, Link{3 * v + 1, map(i + 1)});
    });
  }
  Mod<long long>* suffix(int i) {
    return rt.memo_read<long long>(kSuf, i, a[i], [this, i](const long long& v, Mod<long long>* dest) {
      if (i == n - 1) {
        rt.write(dest, v);
        return;
      }
      rt.read(suffix(i + 1), [this, v, dest](const long long& w) { rt.write(dest, v + w); });
    });
  }
  Chain(const std::vector<long long>& values, int s) : n(static_cast<int>(values.size())) {
    for (int i = 0; i < n; ++i) a.push_back(rt.input<long long>(kIn, static_cast<std::uint64_t>(i), values[i]));
    start = rt.input<int>(kStart, 0, s);
    rt.run([this] {
      out_map = rt.alloc<Mod<Link>*>(kOut, 1);
      out_sum = rt.alloc<long long>(kOut, 2);
      rt.read(start, [this](const int& s) {
        rt.write(out_map, map(s));
        rt.read(suffix(s), [this](const long long& w) { rt.write(out_sum, w); });
      });
      return 0;
    });
  }
  std::vector<long long> mapped() const {  // through deref: no trace
    std::vector<long long> r;
    for (const Mod<Link>* m = rt.deref(out_map); m; m = rt.deref(m).next) r.push_back(rt.deref(m).v);
    return r;
  }
};

// The expectation by plain loops (no runtime).
std::vector<long long> expected_map(const std::vector<long long>& v, int s) {
  std::vector<long long> r;
  for (std::size_t i = static_cast<std::size_t>(s); i < v.size(); ++i) r.push_back(3 * v[i] + 1);
  r.push_back(-1);
  return r;
}
long long expected_sum(const std::vector<long long>& v, int s) {
  long long t = 0;
  for (std::size_t i = static_cast<std::size_t>(s); i < v.size(); ++i) t += v[i];
  return t;
}

TEST(SacLeanTrace, S1_3_MemoReadMatchesLoopsAndFromScratchUnderEdits) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  std::mt19937_64 rng(8);  // seeded: the edit sequence is the same every run
  const int n = 40;
  std::vector<long long> v(n);
  for (auto& x : v) x = static_cast<long long>(rng() % 100);
  int s = 10;
  Chain c(v, s);
  std::uint64_t hits_before = 0;
  for (int step = 0; step < 60; ++step) {
    if (step % 3 == 2) {  // a new start: the root read re-runs; map/suffix calls after the old start are reused
      s = static_cast<int>(rng() % n);
      c.rt.change(c.start, s);
    } else {
      int i = static_cast<int>(rng() % n);
      v[static_cast<std::size_t>(i)] = static_cast<long long>(rng() % 100);
      c.rt.change(c.a[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(i)]);
    }
    c.rt.propagate();
    ASSERT_EQ(c.mapped(), expected_map(v, s)) << "step " << step;
    ASSERT_EQ(c.rt.deref(c.out_sum), expected_sum(v, s)) << "step " << step;
    Chain fresh(v, s);
    ASSERT_EQ(c.rt.signature(), fresh.rt.signature()) << "step " << step;
    ASSERT_EQ(c.rt.stats().trace_nodes, fresh.rt.stats().trace_nodes) << "step " << step;
    ASSERT_EQ(c.rt.stats().live_mods, fresh.rt.stats().live_mods) << "step " << step;
  }
  EXPECT_GT(c.rt.stats().memo_hits, hits_before);  // moving the start earlier reused fused nodes
}

// One memo_read node per call plus its end: the trace of map(0..n) is 2 nodes per element.
TEST(SacLeanTrace, MemoReadIsOneNodeAndOneEnd) {
  std::vector<long long> v(25, 1);
  Chain c(v, 0);
  // root read + end, out allocs (2), out_map write, the i = n cell's alloc + write, out_sum's read,
  // end and write; map: 2 per element; suffix: memo_read + end + nested read + end + write per
  // element but the last (memo_read + end).
  const std::uint64_t expected = 2 + 2 + 1 + 2 + 3 + 2 * 25 + (5 * 24 + 2);
  EXPECT_EQ(c.rt.stats().trace_nodes, expected);
}

// A memo_read closure that reads its destination before writing it: an error in re-execution as in
// the initial run (the inline write of the execution being replaced does not count).
TEST(SacLeanTrace, MisuseReadingTheDestinationBeforeItsWriteInReexecution) {
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  rt.run([&] {
    rt.memo_read<int>(kMapL, 0, x, [&rt](const int& v, Mod<int>* dest) {
      if (v > 0) rt.read(dest, [](const int&) {});
      rt.write(dest, v);
    });
    return 0;
  });
  rt.change(x, 1);
  EXPECT_NE(error_of([&] { rt.propagate(); }).find("before it was written"), std::string::npos);
}

// The inline write keeps its exact time: a nested read that re-execution newly makes read the
// destination before the closure's write is refused, as with a write node.
TEST(SacLeanTrace, MisuseNestedReadOfTheDestinationBeforeItsInlineWrite) {
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 5);
  auto* b = rt.input<int>(kIn, 2, 0);
  rt.run([&] {
    rt.memo_read<int>(kMapL, 0, x, [&rt, b](const int& v, Mod<int>* dest) {
      rt.read(b, [&rt, dest](const int& w) {
        if (w > 0) rt.read(dest, [](const int&) {});
      });
      rt.write(dest, v);
    });
    return 0;
  });
  rt.change(b, 1);  // only the nested read re-runs; it now reads dest before dest's write
  EXPECT_NE(error_of([&] { rt.propagate(); }).find("before it was written"), std::string::npos);
}

TEST(SacLeanTrace, MisuseWritingTheDestinationTwice) {
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  auto twice = [&rt](const int& v, Mod<int>* dest) {
    rt.write(dest, v);
    if (v != 1) rt.write(dest, v + 1);
  };
  EXPECT_NE(error_of([&] { rt.run([&] { return rt.memo_read<int>(kMapL, 0, x, twice); }); }).find("written twice"),
            std::string::npos);
  Runtime rt2;
  auto* y = rt2.input<int>(kIn, 1, 1);
  rt2.run([&] { return rt2.memo_read<int>(kMapL, 0, y, [&rt2](const int& v, Mod<int>* dest) {
    rt2.write(dest, v);
    if (v != 1) rt2.write(dest, v + 1);
  }); });
  rt2.change(y, 2);  // re-execution writes twice
  EXPECT_NE(error_of([&] { rt2.propagate(); }).find("written twice"), std::string::npos);
}

// Re-execution that no longer writes the destination while a live read still depends on it.
TEST(SacLeanTrace, MisuseDestinationLosingItsWriteWhileRead) {
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 1);
  rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    Mod<int>* d = rt.memo_read<int>(kMapL, 0, x, [&rt](const int& v, Mod<int>* dest) {
      if (v > 0) rt.write(dest, v);
    });
    rt.read(d, [&rt, o](const int& w) { rt.write(o, w); });
    return o;
  });
  rt.change(x, 0);
  EXPECT_NE(error_of([&] { rt.propagate(); }).find("lost its write"), std::string::npos);
}

}  // namespace
