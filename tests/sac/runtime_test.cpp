// The sac runtime's guarantees (sac/runtime.hpp): equal writes, memo reuse only inside the
// re-executed interval, keyed allocation, undo hooks, traceable values, live counts, misuse errors.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <string>

#include "exact/error.hpp"
#include "sac/asan.hpp"
#include "sac/runtime.hpp"
#include "error_of.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kIn{"in"}, kOut{"out"}, kG{"g"}, kCell{"cell"}, kHook{"hook"}, kF{"f"};

using kmr::sac::test::error_of;

// The ContractError message (or "") of running body inside rt.run.
template <class F>
std::string error_in_run(Runtime& rt, F&& body) {
  return error_of([&] {
    rt.run([&] {
      body();
      return 0;
    });
  });
}

TEST(SacRuntime, S1_3_EqualWriteDirtiesNothing) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 5);
  int runs = 0;
  auto* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(in, [&rt, o, &runs](int x) {
      ++runs;
      rt.write(o, x % 2);
    });
    return o;
  });
  rt.change(in, 5);  // equal: nothing queued
  EXPECT_EQ(rt.queued(), 0u);
  rt.propagate();
  EXPECT_EQ(runs, 1);
  rt.change(in, 7);  // different input, equal output: the reader re-runs, the output's readers do not
  rt.propagate();
  EXPECT_EQ(runs, 2);
  EXPECT_EQ(rt.deref(out), 1);
  EXPECT_EQ(rt.stats().reads_reexecuted, 1u);
}

TEST(SacRuntime, S1_3_MemoReusedInsideReexecutedInterval) {
  RecordProperty("claim", "S1.3.2-monotone-reuse");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  int g_runs = 0;
  auto g = [&](int k) {
    return rt.memo<int>(kG, k, [&, k] {
      ++g_runs;
      return k * 10;
    });
  };
  auto* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(in, [&, o](int x) { rt.write(o, x + g(7)); });
    return o;
  });
  EXPECT_EQ(g_runs, 1);
  rt.change(in, 1);
  rt.propagate();
  EXPECT_EQ(g_runs, 1) << "g(7) lies inside the re-executed read: it must be reused";
  EXPECT_EQ(rt.stats().memo_hits, 1u);
  EXPECT_EQ(rt.deref(out), 71);
}

TEST(SacRuntime, S1_3_MemoNotReusedOutsideReexecutedInterval) {
  RecordProperty("claim", "S1.3.2-monotone-reuse");
  Runtime rt;
  auto* m1 = rt.input<int>(kIn, 1, 1);
  auto* m2 = rt.input<int>(kIn, 2, 0);
  int g_runs = 0;
  auto g = [&](int k) {
    return rt.memo<int>(kG, k, [&, k] {
      ++g_runs;
      return k;
    });
  };
  rt.run([&] {
    rt.read(m1, [&](int x) {
      if (x) g(5);
    });
    rt.read(m2, [&](int x) {
      if (x) g(5);
    });
    return 0;
  });
  EXPECT_EQ(g_runs, 1);
  // The initial run never reuses: a second call with the same key inside one run executes.
  rt.run([&] {
    g(5);
    return 0;
  });
  EXPECT_EQ(g_runs, 2);
  // Re-executing the read of m2: g(5) exists, but only before the interval: it must run again.
  rt.change(m2, 1);
  rt.propagate();
  EXPECT_EQ(g_runs, 3);
  EXPECT_EQ(rt.stats().memo_hits, 0u);
}

TEST(SacRuntime, S1_3_KeyedAllocationReturnsSameModifiable) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 3);
  Mod<int>* first = nullptr;
  Mod<int>* second = nullptr;
  rt.run([&] {
    rt.read(in, [&](int x) {
      auto* c = rt.alloc<int>(kCell, 42);
      rt.write(c, x);
      (first ? second : first) = c;
    });
    return 0;
  });
  rt.change(in, 4);
  rt.propagate();
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(first, second);
  EXPECT_EQ(rt.deref(second), 4);
  EXPECT_EQ(rt.stats().allocs_reused, 1u);
}

TEST(SacRuntime, S1_3_UndoHooksRunWhenTraceIsDiscarded) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 2);
  int created = 0, released = 0;
  rt.run([&] {
    rt.read(in, [&](int x) {
      for (int i = 0; i < x; ++i) {
        ++created;
        rt.on_discard(kHook, [&released] { ++released; });
      }
    });
    return 0;
  });
  EXPECT_EQ(created, 2);
  rt.change(in, 3);
  rt.propagate();
  EXPECT_EQ(created, 5);
  EXPECT_EQ(released, 2) << "the two hooks of the discarded execution run, the new three do not";
  EXPECT_EQ(rt.stats().hooks_run, 2u);
  rt.reset();
  EXPECT_EQ(released, 5);
  EXPECT_EQ(rt.stats().trace_nodes, 0u);
  EXPECT_EQ(rt.stats().live_mods, 0u);
}

