// The runtime features the Appendix A.2 hull needs (issue 8 §1), one deterministic scenario each,
// checked against hand-derived values and from-scratch runs: certificates created in a run, undo
// hook identity and order, destination-passing memo, a write that moves earlier, fresh
// allocations, full-key allocation reuse, values in the signature.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "exact/error.hpp"
#include "sac/runtime.hpp"
#include "sacprograms/generality.hpp"
#include "error_of.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kIn{"in"}, kOut{"out"}, kCert{"cert"}, kHook{"hook"}, kBox{"box"}, kG{"g"}, kCell{"cell"};

using kmr::sac::test::error_of;

// §1 item 1: a certificate allocated inside the run under a key, set by its owner between runs.
struct CertProgram {
  Runtime rt;
  Mod<int>* n;
  std::map<int, bool> truth;           // the owner's
  std::map<int, Mod<bool>*> certs;     // the owner's handles (last created)
  Mod<int>* out = nullptr;
  explicit CertProgram(int count, std::map<int, bool> t = {}) : n(rt.input<int>(kIn, 1, count)), truth(std::move(t)) {
    out = rt.run([this] {
      auto* o = rt.alloc<int>(kOut);
      rt.read(n, [this, o](int k) {
        // certificates for 0..k-1, each read; the output is the number that hold
        std::vector<Mod<bool>*> cs;
        for (int i = 0; i < k; ++i) {
          Mod<bool>* c = rt.traceable<bool>(kCert, truth.count(i) ? truth[i] : true, i);
          certs[i] = c;
          cs.push_back(c);
        }
        this->count(cs, 0, 0, o);
      });
      return o;
    });
  }
  void count(std::vector<Mod<bool>*> cs, std::size_t i, int acc, Mod<int>* o) {
    if (i == cs.size()) {
      rt.write(o, acc);
      return;
    }
    rt.read(cs[i], [this, cs, i, acc, o](bool b) { count(cs, i + 1, acc + (b ? 1 : 0), o); });
  }
  void set(int i, bool v) {
    truth[i] = v;
    rt.change(certs.at(i), v);
  }
};

TEST(SacGenerality, S1_3_CertificateCreatedInRunIsReusedAndSetByItsOwner) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  CertProgram p(3);
  EXPECT_EQ(p.rt.deref(p.out), 3);
  Mod<bool>* c1 = p.certs.at(1);
  p.set(1, false);
  p.rt.propagate();
  EXPECT_EQ(p.rt.deref(p.out), 2);
  // Re-executing the creating read (n changes) reuses the certificates by key, with the owner's value.
  p.rt.change(p.n, 4);
  p.rt.propagate();
  EXPECT_EQ(p.certs.at(1), c1) << "same key inside the re-executed interval: same traceable";
  EXPECT_FALSE(p.rt.deref(c1));
  EXPECT_EQ(p.rt.deref(p.out), 3);
  EXPECT_GE(p.rt.stats().allocs_reused, 3u);
  CertProgram fresh(4, p.truth);
  EXPECT_EQ(p.rt.signature(), fresh.rt.signature());
  EXPECT_EQ(p.rt.stats().live_mods, fresh.rt.stats().live_mods);
  // The value is part of the signature: a stale certificate would show.
  CertProgram other(4);
  EXPECT_NE(p.rt.signature(), other.rt.signature());
}

TEST(SacGenerality, MisuseWritingATraceableInsideARun) {
  Runtime rt;
  std::string e = error_of([&] {
    rt.run([&] {
      auto* c = rt.traceable<bool>(kCert, true, 1);
      rt.write(c, false);
      return 0;
    });
  });
  EXPECT_NE(e.find("its owner sets it"), std::string::npos) << e;
}

