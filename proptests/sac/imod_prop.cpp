// IMod (ΔML IBox) under change propagation: writers that appear and disappear with the input, reads
// interleaved with them. After each propagation every read's output equals the plain model (the
// latest write before it, else the initial value) and the trace equals a from-scratch run's.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <memory>
#include <vector>

#include "sac/runtime.hpp"

using namespace kmr::sac;

namespace {

constexpr Label kX{"x"}, kBox{"box"}, kOut{"out"};
constexpr int kInitial = -7;

// Step i: the input x_i decides whether step i writes the box (x_i % 3 != 0, value x_i); then
// step i reads the box into out_i.
struct Program {
  Runtime rt;
  std::vector<Mod<int>*> x;
  std::vector<Mod<int>*> out;
  explicit Program(const std::vector<int>& xs) {
    for (std::size_t i = 0; i < xs.size(); ++i) x.push_back(rt.input<int>(kX, i, xs[i]));
    out = rt.run([this] {
      auto* box = rt.ialloc<int>(kBox, kInitial);
      std::vector<Mod<int>*> o;
      for (std::size_t i = 0; i < x.size(); ++i) {
        rt.read(x[i], [this, box](int v) {
          if (v % 3 != 0) rt.iwrite(box, v);
        });
        auto* oi = rt.alloc<int>(kOut, i);
        rt.iread(box, [this, oi](int v) { rt.write(oi, v); });
        o.push_back(oi);
      }
      return o;
    });
  }
};

std::vector<int> model(const std::vector<int>& xs) {
  std::vector<int> r;
  int cur = kInitial;
  for (int v : xs) {
    if (v % 3 != 0) cur = v;
    r.push_back(cur);
  }
  return r;
}

RC_GTEST_PROP(SacImodProp, S1_3_ImperativeModifiablePropagationEqualsFromScratch, ()) {
  std::size_t n = *rc::gen::inRange<std::size_t>(1, 12);
  auto xs = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(-6, 7));
  Program p(xs);
  int rounds = *rc::gen::inRange(1, 8);
  for (int r = 0; r < rounds; ++r) {
    int k = *rc::gen::inRange(1, 4);  // several changes before one propagation
    for (int j = 0; j < k; ++j) {
      std::size_t i = *rc::gen::inRange<std::size_t>(0, n);
      xs[i] = *rc::gen::inRange(-6, 7);
      p.rt.change(p.x[i], xs[i]);
    }
    p.rt.propagate();
    std::vector<int> got;
    for (auto* o : p.out) got.push_back(p.rt.deref(o));
    RC_ASSERT(got == model(xs));
    Program fresh(xs);
    RC_ASSERT(p.rt.signature() == fresh.rt.signature());
    RC_ASSERT(p.rt.stats().trace_nodes == fresh.rt.stats().trace_nodes);
    RC_ASSERT(p.rt.stats().live_mods == fresh.rt.stats().live_mods);
  }
}

}  // namespace