TEST(SacRuntime, S1_3_TraceableValueWrittenByItsOwner) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  // A kinetic certificate's outcome: the computation reads it; the owner flips it and propagates;
  // the computation that depended on the old outcome releases what it created.
  Runtime rt;
  Traceable<bool> cert(rt, kIn, 9, true);
  int live_resources = 0;
  auto* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(cert.mod(), [&, o](bool ok) {
      ++live_resources;
      rt.on_discard(kHook, [&live_resources] { --live_resources; });
      rt.write(o, ok ? 1 : -1);
    });
    return o;
  });
  EXPECT_EQ(rt.deref(out), 1);
  cert.set(false);
  rt.propagate();
  EXPECT_EQ(rt.deref(out), -1);
  EXPECT_EQ(live_resources, 1);
  EXPECT_FALSE(cert.get());
}

TEST(SacRuntime, S1_3_LiveCountsReturnAfterUndoingAnEdit) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 10);
  rt.run([&] {
    rt.read(in, [&](int n) {
      for (int i = 0; i < n; ++i) {
        auto* c = rt.alloc<int>(kCell, i);
        rt.write(c, i * n);
      }
    });
    return 0;
  });
  auto before = rt.stats();
  std::string sig = rt.signature();
  rt.change(in, 3);
  rt.propagate();
  EXPECT_LT(rt.stats().trace_nodes, before.trace_nodes);
  rt.change(in, 10);
  rt.propagate();
  EXPECT_EQ(rt.stats().trace_nodes, before.trace_nodes);
  EXPECT_EQ(rt.stats().live_mods, before.live_mods);
  EXPECT_EQ(rt.signature(), sig);
}

TEST(SacRuntime, MisuseReadingUnwrittenModifiable) {
  Runtime rt;
  std::string e = error_in_run(rt, [&] {
    auto* c = rt.alloc<int>(kCell, 1);
    rt.read(c, [](int) {});
  });
  EXPECT_NE(e.find("before it was written"), std::string::npos) << e;
}

TEST(SacRuntime, MisuseWritingTwice) {
  Runtime rt;
  std::string e = error_in_run(rt, [&] {
    auto* c = rt.alloc<int>(kCell, 1);
    rt.write(c, 1);
    rt.write(c, 2);
  });
  EXPECT_NE(e.find("written twice"), std::string::npos) << e;
}

TEST(SacRuntime, MisuseAllocationKeyUsedTwiceInOneExecution) {
  Runtime rt;
  std::string e = error_in_run(rt, [&] {
    rt.alloc<int>(kCell, 7);
    rt.alloc<int>(kCell, 7);
  });
  EXPECT_NE(e.find("used twice in one execution"), std::string::npos) << e;
}

TEST(SacRuntime, MisuseWritingAnInputInsideARun) {
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  std::string e = error_in_run(rt, [&] {
    rt.write(in, 1);
  });
  EXPECT_NE(e.find("input modifiable"), std::string::npos) << e;
}

TEST(SacRuntime, MisusePropagatingOrChangingDuringARun) {
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  std::string e1 = error_in_run(rt, [&] {
    rt.propagate();
  });
  EXPECT_NE(e1.find("propagate during a run"), std::string::npos) << e1;
  Runtime rt2;
  auto* in2 = rt2.input<int>(kIn, 1, 0);
  std::string e2 = error_in_run(rt2, [&] {
    rt2.change(in2, 3);
  });
  EXPECT_NE(e2.find("change during a run"), std::string::npos) << e2;
  (void)in;
}

TEST(SacRuntime, MisuseTraceOperationsOutsideARunOrInAnUndoHook) {
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  std::string e1 = error_of([&] { rt.read(in, [](int) {}); });
  EXPECT_NE(e1.find("outside a run"), std::string::npos) << e1;
  rt.run([&] {
    rt.read(in, [&](int) { rt.on_discard(kHook, [&] { rt.alloc<int>(kCell, 1); }); });
    return 0;
  });
  rt.change(in, 1);
  std::string e2 = error_of([&] { rt.propagate(); });
  EXPECT_NE(e2.find("inside an undo hook"), std::string::npos) << e2;
}

TEST(SacRuntime, MisuseReleasingAnInputStillRead) {
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  rt.run([&] {
    rt.read(in, [](int) {});
    return 0;
  });
  std::string e = error_of([&] { rt.release(in); });
  EXPECT_NE(e.find("still reads"), std::string::npos) << e;
}