TEST(SacGenerality, TraceableOutsideARunIsAnInput) {
  Runtime rt;
  Traceable<int> t(rt, kCert, 5, 7);
  EXPECT_EQ(rt.stats().input_mods, 1u);
  Mod<int>* inside = nullptr;
  rt.run([&] {
    Traceable<int> u(rt, kCert, 6, 8);  // inside a run: keyed, owned by the trace
    inside = u.mod();
    return 0;
  });
  EXPECT_EQ(rt.stats().input_mods, 1u);
  EXPECT_EQ(rt.stats().live_mods, 1u);
  EXPECT_EQ(rt.deref(inside), 8);
  EXPECT_EQ(t.get(), 7);
}

// §1 item 2: the replacement registers before the predecessor's hook runs; identity keeps it.
TEST(SacGenerality, S1_3_CertificateRecreatedUnderSameKeySurvivesDiscardOfItsPredecessor) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  struct Reg {
    Mod<bool>* cert;
    HookId hook;
  };
  std::map<int, Reg> registry;  // the simulator's, by certificate name
  std::vector<std::string> events;
  rt.run([&] {
    rt.read(x, [&](int v) {
      Mod<bool>* c = rt.traceable<bool>(kCert, true, 7);
      HookId id = rt.on_discard(kHook, [&registry, &events](HookId self) {
        events.push_back("undo#" + std::to_string(self));
        auto r = registry.find(7);
        if (r != registry.end() && r->second.hook == self) registry.erase(r);
      });
      registry[7] = Reg{c, id};
      events.push_back("register#" + std::to_string(id) + ":" + std::to_string(v));
    });
    return 0;
  });
  Mod<bool>* first = registry.at(7).cert;
  rt.change(x, 1);
  rt.propagate();
  // Specified order (spec/sac.md): the re-executed code runs first, the discarded hook after it.
  EXPECT_EQ(events, (std::vector<std::string>{"register#1:0", "register#2:1", "undo#1"}));
  ASSERT_EQ(registry.count(7), 1u) << "the re-created certificate must survive its predecessor's hook";
  EXPECT_EQ(registry.at(7).hook, 2u);
  EXPECT_EQ(registry.at(7).cert, first);
  rt.reset();
  EXPECT_EQ(registry.count(7), 0u);
}

TEST(SacGenerality, S1_3_HooksOfDiscardedTraceRunInTimeOrder) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 4);
  std::vector<int> undone;
  rt.run([&] {
    rt.read(x, [&](int n) {
      for (int i = 0; i < n; ++i) rt.on_discard(kHook, [&undone, i, n] { undone.push_back(n * 10 + i); });
    });
    return 0;
  });
  rt.change(x, 2);
  rt.propagate();
  EXPECT_EQ(undone, (std::vector<int>{40, 41, 42, 43}));
}

// §1 item 3: the memoized call's result depends on a read inside it.
TEST(SacGenerality, S1_3_DestinationMemoResultFollowsItsReads) {
  RecordProperty("claim", "S1.3.2-monotone-reuse");
  Runtime rt;
  std::vector<Mod<int>*> a;
  for (int i = 0; i < 4; ++i) a.push_back(rt.input<int>(kIn, i, 0));
  int bodies = 0;
  // first(i) = the first nonzero a[j], j ≥ i (or -1), by destination-passing memo.
  std::function<Mod<int>*(int)> first = [&](int i) -> Mod<int>* {
    return rt.memo_box<int>(kBox, i, [&, i](Mod<int>* dest) {
      ++bodies;
      if (i == 4) {
        rt.write(dest, -1);
        return;
      }
      rt.read(a[i], [&, i, dest](int v) {
        if (v) rt.write(dest, v);
        else rt.read(first(i + 1), [&rt, dest](int w) { rt.write(dest, w); });
      });
    });
  };
  auto* g = rt.input<int>(kIn, 99, 0);
  Mod<int>* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(g, [&, o](int) { rt.read(first(0), [&rt, o](int w) { rt.write(o, w); }); });
    return o;
  });
  EXPECT_EQ(rt.deref(out), -1);
  EXPECT_EQ(bodies, 5);
  rt.change(a[2], 7);  // the read inside first(2) re-runs; first(0) and first(1) are not re-called
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 7);
  EXPECT_EQ(bodies, 5);
  rt.change(g, 1);  // re-executes the caller: first(0) is reused, with its current result
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 7);
  EXPECT_EQ(rt.stats().memo_hits, 1u);
  EXPECT_EQ(bodies, 5);
}

