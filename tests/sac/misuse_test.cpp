// Misuse of the sac runtime that runtime.hpp promises to refuse with a ContractError naming it, not
// covered by runtime_test.cpp (issue 13 §2): the owner's meta operations on the wrong kind of
// modifiable, a write to a traceable inside a run, and trace operations on a modifiable that change
// propagation has just discarded (kept by a program that holds its pointer across executions).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "error_of.hpp"
#include "sac/runtime.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kIn{"in"}, kCell{"cell"}, kCert{"cert"}, kBox{"ibox"};

using kmr::sac::test::error_of;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SacMisuse, MetaOperationsRefuseModifiablesTheComputationOwns) {
  Runtime rt;
  Mod<int>* in = rt.input<int>(kIn, 1, 5);
  Mod<int>* cell = nullptr;
  Mod<int>* unwritten = nullptr;
  rt.run([&] {
    cell = rt.alloc<int>(kCell, 1);
    rt.write(cell, 7);
    unwritten = rt.alloc<int>(kCell, 2);
  });
  EXPECT_TRUE(has(error_of([&] { rt.change(cell, 8); }), "change: only inputs and traceables are changed from outside a run"));
  EXPECT_TRUE(has(error_of([&] { rt.release(cell); }), "release: only input modifiables are released by their owner"));
  EXPECT_TRUE(has(error_of([&] { rt.deref(unwritten); }), "deref of an unwritten modifiable"));
  // The refused operations changed nothing: the owned cell keeps its value, the input can change.
  EXPECT_EQ(rt.deref(cell), 7);
  rt.change(in, 6);
  rt.propagate();
  EXPECT_EQ(rt.deref(in), 6);
}

TEST(SacMisuse, AWriteToATraceableInsideARunIsRefused) {
  Runtime rt;
  std::string e = error_of([&] {
    rt.run([&] {
      Mod<bool>* c = rt.traceable<bool>(kCert, true, 1);
      rt.write(c, false);
    });
  });
  EXPECT_TRUE(has(e, "write to traceable ")) << e;
  EXPECT_TRUE(has(e, " inside a run (its owner sets it with change)")) << e;
}

// A program that keeps a modifiable's pointer outside the trace: the first read of `sel` allocates
// a cell keyed by sel's value (a new key after sel changes, so propagation discards the old cell);
// the later read of `use` then works on the cell kept from the first execution (op). After both
// inputs change, propagation re-executes the first read (discarding the old cell) before the second:
// op meets a discarded modifiable and must be refused, not read freed memory.
template <class M, class Alloc, class Op>
std::string op_on_discarded(Alloc alloc, Op op) {
  Runtime rt;
  Mod<int>* sel = rt.input<int>(kIn, 1, 0);
  Mod<int>* use = rt.input<int>(kIn, 2, 0);
  std::vector<M*> kept;
  auto* keep = &kept;
  rt.run([&] {
    rt.read(sel, [&rt, keep, alloc](int s) { keep->push_back(alloc(rt, s)); });
    rt.read(use, [&rt, keep, op](int u) {
      if (u == 1) op(rt, keep->front());
    });
  });
  EXPECT_EQ(kept.size(), 1u);
  rt.change(sel, 1);
  rt.change(use, 1);
  return error_of([&] { rt.propagate(); });
}

TEST(SacMisuse, TraceOperationsOnADiscardedModifiableAreRefused) {
  auto cell = [](Runtime& rt, int s) {
    Mod<int>* m = rt.alloc<int>(kCell, s);
    rt.write(m, s);
    return m;
  };
  std::string read = op_on_discarded<Mod<int>>(cell, [](Runtime& rt, Mod<int>* m) { rt.read(m, [](int) {}); });
  EXPECT_TRUE(has(read, "read of a discarded modifiable ")) << read;
  std::string write = op_on_discarded<Mod<int>>(cell, [](Runtime& rt, Mod<int>* m) { rt.write(m, 3); });
  EXPECT_TRUE(has(write, "write to a discarded modifiable ")) << write;
  auto ibox = [](Runtime& rt, int s) { return rt.ialloc<int>(kBox, 0, s); };
  std::string iread = op_on_discarded<IMod<int>>(ibox, [](Runtime& rt, IMod<int>* m) { rt.iread(m, [](int) {}); });
  EXPECT_TRUE(has(iread, "iread of a discarded modifiable")) << iread;
  std::string iwrite = op_on_discarded<IMod<int>>(ibox, [](Runtime& rt, IMod<int>* m) { rt.iwrite(m, 3); });
  EXPECT_TRUE(has(iwrite, "iwrite to a discarded modifiable")) << iwrite;
}

// The same program without the misuse (the second read leaves the kept cell alone) propagates.
TEST(SacMisuse, TheSameProgramWithoutTheMisusePropagates) {
  auto cell = [](Runtime& rt, int s) {
    Mod<int>* m = rt.alloc<int>(kCell, s);
    rt.write(m, s);
    return m;
  };
  EXPECT_EQ(op_on_discarded<Mod<int>>(cell, [](Runtime&, Mod<int>*) {}), "");
}

}  // namespace