TEST(SacRuntime, S1_3_SignatureNamesModifiablesByKeysNotAddresses) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  // Two runtimes, same program and input names: same signature, though every address differs.
  auto build = [](Runtime& rt, int pad) {
    std::vector<Mod<int>*> junk;
    for (int i = 0; i < pad; ++i) junk.push_back(rt.input<int>(kF, 1000 + i, i));  // shifts addresses
    auto* in = rt.input<int>(kIn, 1, 4);
    rt.run([&] {
      rt.read(in, [&](int n) {
        for (int i = 0; i < n; ++i) rt.memo<int>(kG, i, [&, i] {
          auto* c = rt.alloc<int>(kCell, i);
          rt.write(c, i);
          return i;
        });
      });
      return 0;
    });
    return rt.signature();
  };
  Runtime a, b;
  std::string sa = build(a, 0), sb = build(b, 37);
  EXPECT_EQ(sa, sb);
  EXPECT_NE(sa.find("Mg:"), std::string::npos);
}

}  // namespace

namespace {

// ΔML's IBox: written several times in one execution; a read sees the latest write before it.
TEST(SacRuntime, S1_3_ImperativeModifiableReadsSeeTheLatestEarlierWrite) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  std::vector<int> seen;
  rt.run([&] {
    auto* m = rt.ialloc<int>(kCell, 7, 1);
    rt.iread(m, [&](int v) { seen.push_back(v); });
    rt.iwrite(m, 1);
    rt.iread(m, [&](int v) { seen.push_back(v); });
    rt.iwrite(m, 2);
    rt.iwrite(m, 3);
    rt.iread(m, [&](int v) { seen.push_back(v); });
    return 0;
  });
  EXPECT_EQ(seen, (std::vector<int>{7, 1, 3}));
}

// A program whose IBox writes come and go with the input; after every propagation the output and
// the trace equal a from-scratch run's.
struct ImperativeProgram {
  Runtime rt;
  Mod<int>* x;
  Mod<int>* y;
  Mod<int>* out = nullptr;
  ImperativeProgram(int xv, int yv) : x(rt.input<int>(kIn, 1, xv)), y(rt.input<int>(kIn, 2, yv)) {
    out = rt.run([this] {
      auto* m = rt.ialloc<int>(kCell, -1, 1);
      auto* o = rt.alloc<int>(kOut);
      rt.read(x, [this, m](int v) {
        if (v > 0) rt.iwrite(m, v);  // a write that exists only for positive x
      });
      rt.read(y, [this, m](int v) { rt.iwrite(m, v * 100); });
      rt.iread(m, [this, o](int v) { rt.write(o, v); });
      return o;
    });
  }
};

TEST(SacRuntime, S1_3_ImperativeModifiablePropagationEqualsFromScratch) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  ImperativeProgram p(3, 0);
  EXPECT_EQ(p.rt.deref(p.out), 0);
  const std::vector<std::pair<int, int>> steps{{3, 2}, {0, 2}, {5, 2}, {5, 0}, {-1, 4}, {2, 4}};
  for (auto [xv, yv] : steps) {
    p.rt.change(p.x, xv);
    p.rt.change(p.y, yv);
    p.rt.propagate();
    ImperativeProgram fresh(xv, yv);
    EXPECT_EQ(p.rt.deref(p.out), yv * 100);
    EXPECT_EQ(p.rt.signature(), fresh.rt.signature()) << xv << "," << yv;
    EXPECT_EQ(p.rt.stats().trace_nodes, fresh.rt.stats().trace_nodes);
    EXPECT_EQ(p.rt.stats().live_mods, fresh.rt.stats().live_mods);
  }
}

TEST(SacRuntime, S1_3_ImperativeModifiableLastWriteRemoved) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  // The read after the only write falls back to the initial value when the write is discarded.
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 4);
  auto* out = rt.run([&] {
    auto* m = rt.ialloc<int>(kCell, 9, 1);
    auto* o = rt.alloc<int>(kOut);
    rt.read(x, [&rt, m](int v) {
      if (v) rt.iwrite(m, v);
    });
    rt.iread(m, [&rt, o](int v) { rt.write(o, v); });
    return o;
  });
  EXPECT_EQ(rt.deref(out), 4);
  rt.change(x, 0);
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 9);
  rt.change(x, 6);
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 6);
  rt.reset();
  EXPECT_EQ(rt.stats().trace_nodes, 0u);
  EXPECT_EQ(rt.stats().live_mods, 0u);
}