// §1 item 4: a write that moves earlier than the write it replaces (CEAL accepts it).
struct TwoPass {
  Runtime rt;
  Mod<int>* x;
  Mod<int>* out = nullptr;
  explicit TwoPass(int xv) : x(rt.input<int>(kIn, 1, xv)) {
    out = rt.run([this] {
      auto* o = rt.alloc<int>(kOut);
      auto* found = rt.alloc<bool>(kOut, 2);
      rt.read(x, [this, o, found](int v) {
        if (v > 0) rt.write(o, v);
        rt.write(found, v > 0);
      });
      rt.read(found, [this, o](bool f) {
        if (!f) rt.write(o, -100);  // the later write, when the first pass wrote nothing
      });
      return o;
    });
  }
};

TEST(SacGenerality, S1_3_WriteMovingEarlierIsAcceptedAndTheLaterOneRemoved) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  TwoPass p(0);
  EXPECT_EQ(p.rt.deref(p.out), -100);
  p.rt.change(p.x, 5);
  p.rt.propagate();
  EXPECT_EQ(p.rt.deref(p.out), 5);
  EXPECT_EQ(p.rt.stats().writes_moved_earlier, 1u);
  TwoPass fresh5(5);
  EXPECT_EQ(p.rt.signature(), fresh5.rt.signature());
  EXPECT_EQ(p.rt.stats().trace_nodes, fresh5.rt.stats().trace_nodes);
  p.rt.change(p.x, -3);  // and back: the write moves later again
  p.rt.propagate();
  EXPECT_EQ(p.rt.deref(p.out), -100);
  TwoPass fresh0(-3);
  EXPECT_EQ(p.rt.signature(), fresh0.rt.signature());
}

TEST(SacGenerality, MisuseAMovedWriteWhoseLaterWriteStays) {
  // Inconsistent: the later write does not depend on what the earlier pass did.
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  auto* y = rt.input<int>(kIn, 2, 0);
  rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(x, [&rt, o](int v) {
      if (v > 0) rt.write(o, v);
    });
    rt.read(y, [&rt, o](int) { rt.write(o, -1); });
    return 0;
  });
  rt.change(x, 3);
  std::string e = error_of([&] { rt.propagate(); });
  EXPECT_NE(e.find("moved earlier but the later write is still in the trace"), std::string::npos) << e;
}

// §1 item 5: fresh allocations, several per execution, never reused, named canonically.
TEST(SacGenerality, S1_3_FreshAllocationsAreCanonicalAndNeverReused) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  auto build = [](Runtime& rt, Mod<int>* in, std::vector<Mod<int>*>* made) {
    rt.run([&rt, in, made] {
      rt.read(in, [&rt, made](int n) {
        for (int i = 0; i < n; ++i) made->push_back(rt.put<int>(kBox, i * i));
      });
      return 0;
    });
  };
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 3);
  std::vector<Mod<int>*> made;
  build(rt, in, &made);
  EXPECT_EQ(rt.stats().fresh_allocs, 3u);
  rt.change(in, 4);
  rt.propagate();
  ASSERT_EQ(made.size(), 7u);
  EXPECT_NE(made[3], made[0]) << "fresh allocations are not reused";
  EXPECT_EQ(rt.deref(made[6]), 9);
  EXPECT_EQ(rt.stats().live_mods, 4u);
  EXPECT_EQ(rt.stats().allocs_reused, 0u);
  Runtime fresh;
  auto* in2 = fresh.input<int>(kIn, 1, 4);
  std::vector<Mod<int>*> made2;
  build(fresh, in2, &made2);
  EXPECT_EQ(rt.signature(), fresh.signature());
  EXPECT_NE(rt.signature().find("F"), std::string::npos);
}

// §1 item 5: allocation reuse compares the full key, not its hash.
struct Colliding {
  int v;
  bool operator==(const Colliding&) const = default;
};
std::uint64_t canon_key(const Colliding&) { return 42; }  // every key has the same hash

