// Model-vs-system properties (rc::state) for the runtime features the Appendix A.2 hull needs
// (issue 8 §1; sacprograms/generality.hpp): certificates created during the run and flipped from
// outside, undo-hook order and identity, destination-passing memo with repeated keys, a write that
// moves earlier. The model is the plain input (values, element ids, the owner's flips). After every
// command and its propagation: output = static twin, and the trace signature and live counts equal
// those of a from-scratch run on the current input (same ids, same flips).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <map>
#include <memory>

#include "sacprograms/generality.hpp"
#include "../check_cases.hpp"

using namespace kmr::sacprograms;
using kmr::sac::HookId;

namespace {

// rc::gen::inRange narrows its range at small sizes (positions near 0, first kinds only, small
// values); edits and elements here are drawn from the whole range at every size.
template <class T>
rc::Gen<T> uniform(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi));
}

enum class Prog { CertifiedFilter, NextGreater, FirstPositive };

struct Model {
  std::vector<long long> values;
  std::vector<std::uint64_t> ids;
  std::map<std::uint64_t, bool> flips;
  std::uint64_t next_id = 1;
};

struct Instance {
  std::unique_ptr<Runtime> rt;
  std::unique_ptr<CertificateOwner> owner;
  std::unique_ptr<ListInput> in;
  Root* out_list = nullptr;
  Mod<long long>* out_value = nullptr;
  std::vector<long long> output() const {
    if (out_list) return to_vector(*rt, out_list);
    return {rt->deref(out_value)};
  }
};

Instance build(Prog p, const Model& m) {
  Instance s;
  s.rt = std::make_unique<Runtime>();
  s.owner = std::make_unique<CertificateOwner>(*s.rt);
  s.owner->set_flips(m.flips);
  s.in = std::make_unique<ListInput>(*s.rt, m.values, m.ids);
  if (p == Prog::CertifiedFilter) s.out_list = sa_certified_filter(*s.rt, s.in->root(), s.owner.get());
  else if (p == Prog::NextGreater) s.out_list = sa_next_greater(*s.rt, s.in->root());
  else s.out_value = sa_first_positive(*s.rt, s.in->root());
  return s;
}

std::vector<long long> twin(Prog p, const Model& m) {
  if (p == Prog::CertifiedFilter) return static_certified_filter(m.values, m.ids, m.flips);
  if (p == Prog::NextGreater) return static_next_greater(m.values);
  return {static_first_positive(m.values)};
}

struct Sut {
  Prog prog;
  Instance inst;
  std::map<HookId, std::size_t> hook_pos;  // live hook → its cell's position (time order) before the command
};

// Records where each live certificate's hook sits in time (its cell's position in the list).
void snapshot_hooks(Sut& s, const Model& m) {
  s.hook_pos.clear();
  if (s.prog != Prog::CertifiedFilter) return;
  for (std::size_t i = 0; i < m.ids.size(); ++i) {
    auto l = s.inst.owner->live().find(input_cell_name(m.ids[i]));
    if (l != s.inst.owner->live().end()) s.hook_pos[l->second.hook] = i;
  }
  s.inst.owner->take_discards();
}

void verify(Sut& s, const Model& m) {
  Instance& i = s.inst;
  RC_ASSERT(i.in->values() == m.values);
  RC_ASSERT(i.output() == twin(s.prog, m));
  Instance fresh = build(s.prog, m);
  RC_ASSERT(i.rt->signature() == fresh.rt->signature());
  RC_ASSERT(i.rt->stats().trace_nodes == fresh.rt->stats().trace_nodes);
  RC_ASSERT(i.rt->stats().live_mods == fresh.rt->stats().live_mods);
  if (s.prog == Prog::CertifiedFilter) {
    // One registration per cell, holding the live certificate with the owner's truth (a
    // certificate re-created under its key survived the discard of its predecessor's hook).
    RC_ASSERT(i.owner->live().size() == m.ids.size());
    for (std::uint64_t id : m.ids) {
      std::uint64_t name = input_cell_name(id);
      auto l = i.owner->live().find(name);
      RC_ASSERT(l != i.owner->live().end());
      RC_ASSERT(i.rt->deref(l->second.cert) == certificate_truth(m.flips, name));
    }
    // The hooks of this propagation ran in the time order of the trace they belonged to.
    std::vector<HookId> ran = i.owner->take_discards();
    std::size_t last = 0;
    for (std::size_t k = 0; k < ran.size(); ++k) {
      auto p = s.hook_pos.find(ran[k]);
      RC_ASSERT(p != s.hook_pos.end());
      RC_ASSERT(k == 0 || p->second > last);
      last = p->second;
    }
  }
  snapshot_hooks(s, m);
}

