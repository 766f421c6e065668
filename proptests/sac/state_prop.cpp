// Model-vs-system properties (rc::state) for every self-adjusting program (§1.3.1, §1.3.2): the
// model is the plain input list; commands insert, delete or change one element, or several before
// one propagation. After each propagation: output = static twin = independent reference, and the
// trace signature and live counts equal those of a from-scratch self-adjusting run.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <memory>

#include "sacprograms/exptree.hpp"
#include "sacprograms/session.hpp"
#include "../check_cases.hpp"

using namespace kmr::sacprograms;

namespace {

// rc::gen::inRange narrows its range at small sizes (positions near 0, first kinds only, small
// values); edits and elements here are drawn from the whole range at every size.
template <class T>
rc::Gen<T> uniform(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi));
}

struct Model {
  std::vector<long long> values;
};

struct Sut {
  std::unique_ptr<ListSession> session;
};

// Elements: small integers (many duplicates) or, for quickhull, points on a small grid.
rc::Gen<long long> element(bool points) {
  if (points)
    return rc::gen::map(rc::gen::pair(uniform<long long>(-8, 9), uniform<long long>(-8, 9)),
                        [](std::pair<long long, long long> p) { return encode_point(p.first, p.second); });
  return uniform<long long>(-20, 21);
}

void verify(const ListSession& s, const Model& m) {
  const std::string& name = s.program().name;
  RC_ASSERT(s.values() == m.values);
  Snapshot got = s.snapshot();
  Snapshot fresh = from_scratch(s.program(), m.values, s.ids());
  RC_ASSERT(got.output == s.static_output());
  RC_ASSERT(got.output == reference_output(name, m.values));
  RC_ASSERT(got.signature == fresh.signature);
  RC_ASSERT(got.trace_nodes == fresh.trace_nodes);
  RC_ASSERT(got.live_mods == fresh.live_mods);
}

struct Edit {
  int kind;  // 0 insert, 1 erase, 2 set
  std::size_t pos;
  long long value;
};

Edit gen_edit(std::size_t size, bool points) {
  int kind = size == 0 ? 0 : *uniform(0, 3);
  std::size_t pos = *uniform<std::size_t>(0, kind == 0 ? size + 1 : size);
  return Edit{kind, pos, *element(points)};
}

void apply_edit(const Edit& e, std::vector<long long>& v) {
  auto at = v.begin() + static_cast<std::ptrdiff_t>(e.pos);
  if (e.kind == 0) v.insert(at, e.value);
  else if (e.kind == 1) v.erase(at);
  else *at = e.value;
}

void apply_edit(const Edit& e, ListSession& s) {
  if (e.kind == 0) s.insert(e.pos, e.value);
  else if (e.kind == 1) s.erase(e.pos);
  else s.set(e.pos, e.value);
}

bool g_points = false;  // set per property before rc::state::check

// Shrinking drops commands, so a later edit's position may no longer exist: such sequences are
// skipped (rc::state preconditions), never applied out of range.
bool edit_fits(const Edit& e, std::size_t& size) {
  if (e.kind == 0 ? e.pos > size : e.pos >= size) return false;
  size += e.kind == 0 ? 1 : e.kind == 1 ? -1 : 0;
  return true;
}

struct OneEdit : rc::state::Command<Model, Sut> {
  Edit e;
  explicit OneEdit(const Model& m) : e(gen_edit(m.values.size(), g_points)) {}
  void checkPreconditions(const Model& m) const override {
    std::size_t size = m.values.size();
    RC_PRE(edit_fits(e, size));
  }
  void apply(Model& m) const override { apply_edit(e, m.values); }
  void run(const Model& m, Sut& sut) const override {
    Model next = m;
    apply(next);
    apply_edit(e, *sut.session);
    sut.session->propagate();
    verify(*sut.session, next);
  }
  void show(std::ostream& os) const override { os << "edit kind=" << e.kind << " pos=" << e.pos << " value=" << e.value; }
};