TEST(SacGenerality, S1_3_AllocationReuseComparesTheFullKey) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* in = rt.input<int>(kIn, 1, 0);
  std::vector<std::pair<Mod<int>*, Mod<int>*>> seen;
  rt.run([&] {
    rt.read(in, [&](int v) {
      Mod<int>* a = rt.alloc<int>(kCell, Colliding{1});  // same hash, different keys: both allowed
      Mod<int>* b = rt.alloc<int>(kCell, Colliding{2});
      rt.write(a, v);
      rt.write(b, v + 1);
      seen.emplace_back(a, b);
    });
    return 0;
  });
  rt.change(in, 5);
  rt.propagate();
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[1].first, seen[0].first) << "key {1} gets key {1}'s modifiable";
  EXPECT_EQ(seen[1].second, seen[0].second);
  EXPECT_EQ(rt.deref(seen[1].first), 5);
  EXPECT_EQ(rt.deref(seen[1].second), 6);
  std::string e = error_of([&] {
    Runtime r2;
    r2.run([&] {
      r2.alloc<int>(kCell, Colliding{3});
      r2.alloc<int>(kCell, Colliding{3});
      return 0;
    });
  });
  EXPECT_NE(e.find("used twice in one execution"), std::string::npos) << e;
}

// §1 item 6: written values and memo results are in the signature.
TEST(SacGenerality, S1_3_SignatureIncludesWrittenValuesAndMemoResults) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  auto sig = [](int written, int result) {
    Runtime rt;
    rt.run([&] {
      auto* o = rt.alloc<int>(kOut);
      rt.write(o, written);
      rt.memo<int>(kG, 1, [result] { return result; });
      return 0;
    });
    return rt.signature();
  };
  EXPECT_EQ(sig(1, 2), sig(1, 2));
  EXPECT_NE(sig(1, 2), sig(3, 2)) << "a different written value under the same name";
  EXPECT_NE(sig(1, 2), sig(1, 4)) << "a different memo result under the same key";
}

// Review (issue 8 §1 item 5): memo reuse compares the full key, label included, not the label's
// hash (as allocation reuse does): two labels whose hashes collide are different calls.
TEST(SacGenerality, S1_3_MemoReuseComparesTheLabelNotItsHash) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Label la("memo-a"), lb("memo-b");
  lb.hash = la.hash;  // a 64-bit collision, forced
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  Mod<int>* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(x, [&, o](int v) {
      int r = v == 0 ? rt.memo<int>(la, 5, [] { return 1; }) : rt.memo<int>(lb, 5, [] { return 2; });
      rt.write(o, r);
    });
    return o;
  });
  EXPECT_EQ(rt.deref(out), 1);
  rt.change(x, 1);
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 2) << "memo-b must not reuse memo-a's call";
  EXPECT_EQ(rt.stats().memo_hits, 0u);
}

// Review (§1 item 1): a traceable's key used twice in one execution is a contract error, in the
// initial run and when the first creation reused the previous execution's traceable.
TEST(SacGenerality, MisuseATraceableKeyCreatedTwiceInOneExecution) {
  std::string e = error_of([&] {
    Runtime rt;
    rt.run([&] {
      rt.traceable<bool>(kCert, true, 7);
      rt.traceable<bool>(kCert, false, 7);
      return 0;
    });
  });
  EXPECT_NE(e.find("used twice in one execution"), std::string::npos) << e;
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 1);
  rt.run([&] {
    rt.read(x, [&](int v) {
      for (int i = 0; i < v; ++i) rt.traceable<bool>(kCert, true, 7);
    });
    return 0;
  });
  rt.change(x, 2);
  e = error_of([&] { rt.propagate(); });
  EXPECT_NE(e.find("used twice in one execution"), std::string::npos) << e;
}