Prog g_prog = Prog::CertifiedFilter;
std::size_t g_max_n = 40;

rc::Gen<long long> element() {
  if (g_prog == Prog::NextGreater) return uniform<long long>(-6, 7);  // many equal keys
  if (g_prog == Prog::FirstPositive) return uniform<long long>(-10, 2);  // positives are rare
  return uniform<long long>(-20, 21);
}

struct Edit {
  int kind;  // 0 insert, 1 erase, 2 set, 3 flip (certified filter)
  std::size_t pos;
  long long value;
};

Edit gen_edit(std::size_t size) {
  int kinds = g_prog == Prog::CertifiedFilter ? 4 : 3;
  int kind = size == 0 ? 0 : *uniform(0, kinds);
  std::size_t pos = *uniform<std::size_t>(0, kind == 0 ? size + 1 : size);
  return Edit{kind, pos, *element()};
}

void apply_edit(const Edit& e, Model& m) {
  auto at = static_cast<std::ptrdiff_t>(e.pos);
  if (e.kind == 0) {
    m.values.insert(m.values.begin() + at, e.value);
    m.ids.insert(m.ids.begin() + at, m.next_id++);
  } else if (e.kind == 1) {
    m.values.erase(m.values.begin() + at);
    m.ids.erase(m.ids.begin() + at);
  } else if (e.kind == 2) {
    m.values[e.pos] = e.value;
  } else {
    std::uint64_t name = input_cell_name(m.ids[e.pos]);
    m.flips[name] = !certificate_truth(m.flips, name);
  }
}

// The system side of an edit (m: the model before it, for the new element's id).
void apply_edit(const Edit& e, const Model& m, Sut& s) {
  if (e.kind == 0) s.inst.in->insert(e.pos, m.next_id, e.value);
  else if (e.kind == 1) s.inst.in->erase(e.pos);
  else if (e.kind == 2) s.inst.in->set(e.pos, e.value);
  else s.inst.owner->flip(input_cell_name(m.ids[e.pos]));  // the owner sets its certificate
}

// Shrinking drops commands, so a later edit's position may no longer exist: such sequences are
// skipped (rc::state preconditions), never applied out of range.
bool edit_fits(const Edit& e, std::size_t& size) {
  if (e.kind == 0 ? e.pos > size : e.pos >= size) return false;
  size += e.kind == 0 ? 1 : e.kind == 1 ? -1 : 0;
  return true;
}

struct OneEdit : rc::state::Command<Model, Sut> {
  Edit e;
  explicit OneEdit(const Model& m) : e(gen_edit(m.values.size())) {}
  void checkPreconditions(const Model& m) const override {
    std::size_t size = m.values.size();
    RC_PRE(edit_fits(e, size));
  }
  void apply(Model& m) const override { apply_edit(e, m); }
  void run(const Model& m, Sut& s) const override {
    apply_edit(e, m, s);
    s.inst.in->propagate();
    Model next = m;
    apply(next);
    verify(s, next);
  }
  void show(std::ostream& os) const override { os << "edit kind=" << e.kind << " pos=" << e.pos << " value=" << e.value; }
};

