// A refusal of sac/runtime.hpp that the other misuse tests leave out (issue 13 §2), judged by an
// independent fact: a program whose change propagation would write a modifiable after a read
// of it (inconsistent: run from scratch on the changed input, the same program reads the modifiable
// before writing it, which the runtime refuses too). (with_stack's refusals: big_stack_test.cpp.)
#include <gtest/gtest.h>

#include <string>

#include "error_of.hpp"
#include "sac/runtime.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kIn{"in"}, kCell{"cell"};

using kmr::sac::test::error_of;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// read(in): if in = 1, write a := 5;   read(a);   read(in): if in = 0, write a := 7.
// With in = 1 the write precedes the read of a (consistent). After in → 0 propagation removes the
// first write and re-executes the third read, whose write of a lands after the read of a.
void program(Runtime& rt, Mod<int>* in, Mod<int>** a, int* seen) {
  *a = rt.alloc<int>(kCell, 1);
  Mod<int>* cell = *a;
  rt.read(in, [&rt, cell](int v) {
    if (v == 1) rt.write(cell, 5);
  });
  rt.read(cell, [seen](int x) { *seen = x; });
  rt.read(in, [&rt, cell](int v) {
    if (v == 0) rt.write(cell, 7);
  });
}

TEST(SacConsistency, AWriteAfterAReadOfTheSameModifiableIsRefusedInPropagation) {
  Runtime rt;
  Mod<int>* in = rt.input<int>(kIn, 1, 1);
  Mod<int>* a = nullptr;
  int seen = -1;
  rt.run([&] { program(rt, in, &a, &seen); });
  EXPECT_EQ(seen, 5);
  rt.change(in, 0);
  std::string e = error_of([&] { rt.propagate(); });
  EXPECT_TRUE(has(e, " affects a read earlier in the trace: the program is not consistent")) << e;
  // The independent judgement: from scratch on in = 0 the read of a comes before any write of it.
  Runtime fresh;
  Mod<int>* in0 = fresh.input<int>(kIn, 1, 0);
  std::string scratch = error_of([&] { fresh.run([&] { program(fresh, in0, &a, &seen); }); });
  EXPECT_TRUE(has(scratch, "before it was written in this execution")) << scratch;
}

// The consistent variant (the late write goes to another cell) propagates and equals from scratch.
TEST(SacConsistency, TheSameShapeWritingAnotherCellPropagates) {
  auto body = [](Runtime& rt, Mod<int>* in, int* seen, Mod<int>** late) {
    Mod<int>* a = rt.alloc<int>(kCell, 1);
    *late = rt.alloc<int>(kCell, 2);
    rt.read(in, [&rt, a](int v) { rt.write(a, v == 1 ? 5 : 6); });
    rt.read(a, [seen](int x) { *seen = x; });
    Mod<int>* l = *late;
    rt.read(in, [&rt, l](int v) { rt.write(l, v == 0 ? 7 : 8); });
  };
  Runtime rt;
  Mod<int>* in = rt.input<int>(kIn, 1, 1);
  int seen = -1;
  Mod<int>* late = nullptr;
  rt.run([&] { body(rt, in, &seen, &late); });
  rt.change(in, 0);
  EXPECT_EQ(error_of([&] { rt.propagate(); }), "");
  EXPECT_EQ(seen, 6);
  EXPECT_EQ(rt.deref(late), 7);
  Runtime fresh;
  Mod<int>* in0 = fresh.input<int>(kIn, 1, 0);
  int seen0 = -1;
  Mod<int>* late0 = nullptr;
  fresh.run([&] { body(fresh, in0, &seen0, &late0); });
  EXPECT_EQ(rt.signature(), fresh.signature());
}

}  // namespace
