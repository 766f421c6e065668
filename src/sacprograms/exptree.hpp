#pragma once
// Expression-tree evaluation (the CEAL benchmark "exptrees"): leaves hold integers, inner nodes an
// operator (+, −, × on wrapping 64-bit integers). Guarantees (tests/sac, proptests/sac):
//  * sa_exptree's output equals PlainTree::eval (the static twin) after any edits + propagate();
//  * TreeInput names every node by its id, so equal PlainTrees give equal input names (and so equal
//    trace signatures for from-scratch runs); split/merge/set change O(1) input modifiables.
#include <cstdint>
#include <vector>

#include "sac/runtime.hpp"

namespace kmr::sacprograms {

struct PlainTree {
  struct N {
    bool leaf = true;
    long long val = 0;  // leaf value
    int op = 0;         // 0 '+', 1 '−', 2 '×'
    int l = -1, r = -1;
    std::uint64_t id = 0;
  };
  std::vector<N> nodes;  // nodes[0] is the root; merged-away nodes stay as garbage
  std::uint64_t next_id = 1;

  static PlainTree random(std::size_t leaves, std::uint64_t seed);  // balanced, random ops/values
  long long eval() const;                                           // the static twin (iterative)
  std::vector<int> leaves() const;                                  // reachable leaf indices
  std::vector<int> mergeable() const;  // reachable inner nodes whose children are both leaves
  void set(int i, long long v);
  void split(int i, int op, long long right);  // leaf i → op(leaf(old), leaf(right))
  void merge(int i);                           // op(leaf a, leaf b) → leaf a
};

long long apply_op(int op, long long a, long long b);

struct TNode {
  bool leaf = true;
  long long val = 0;
  int op = 0;
  sac::Mod<TNode>* l = nullptr;
  sac::Mod<TNode>* r = nullptr;
  bool operator==(const TNode&) const = default;
};
inline std::uint64_t canon_value(const TNode& t) {
  return sac::mix(sac::mix(sac::mix(sac::mix(t.leaf, static_cast<std::uint64_t>(t.val)), static_cast<std::uint64_t>(t.op)),
                           sac::canon_key(t.l)),
                  sac::canon_key(t.r));
}

// The input tree as input modifiables, edited in step with a PlainTree it owns.
class TreeInput {
 public:
  TreeInput(sac::Runtime& rt, PlainTree tree);
  sac::Mod<TNode>* root() const { return mods_[0]; }
  const PlainTree& tree() const { return tree_; }
  void set(int i, long long v);
  void split(int i, int op, long long right);
  void merge(int i);
  void propagate();  // rt.propagate(), then release merged-away leaves
  void reserve(std::size_t splits);  // room for that many splits without reallocating (benchmarks)

 private:
  sac::Mod<TNode>* make(int i);
  TNode value(int i) const;
  sac::Runtime& rt_;
  PlainTree tree_;
  std::vector<sac::Mod<TNode>*> mods_;
  std::vector<sac::Mod<TNode>*> released_;
};

sac::Mod<long long>* sa_exptree(sac::Runtime& rt, sac::Mod<TNode>* root);

}  // namespace kmr::sacprograms
