// The editable inputs of the benchmark programs refuse bad edits (issue 13 §2, found by
// coverage/run.sh): a position past the end, an erased cell, an empty list, a tree edit on the wrong
// kind of node. Each refusal is an InputError, and afterwards the input, the output (against
// reference_output / a recursive evaluation written here) and the trace signature (against a
// from-scratch run) are as if the edit had never been tried.
#include <gtest/gtest.h>

#include "exact/error.hpp"
#include "sacprograms/exptree.hpp"
#include "sacprograms/list.hpp"
#include "sacprograms/session.hpp"

using namespace kmr::sacprograms;
using kmr::InputError;

namespace {

TEST(ProgramInputs, RefusedListEditsChangeNothing) {
  for (const char* name : {"sum", "filter", "quicksort"}) {
    std::vector<long long> in{5, -3, 8};
    ListSession s(list_program(name), in);
    EXPECT_THROW(s.erase(3), InputError) << name;
    EXPECT_THROW(s.set(3, 1), InputError) << name;
    EXPECT_THROW(s.insert(4, 1), InputError) << name;
    s.propagate();
    EXPECT_EQ(s.values(), in) << name;
    Snapshot got = s.snapshot();
    EXPECT_EQ(got.output, reference_output(name, in)) << name;
    EXPECT_EQ(got.signature, from_scratch(list_program(name), in, s.ids()).signature) << name;
    s.insert(3, 7);  // at the end is allowed
    s.propagate();
    EXPECT_EQ(s.snapshot(false).output, reference_output(name, {5, -3, 8, 7})) << name;
  }
}

TEST(ProgramInputs, ErasedCellsAndEmptyListsAreRefused) {
  Runtime rt;
  ListInput in(rt, {}, {});
  EXPECT_EQ(in.size(), 0u);
  EXPECT_THROW(in.random_cell(3), InputError);
  EXPECT_THROW(in.cell_at(0), InputError);
  EXPECT_THROW(in.erase(std::size_t{0}), InputError);
  in.insert(0, 1, 42);
  List* cell = in.cell_at(0);
  EXPECT_EQ(in.random_cell(12345), cell);  // the only live cell
  in.erase(cell);
  EXPECT_THROW(in.erase(cell), InputError);  // no longer live
  in.propagate();
  EXPECT_TRUE(in.values().empty());
}

long long eval(const PlainTree& t, int i) {  // recursive, unlike PlainTree::eval
  const auto& n = t.nodes[static_cast<std::size_t>(i)];
  if (n.leaf) return n.val;
  long long a = eval(t, n.l), b = eval(t, n.r);
  return n.op == 0 ? static_cast<long long>(static_cast<unsigned long long>(a) + static_cast<unsigned long long>(b))
       : n.op == 1 ? static_cast<long long>(static_cast<unsigned long long>(a) - static_cast<unsigned long long>(b))
                   : static_cast<long long>(static_cast<unsigned long long>(a) * static_cast<unsigned long long>(b));
}

TEST(ProgramInputs, TreeEditsOnTheWrongNodeAreRefused) {
  PlainTree t = PlainTree::random(4, 9);  // balanced: root 0 with two inner children
  ASSERT_FALSE(t.nodes[0].leaf);
  const long long before = eval(t, 0);
  const std::size_t nodes = t.nodes.size();
  EXPECT_THROW(t.set(0, 5), InputError);
  EXPECT_THROW(t.split(0, 0, 5), InputError);
  EXPECT_THROW(t.merge(0), InputError);  // its children are not leaves
  int leaf = t.leaves().front();
  EXPECT_THROW(t.merge(leaf), InputError);
  EXPECT_THROW(t.set(static_cast<int>(nodes) + 3, 1), std::out_of_range);
  EXPECT_EQ(t.nodes.size(), nodes);
  EXPECT_EQ(eval(t, 0), before);
  EXPECT_EQ(t.eval(), before);
  // The allowed edits, against the recursive evaluation.
  t.split(leaf, 2, 3);
  EXPECT_EQ(t.eval(), eval(t, 0));
  t.merge(leaf);
  EXPECT_EQ(t.eval(), before);
  EXPECT_THROW(PlainTree::random(0, 1), kmr::ContractError);
}

}  // namespace