// Warm memory (issue 9, spec/sac.md "Warm memory"): the pool chunks of a runtime that ended are
// kept for the next runtime on the thread, so building the same trace again faults in far fewer
// fresh pages (judged by the process's minor page faults: ≈ 17 MB of trace is ≈ 4 000 pages the
// first time; without the kept chunks the second build faults them in again).
TEST(SacRuntime, S1_3_ChunksOfAnEndedRuntimeAreReusedWarm) {
#ifdef KMR_ASAN
  GTEST_SKIP() << "AddressSanitizer build: no chunk is kept, so ASan sees a dead runtime's memory freed (runtime.cpp)";
#endif
  auto faults = [] {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
  };
  auto build = [] {
    Runtime rt;
    rt.run([&rt] {
      for (int i = 0; i < 100000; ++i) rt.write(rt.alloc<long long>(kCell, i), static_cast<long long>(i));
    });
    return rt.stats().bytes;
  };
  const long f0 = faults();
  const auto bytes = build();
  const long first = faults() - f0;
  const long f1 = faults();
  EXPECT_EQ(build(), bytes);
  const long second = faults() - f1;
  EXPECT_GE(bytes, std::uint64_t{8} << 20);
  EXPECT_GE(first, 2000);  // 4 KiB pages
  EXPECT_LT(second, first / 2) << "the second runtime should take the first one's warm chunks";
}

}  // namespace

namespace {

// Names (issue 9's cheaper keyed allocation changed how they are computed, not what they are): a
// keyed allocation is named by the mix chain of its label's hash and its keys (sac::alloc_name);
// fresh allocations inside a read of m by (label, mix(m's name, 0x52ead), ordinal), inside a memo
// call by (label, the call's key hash, ordinal). Expectations computed here from those formulas.
TEST(SacRuntime, S1_3_AllocationAndFreshNamesFollowTheirFormulas) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 3);
  Mod<int>* keyed = nullptr;
  Mod<int>* in_read[2] = {};
  Mod<int>* in_memo = nullptr;
  rt.run([&] {
    keyed = rt.alloc<int>(kCell, 7, 9);
    rt.write(keyed, 1);
    rt.read(in, [&](int) {
      in_read[0] = rt.put<int>(kF, 1);
      rt.memo<int>(kG, 5, [&] {
        in_memo = rt.put<int>(kF, 2);
        return 0;
      });
      in_read[1] = rt.put<int>(kF, 3);  // the read's scope again after the memo call's
    });
    return 0;
  });
  EXPECT_EQ(keyed->name, mix(mix(kCell.hash, 7), 9));
  EXPECT_EQ(keyed->name, alloc_name(kCell, 7, 9));
  const std::uint64_t read_scope = mix(in->name, 0x52ead);
  EXPECT_EQ(in_read[0]->name, mix(mix(kF.hash, read_scope), 0));
  EXPECT_EQ(in_read[1]->name, mix(mix(kF.hash, read_scope), 1));
  EXPECT_EQ(in_memo->name, mix(mix(kF.hash, mix(kG.hash, 5)), 0));
}

// reserve_keys (issue 9): the key index sized up front, before a run or with entries in it (a
// one-pass rehash), changes no lookup: every keyed allocation of a re-executed read is reused and
// the trace equals an unreserved runtime's and a from-scratch run's.
TEST(SacRuntime, S1_3_ReservedKeyIndexChangesNoReuse) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  constexpr int kCells = 3000;  // three doublings of the default 1024 buckets
  auto program = [](Runtime& rt, Mod<int>* in) {
    rt.run([&] {
      rt.read(in, [&rt](int x) {
        for (int i = 0; i < kCells; ++i) rt.write(rt.alloc<int>(kCell, i, i % 7), x + i);
      });
      return 0;
    });
  };
  for (int mode = 0; mode < 3; ++mode) {  // 0: no reserve; 1: before the run; 2: between run and propagation
    SCOPED_TRACE("mode " + std::to_string(mode));
    Runtime rt;
    auto* in = rt.input<int>(kIn, 1, 1);
    if (mode == 1) rt.reserve_keys(5000);
    program(rt, in);
    if (mode == 2) rt.reserve_keys(1 << 14);
    rt.change(in, 2);
    rt.propagate();
    EXPECT_EQ(rt.stats().allocs_reused, static_cast<std::uint64_t>(kCells));
    EXPECT_EQ(rt.stats().live_mods, static_cast<std::uint64_t>(kCells));
    Runtime scratch;
    program(scratch, scratch.input<int>(kIn, 1, 2));
    EXPECT_EQ(rt.signature(), scratch.signature());
  }
}

}  // namespace