// Review (§1 item 1): a key that named a plain allocation cannot come back as a traceable, nor a
// traceable's key as a plain allocation (which would then read the owner's value as if written).
TEST(SacGenerality, MisuseATraceableKeyReusedByAPlainAllocationOrBack) {
  for (int first = 0; first < 2; ++first) {
    Runtime rt;
    auto* x = rt.input<int>(kIn, 1, first);
    auto* o = rt.input<int>(kOut, 1, 0);
    (void)o;
    Mod<int>* out = rt.run([&] {
      auto* res = rt.alloc<int>(kOut, 0);
      rt.read(x, [&, res](int v) {
        Mod<bool>* c = v == 1 ? rt.traceable<bool>(kCert, true, 7) : rt.alloc<bool>(kCert, 7);
        if (v == 0) rt.write(c, false);
        rt.read(c, [&, res](bool b) { rt.write(res, b ? 1 : 0); });
      });
      return res;
    });
    EXPECT_EQ(rt.deref(out), first);
    rt.change(x, 1 - first);
    std::string e = error_of([&] { rt.propagate(); });
    EXPECT_NE(e.find(first == 0 ? "key reused by a plain allocation" : "key of a traceable reused by a plain allocation"),
              std::string::npos)
        << "first=" << first << ": " << e;
  }
}

// Review (§1 item 2): when a reused memo call lies between a certificate's old registration and
// its re-creation, the predecessor's hook runs at the memo hit, before the re-creation (the
// re-created certificate is then a new traceable); identity keeps the registry right either way.
TEST(SacGenerality, S1_3_HookBeforeAReusedMemoRunsBeforeTheRecreation) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 0);
  struct Reg {
    Mod<bool>* cert;
    HookId hook;
  };
  std::map<int, Reg> registry;
  std::vector<std::string> events;
  auto certificate = [&] {
    Mod<bool>* c = rt.traceable<bool>(kCert, true, 7);
    HookId id = rt.on_discard(kHook, [&registry, &events](HookId self) {
      events.push_back("undo#" + std::to_string(self));
      auto r = registry.find(7);
      if (r != registry.end() && r->second.hook == self) registry.erase(r);
    });
    registry[7] = Reg{c, id};
    events.push_back("register#" + std::to_string(id));
  };
  rt.run([&] {
    rt.read(x, [&](int v) {
      if (v == 0) certificate();  // before the memo call in the first execution
      rt.memo<int>(kG, 1, [] { return 0; });
      if (v == 1) certificate();  // after it in the second
    });
    return 0;
  });
  Mod<bool>* first = registry.at(7).cert;
  (void)first;
  rt.change(x, 1);
  rt.propagate();
  EXPECT_EQ(rt.stats().memo_hits, 1u);
  EXPECT_EQ(events, (std::vector<std::string>{"register#1", "undo#1", "register#2"}));
  ASSERT_EQ(registry.count(7), 1u);
  EXPECT_EQ(registry.at(7).hook, 2u);
}

// Review (§1 item 5): a modifiable read right after its write (ΔML `Box.put` then `Box.get`, the
// write the last trace operation) is written in this execution; it was refused as unwritten.
TEST(SacGenerality, S1_3_ReadRightAfterItsWrite) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 3);
  Mod<int>* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    rt.read(x, [&, o](int v) {
      Mod<int>* b = rt.put<int>(kBox, v * 2);
      rt.read(b, [&, o](int w) { rt.write(o, w + 1); });
    });
    return o;
  });
  EXPECT_EQ(rt.deref(out), 7);
  rt.change(x, 5);
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 11);
}

