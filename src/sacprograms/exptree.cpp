#include "sacprograms/exptree.hpp"

#include <random>

#include "exact/error.hpp"

namespace kmr::sacprograms {

using sac::Label;
using sac::Mod;
using sac::Runtime;

long long apply_op(int op, long long a, long long b) {
  auto x = static_cast<unsigned long long>(a), y = static_cast<unsigned long long>(b);
  unsigned long long r = op == 0 ? x + y : op == 1 ? x - y : x * y;
  return static_cast<long long>(r);
}

PlainTree PlainTree::random(std::size_t leaves, std::uint64_t seed) {
  KMR_CHECK(leaves >= 1, "PlainTree::random: at least one leaf");
  PlainTree t;
  std::mt19937_64 rng(seed);
  t.nodes.reserve(2 * leaves);
  // Iterative balanced build: (node index, number of leaves below it).
  std::vector<std::pair<int, std::size_t>> stack{{0, leaves}};
  t.nodes.emplace_back();
  while (!stack.empty()) {
    auto [i, k] = stack.back();
    stack.pop_back();
    t.nodes[i].id = t.next_id++;
    if (k == 1) {
      t.nodes[i].leaf = true;
      t.nodes[i].val = static_cast<long long>(rng() % 1000);
      continue;
    }
    int l = static_cast<int>(t.nodes.size()), r = l + 1;
    t.nodes.emplace_back();
    t.nodes.emplace_back();
    t.nodes[i].leaf = false;
    t.nodes[i].op = static_cast<int>(rng() % 3);
    t.nodes[i].l = l;
    t.nodes[i].r = r;
    stack.push_back({r, k - k / 2});
    stack.push_back({l, k / 2});
  }
  return t;
}

long long PlainTree::eval() const {
  // Post-order without recursion: values[i] once both children are done.
  std::vector<long long> value(nodes.size());
  std::vector<std::pair<int, bool>> stack{{0, false}};
  while (!stack.empty()) {
    auto [i, done] = stack.back();
    stack.pop_back();
    const N& n = nodes[i];
    if (n.leaf) {
      value[i] = n.val;
    } else if (done) {
      value[i] = apply_op(n.op, value[n.l], value[n.r]);
    } else {
      stack.push_back({i, true});
      stack.push_back({n.r, false});
      stack.push_back({n.l, false});
    }
  }
  return value[0];
}

std::vector<int> PlainTree::leaves() const {
  std::vector<int> out, stack{0};
  while (!stack.empty()) {
    int i = stack.back();
    stack.pop_back();
    if (nodes[i].leaf) out.push_back(i);
    else stack.insert(stack.end(), {nodes[i].r, nodes[i].l});
  }
  return out;
}

std::vector<int> PlainTree::mergeable() const {
  std::vector<int> out, stack{0};
  while (!stack.empty()) {
    int i = stack.back();
    stack.pop_back();
    if (nodes[i].leaf) continue;
    if (nodes[nodes[i].l].leaf && nodes[nodes[i].r].leaf) out.push_back(i);
    stack.insert(stack.end(), {nodes[i].r, nodes[i].l});
  }
  return out;
}

void PlainTree::set(int i, long long v) {
  if (!nodes.at(i).leaf) throw InputError("PlainTree::set: node " + std::to_string(i) + " is not a leaf");
  nodes[i].val = v;
}

void PlainTree::split(int i, int op, long long right) {
  if (!nodes.at(i).leaf) throw InputError("PlainTree::split: node " + std::to_string(i) + " is not a leaf");
  int l = static_cast<int>(nodes.size()), r = l + 1;
  N left, rt;
  left.val = nodes[i].val;
  left.id = next_id++;
  rt.val = right;
  rt.id = next_id++;
  nodes.push_back(left);
  nodes.push_back(rt);
  nodes[i].leaf = false;
  nodes[i].op = op;
  nodes[i].l = l;
  nodes[i].r = r;
}

void PlainTree::merge(int i) {
  N& n = nodes.at(i);
  if (n.leaf || !nodes[n.l].leaf || !nodes[n.r].leaf)
    throw InputError("PlainTree::merge: node " + std::to_string(i) + " does not have two leaf children");
  n.leaf = true;
  n.val = nodes[n.l].val;
  n.l = n.r = -1;
}

namespace {
constexpr Label kNode{"tree.node"}, kEval{"eval"};

Mod<long long>* eval(Runtime* rt, Mod<TNode>* t) {
  return rt->memo_read<long long>(kEval, t, t, [rt](const TNode& n, Mod<long long>* dest) {
    if (n.leaf) {
      rt->write(dest, n.val);
      return;
    }
    Mod<long long>* a = eval(rt, n.l);
    Mod<long long>* b = eval(rt, n.r);
    int op = n.op;
    rt->read(a, [rt, dest, b, op](long long x) {
      rt->read(b, [rt, dest, op, x](long long y) { rt->write(dest, apply_op(op, x, y)); });
    });
  });
}
}  // namespace

TreeInput::TreeInput(Runtime& rt, PlainTree tree) : rt_(rt), tree_(std::move(tree)) {
  mods_.assign(tree_.nodes.size(), nullptr);
  // Children before parents: reverse post-order of an explicit stack.
  std::vector<std::pair<int, bool>> stack{{0, false}};
  while (!stack.empty()) {
    auto [i, done] = stack.back();
    stack.pop_back();
    const auto& n = tree_.nodes[i];
    if (n.leaf || done) {
      mods_[i] = make(i);
    } else {
      stack.push_back({i, true});
      stack.push_back({n.r, false});
      stack.push_back({n.l, false});
    }
  }
}

TNode TreeInput::value(int i) const {
  const auto& n = tree_.nodes[i];
  if (n.leaf) return TNode{true, n.val, 0, nullptr, nullptr};
  return TNode{false, 0, n.op, mods_[n.l], mods_[n.r]};
}

Mod<TNode>* TreeInput::make(int i) { return rt_.input<TNode>(kNode, tree_.nodes[i].id, value(i)); }

void TreeInput::set(int i, long long v) {
  tree_.set(i, v);
  rt_.change(mods_[i], value(i));
}

void TreeInput::split(int i, int op, long long right) {
  tree_.split(i, op, right);
  mods_.resize(tree_.nodes.size(), nullptr);
  mods_[tree_.nodes[i].l] = make(tree_.nodes[i].l);
  mods_[tree_.nodes[i].r] = make(tree_.nodes[i].r);
  rt_.change(mods_[i], value(i));
}

void TreeInput::merge(int i) {
  int l = tree_.nodes.at(i).l, r = tree_.nodes.at(i).r;
  tree_.merge(i);
  rt_.change(mods_[i], value(i));
  released_.push_back(mods_[l]);
  released_.push_back(mods_[r]);
  mods_[l] = mods_[r] = nullptr;
}

void TreeInput::reserve(std::size_t splits) {
  tree_.nodes.reserve(tree_.nodes.size() + 2 * splits);
  mods_.reserve(tree_.nodes.size() + 2 * splits);
}

void TreeInput::propagate() {
  rt_.propagate();
  for (auto* m : released_) rt_.release(m);
  released_.clear();
}

Mod<long long>* sa_exptree(Runtime& rt, Mod<TNode>* root) {
  return rt.run([r = &rt, root] { return eval(r, root); });
}

}  // namespace kmr::sacprograms