struct Batch : rc::state::Command<Model, Sut> {
  std::vector<Edit> edits;
  explicit Batch(const Model& m) {
    std::size_t size = m.values.size();
    int k = *uniform(2, 6);
    for (int i = 0; i < k; ++i) {
      edits.push_back(gen_edit(size, g_points));
      size += edits.back().kind == 0 ? 1 : edits.back().kind == 1 ? -1 : 0;
    }
  }
  void checkPreconditions(const Model& m) const override {
    std::size_t size = m.values.size();
    for (const Edit& e : edits) RC_PRE(edit_fits(e, size));
  }
  void apply(Model& m) const override {
    for (const Edit& e : edits) apply_edit(e, m.values);
  }
  void run(const Model& m, Sut& sut) const override {
    Model next = m;
    apply(next);
    for (const Edit& e : edits) apply_edit(e, *sut.session);
    sut.session->propagate();  // one propagation for the whole batch
    verify(*sut.session, next);
  }
  void show(std::ostream& os) const override { os << "batch of " << edits.size() << " edits"; }
};

// Initial inputs: empty, all duplicates, sorted, reverse sorted, or random.
std::vector<long long> initial(bool points, std::size_t max_n) {
  int shape = *rc::gen::element(0, 1, 2, 3, 4);
  std::size_t n = shape == 0 ? 0 : *uniform<std::size_t>(1, max_n + 1);
  std::vector<long long> v = *rc::gen::container<std::vector<long long>>(n, element(points));
  if (shape == 1) std::fill(v.begin(), v.end(), v.empty() ? 0 : v[0]);
  if (shape == 2) std::sort(v.begin(), v.end());
  if (shape == 3) std::sort(v.rbegin(), v.rend());
  static const char* names[] = {"empty", "duplicates", "sorted", "reverse-sorted", "random"};
  RC_CLASSIFY(true, names[shape]);
  return v;
}

// max_n: largest initial input; min_commands: a prefix of at least that many commands runs before
// rc::state's own sequence (long runs).
void check_program(const std::string& name, std::size_t max_n = 39, int min_commands = 0) {
  g_points = name == "quickhull";
  Model m{initial(g_points, max_n)};
  Sut sut{std::make_unique<ListSession>(list_program(name), m.values)};
  verify(*sut.session, m);
  int prefix = min_commands ? *uniform(min_commands, min_commands + 11) : 0;
  for (int k = 0; k < prefix; ++k) {
    auto cmd = *rc::state::gen::execOneOfWithArgs<OneEdit, OneEdit, Batch>()(m);
    cmd->run(m, sut);
    cmd->apply(m);
  }
  rc::state::check(m, sut, rc::state::gen::execOneOfWithArgs<OneEdit, OneEdit, Batch>());
}

RC_GTEST_PROP(SacStateProp, S1_3_MapPropagationEqualsFromScratch, ()) { check_program("map"); }
RC_GTEST_PROP(SacStateProp, S1_3_FilterPropagationEqualsFromScratch, ()) { check_program("filter"); }
RC_GTEST_PROP(SacStateProp, S1_3_SumPropagationEqualsFromScratch, ()) { check_program("sum"); }
RC_GTEST_PROP(SacStateProp, S1_3_QuicksortPropagationEqualsFromScratch, ()) { check_program("quicksort"); }
RC_GTEST_PROP(SacStateProp, S1_3_MergesortPropagationEqualsFromScratch, ()) { check_program("mergesort"); }
RC_GTEST_PROP(SacStateProp, S1_3_QuickhullPropagationEqualsFromScratch, ()) { check_program("quickhull"); }