// Review (§1 items 3, 4): re-execution that drops a modifiable's only write while a read of it
// outside the re-executed interval stays live would leave that read on a stale value (a
// from-scratch run refuses the read as unwritten); propagate() reports it.
TEST(SacGenerality, MisuseAWriteDroppedWhileItsReadStays) {
  auto program = [](Runtime& rt, Mod<int>* x) {
    return rt.run([&rt, x] {
      auto* d = rt.alloc<int>(kBox);
      rt.read(x, [&rt, d](int v) {
        if (v > 0) rt.write(d, v);
      });
      auto* o = rt.alloc<int>(kOut);
      rt.read(d, [&rt, o](int w) { rt.write(o, w); });
      return o;
    });
  };
  Runtime rt;
  auto* x = rt.input<int>(kIn, 1, 1);
  Mod<int>* o = program(rt, x);
  EXPECT_EQ(rt.deref(o), 1);
  rt.change(x, 2);
  rt.propagate();
  EXPECT_EQ(rt.deref(o), 2);
  rt.change(x, 0);
  std::string e = error_of([&] { rt.propagate(); });
  EXPECT_NE(e.find("lost its write"), std::string::npos) << e;
  Runtime scratch;
  std::string f = error_of([&] { program(scratch, scratch.input<int>(kIn, 1, 0)); });
  EXPECT_NE(f.find("before it was written"), std::string::npos) << f;
}


// Owned traceables (rt.owned, spec/sac.md "Owned traceables"): the undo hook fused into the
// allocation node. Hand-derived expectations: a reused owned traceable is not released; one whose
// allocation is discarded is released once, in time order, after the replacing code, and the owner
// tells a predecessor from its successor by the record it keeps in the modifiable; reset releases
// the rest; ~Runtime releases nothing.
struct OwnedRecord {
  int key = 0;
  bool current = false;
};
using OwnedCert = OwnedMod<bool, OwnedRecord>;
struct OwnedOwner {
  std::map<int, OwnedCert*> registry;  // key → the traceable holding it
  std::vector<std::string> events;
  int created = 0;
  static void release(void* o, OwnedCert* m) { static_cast<OwnedOwner*>(o)->released(m); }
  void released(OwnedCert* m) {
    events.push_back("release:" + std::to_string(m->payload.key) + (m->payload.current ? "" : "(old)"));
    if (m->payload.current) registry.erase(m->payload.key);
  }
  OwnedCert* cert(Runtime& rt, int key) {
    return rt.owned<bool, OwnedRecord>(kCert, this, &OwnedOwner::release, [&](OwnedCert& m) {
      auto it = registry.find(key);
      if (it != registry.end()) {  // re-created before its predecessor's release
        m.value = it->second->value;
        it->second->payload.current = false;
        it->second = &m;
        events.push_back("recreate:" + std::to_string(key));
      } else {
        m.value = true;
        registry[key] = &m;
        ++created;
        events.push_back("create:" + std::to_string(key));
      }
      m.payload = {key, true};
    }, key);
  }
};

// Reads cs[i..] in turn and hands the number that hold to k.
template <class K>
void count_owned(Runtime& rt, std::vector<OwnedCert*> cs, std::size_t i, int acc, K k) {
  if (i == cs.size()) return k(acc);
  rt.read(cs[i], [&rt, cs, i, acc, k](bool b) { count_owned(rt, cs, i + 1, acc + (b ? 1 : 0), k); });
}