struct Batch : rc::state::Command<Model, Sut> {
  std::vector<Edit> edits;
  explicit Batch(const Model& m) {
    std::size_t size = m.values.size();
    int k = *uniform(2, 6);
    for (int i = 0; i < k; ++i) {
      edits.push_back(gen_edit(size));
      size += edits.back().kind == 0 ? 1 : edits.back().kind == 1 ? -1 : 0;
    }
  }
  void checkPreconditions(const Model& m) const override {
    std::size_t size = m.values.size();
    for (const Edit& e : edits) RC_PRE(edit_fits(e, size));
  }
  void apply(Model& m) const override {
    for (const Edit& e : edits) apply_edit(e, m);
  }
  void run(const Model& m, Sut& s) const override {
    Model cur = m;
    for (const Edit& e : edits) {
      apply_edit(e, cur, s);
      apply_edit(e, cur);
    }
    s.inst.in->propagate();  // one propagation for the whole batch
    verify(s, cur);
  }
  void show(std::ostream& os) const override { os << "batch of " << edits.size() << " edits"; }
};

void check(Prog p, std::size_t max_n, int min_commands) {
  g_prog = p;
  g_max_n = max_n;
  Model m;
  std::size_t n = *uniform<std::size_t>(0, max_n + 1);
  m.values = *rc::gen::container<std::vector<long long>>(n, element());
  // first_positive starts without positives: the first one to arrive moves the output's write earlier.
  if (p == Prog::FirstPositive)
    for (long long& v : m.values) v = std::min(v, 0LL);
  for (std::size_t i = 0; i < n; ++i) m.ids.push_back(m.next_id++);
  Sut s{p, build(p, m), {}};
  verify(s, m);
  // A prefix of at least min_commands commands (long runs), then rc::state's own sequence.
  int prefix = min_commands ? *uniform(min_commands, min_commands + 11) : 0;
  for (int k = 0; k < prefix; ++k) {
    auto cmd = *rc::state::gen::execOneOfWithArgs<OneEdit, OneEdit, Batch>()(m);
    cmd->run(m, s);
    cmd->apply(m);
  }
  rc::state::check(m, s, rc::state::gen::execOneOfWithArgs<OneEdit, OneEdit, Batch>());
  auto st = s.inst.rt->stats();
  RC_CLASSIFY(st.writes_moved_earlier > 0, "a write moved earlier");
  RC_CLASSIFY(st.memo_hits > 0, "memo reused");
  RC_CLASSIFY(st.fresh_allocs > 0, "fresh allocations");
  RC_CLASSIFY(st.allocs_reused > 0, "allocation reused");
  RC_CLASSIFY(st.hooks_run > 0, "undo hooks run");
}

// §1 item 1 (+2): certificates created in the run under a key, flipped by their owner.
RC_GTEST_PROP(SacGeneralityProp, S1_3_CertificatesCreatedInRunAndFlippedFromOutside, ()) {
  check(Prog::CertifiedFilter, 40, 0);
}
// §1 item 2: long runs stress re-registration; hook order and identity are checked after each.
TEST(SacGeneralityProp, S1_3_UndoHooksRunInTimeOrderAndKeepIdentity) {
  kmr::proptest::check_cases(25, [] { check(Prog::CertifiedFilter, 200, 50); });
}
// §1 item 3 (+ repeated memo keys): destination-passing memo whose result depends on reads.
RC_GTEST_PROP(SacGeneralityProp, S1_3_DestinationMemoWithRepeatedKeysEqualsFromScratch, ()) {
  check(Prog::NextGreater, 40, 0);
}
TEST(SacGeneralityProp, S1_3_DestinationMemoLongRuns) {
  kmr::proptest::check_cases(10, [] { check(Prog::NextGreater, 120, 50); });
}
// §1 item 4: a write that moves earlier during re-execution.
RC_GTEST_PROP(SacGeneralityProp, S1_3_WriteMovingEarlierEqualsFromScratch, ()) {
  check(Prog::FirstPositive, 40, 0);
}
TEST(SacGeneralityProp, S1_3_WriteMovingEarlierLongRuns) {
  kmr::proptest::check_cases(25, [] { check(Prog::FirstPositive, 200, 50); });
}

}  // namespace