// Long runs: ≥ 50 commands on inputs of up to 200 elements (fewer cases for the Θ(n log n) traces).
TEST(SacStateProp, S1_3_MapLongRuns) { kmr::proptest::check_cases(15, [] { check_program("map", 200, 50); }); }
TEST(SacStateProp, S1_3_FilterLongRuns) { kmr::proptest::check_cases(15, [] { check_program("filter", 200, 50); }); }
TEST(SacStateProp, S1_3_SumLongRuns) { kmr::proptest::check_cases(10, [] { check_program("sum", 200, 50); }); }
TEST(SacStateProp, S1_3_QuicksortLongRuns) { kmr::proptest::check_cases(5, [] { check_program("quicksort", 200, 50); }); }
TEST(SacStateProp, S1_3_MergesortLongRuns) { kmr::proptest::check_cases(2, [] { check_program("mergesort", 200, 50); }); }
TEST(SacStateProp, S1_3_QuickhullLongRuns) { kmr::proptest::check_cases(5, [] { check_program("quickhull", 200, 50); }); }

// ---- expression trees: the model is the plain tree -------------------------------------------
struct TreeSut {
  std::unique_ptr<kmr::sac::Runtime> rt;
  std::unique_ptr<TreeInput> input;
  kmr::sac::Mod<long long>* out = nullptr;
};

void verify_tree(const TreeSut& s, const PlainTree& m) {
  RC_ASSERT(s.rt->deref(s.out) == m.eval());
  kmr::sac::Runtime fresh;
  TreeInput in(fresh, m);
  sa_exptree(fresh, in.root());
  RC_ASSERT(s.rt->signature() == fresh.signature());
  RC_ASSERT(s.rt->stats().trace_nodes == fresh.stats().trace_nodes);
  RC_ASSERT(s.rt->stats().live_mods == fresh.stats().live_mods);
}

struct TreeEdit : rc::state::Command<PlainTree, TreeSut> {
  int kind, node, op;
  long long value;
  explicit TreeEdit(const PlainTree& m) {
    auto leaves = m.leaves();
    auto merge = m.mergeable();
    kind = merge.empty() ? *uniform(0, 2) : *uniform(0, 3);
    node = kind == 2 ? *rc::gen::elementOf(merge) : *rc::gen::elementOf(leaves);
    op = *uniform(0, 3);
    value = *uniform<long long>(-50, 51);
  }
  void apply(PlainTree& m) const override {
    if (kind == 0) m.set(node, value);
    else if (kind == 1) m.split(node, op, value);
    else m.merge(node);
  }
  void run(const PlainTree& m, TreeSut& s) const override {
    PlainTree next = m;
    apply(next);
    if (kind == 0) s.input->set(node, value);
    else if (kind == 1) s.input->split(node, op, value);
    else s.input->merge(node);
    s.input->propagate();
    verify_tree(s, next);
  }
  void show(std::ostream& os) const override { os << "tree edit kind=" << kind << " node=" << node; }
};

void check_exptree(std::size_t max_leaves, int min_commands) {
  std::size_t leaves = *uniform<std::size_t>(1, max_leaves + 1);
  PlainTree m = PlainTree::random(leaves, *rc::gen::arbitrary<std::uint64_t>());
  RC_CLASSIFY(leaves == 1, "single leaf");
  TreeSut s;
  s.rt = std::make_unique<kmr::sac::Runtime>();
  s.input = std::make_unique<TreeInput>(*s.rt, m);
  s.out = sa_exptree(*s.rt, s.input->root());
  verify_tree(s, m);
  int prefix = min_commands ? *uniform(min_commands, min_commands + 11) : 0;
  for (int k = 0; k < prefix; ++k) {
    auto cmd = *rc::state::gen::execOneOfWithArgs<TreeEdit>()(m);
    cmd->run(m, s);
    cmd->apply(m);
  }
  rc::state::check(m, s, rc::state::gen::execOneOfWithArgs<TreeEdit>());
}

RC_GTEST_PROP(SacStateProp, S1_3_ExptreePropagationEqualsFromScratch, ()) { check_exptree(29, 0); }
TEST(SacStateProp, S1_3_ExptreeLongRuns) { kmr::proptest::check_cases(15, [] { check_exptree(200, 50); }); }

}  // namespace