TEST(SacGenerality, S1_3_OwnedTraceableIsReleasedWithItsAllocationOnly) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  OwnedOwner owner;
  auto* x = rt.input<int>(kIn, 1, 3);
  auto* y = rt.input<int>(kIn, 2, 0);
  auto* o = rt.run([&] {
    auto* out = rt.alloc<int>(kOut);
    rt.read(x, [&, out](int n) {
      // keys 0..n-1 (reused when n changes), then key 10 inside a read of y (re-created when y changes)
      std::vector<OwnedCert*> cs;
      for (int i = 0; i < n; ++i) cs.push_back(owner.cert(rt, i));
      rt.read(y, [&, out, cs](int v) {
        std::vector<OwnedCert*> all = cs;
        all.push_back(owner.cert(rt, 10 + (v > 5 ? 1 : 0)));
        count_owned(rt, all, 0, 0, [&rt, out, v](int t) { rt.write(out, t * 100 + v); });
      });
    });
    return out;
  });
  EXPECT_EQ(rt.deref(o), 400);
  EXPECT_EQ(owner.events, (std::vector<std::string>{"create:0", "create:1", "create:2", "create:10"}));
  owner.events.clear();
  // The owner sets a certificate; only it changes; the run follows.
  rt.change<bool>(owner.registry.at(1), false);
  rt.propagate();
  EXPECT_EQ(rt.deref(o), 300);
  EXPECT_TRUE(owner.events.empty());
  // y changes: the read of y re-runs; key 10 is found in the re-executed interval and reused.
  rt.change(y, 2);
  rt.propagate();
  EXPECT_EQ(rt.deref(o), 302);
  EXPECT_TRUE(owner.events.empty()) << "a reused owned traceable is neither re-created nor released";
  // y past 5: key 10 is not asked for any more (released), key 11 is new.
  rt.change(y, 7);
  rt.propagate();
  EXPECT_EQ(rt.deref(o), 307);
  EXPECT_EQ(owner.events, (std::vector<std::string>{"create:11", "release:10"}));
  owner.events.clear();
  // x changes: the outer read re-runs; keys 0, 1 are reused (1 keeps the owner's value), 2 is released.
  rt.change(x, 2);
  rt.propagate();
  EXPECT_EQ(rt.deref(o), 207);  // keys 0 (true), 1 (false, kept), 11 (true)
  EXPECT_EQ(owner.events, (std::vector<std::string>{"release:2"}));
  EXPECT_EQ(owner.registry.size(), 3u);  // 0, 1, 11
  EXPECT_EQ(owner.created, 5);
  owner.events.clear();
  rt.reset();
  EXPECT_TRUE(owner.registry.empty()) << "reset releases every owned traceable";
  EXPECT_EQ(owner.events.size(), 3u);
}

// A key re-created by an earlier re-executed read while its old allocation, in a later read's
// interval, is still live: the new traceable takes the owner's value and registration, and the
// old one's release (when the later read re-runs) leaves the registration alone.
TEST(SacGenerality, S1_3_OwnedTraceableRecreatedBeforeItsPredecessorsRelease) {
  RecordProperty("claim", "S1.3.3-traceable-undo");
  Runtime rt;
  OwnedOwner owner;
  auto* x = rt.input<int>(kIn, 1, 0);
  auto* y = rt.input<int>(kIn, 2, 0);
  Mod<int>* ox = nullptr;
  auto* out = rt.run([&] {
    auto* o = rt.alloc<int>(kOut);
    ox = rt.alloc<int>(kOut, 1);
    rt.read(x, [&, o = ox](int v) {
      if (v == 1) rt.read(owner.cert(rt, 7), [&rt, o](bool b) { rt.write(o, b ? 71 : 70); });
      else rt.write(o, -1);
    });
    rt.read(y, [&, o](int w) {
      if (w == 0) rt.read(owner.cert(rt, 7), [&rt, o](bool b) { rt.write(o, b ? 1 : 0); });
      else rt.write(o, 2);
    });
    return o;
  });
  EXPECT_EQ(rt.deref(out), 1);
  OwnedCert* first = owner.registry.at(7);
  rt.change<bool>(first, false);  // the owner's value, which the successor must inherit
  rt.propagate();
  EXPECT_EQ(rt.deref(out), 0);
  owner.events.clear();
  rt.change(x, 1);
  rt.change(y, 1);
  rt.propagate();
  EXPECT_EQ(owner.events, (std::vector<std::string>{"recreate:7", "release:7(old)"}));
  ASSERT_EQ(owner.registry.count(7), 1u) << "the successor keeps the registration";
  OwnedCert* second = owner.registry.at(7);
  EXPECT_NE(second, first);
  EXPECT_FALSE(second->value) << "the successor inherits the owner's value";
  EXPECT_TRUE(second->payload.current);
  EXPECT_EQ(rt.deref(out), 2);
  EXPECT_EQ(rt.deref(ox), 70);
  EXPECT_EQ(owner.created, 1);
  rt.change(x, 0);
  rt.propagate();
  EXPECT_TRUE(owner.registry.empty());
  OwnedOwner o2;
  {
    Runtime r2;
    r2.run([&] { return o2.cert(r2, 1); });
  }
  EXPECT_EQ(o2.events, (std::vector<std::string>{"create:1"})) << "~Runtime releases nothing";
}

}  // namespace
