#pragma once
// The computation graph (§3.2.3): operations v_(t), Enqueue (edges op → op), MarkReaders (edges
// s → op), its canonical form (Lemma 3.4.2 compares these) and the internal-index check.
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
auto WellSpacedSet<D>::Impl::mark_readers(const K& s, const Time& t) -> void {
  auto it = leaves.find(s);
  if (it == leaves.end()) return;  // not a leaf: nothing reads it (Leaf::readers)
  for (const OpRec* r : it->second.readers)
    if (r->first.t > t) pending.insert(r->first);
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::get_op(const OpKey& k) -> Op& {
  auto [it, fresh] = ops.try_emplace(k);
  if (fresh) {
    pending.insert(k);
    ops_by_vertex[k.v].insert(k.t);
  }
  return it->second;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::erase_op(typename std::map<OpKey, Op>::iterator it) -> void {
  auto bv = ops_by_vertex.find(it->first.v);
  bv->second.erase(it->first.t);
  if (bv->second.empty()) ops_by_vertex.erase(bv);
  ops.erase(it);
}

// Enqueue(w, flag, nn, v_(t)), with nn given by its rank ⌊log_ρ nn⌋.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::enqueue(const Pt& w, int type, int rank, const OpKey& from, Op& fromop) -> void {
  Time tw;
  tw.rank = rank;
  tw.type = type;
  tw.color = type ? color(w, tw.rank) : 0;
  if (!(tw > from.t)) return;
  OpKey k{tw, w};
  if (std::find(fromop.targets.begin(), fromop.targets.end(), k) != fromop.targets.end()) return;
  Op& op = get_op(k);
  op.sources.push_back(from);
  fromop.targets.push_back(k);
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::input_dispatch_time(const Pt& v) -> Time {
  K l = vtx.at(v).leaf;
  Q side2 = Q(1);
  Q quarter(1, 4);
  for (int i = 0; i < l.level; ++i) side2 *= quarter;
  Time t;
  t.rank = rank_of(side2);
  t.type = 0;
  return t;
}

// The indexes the canonical graph does not show (issue 11 §2), checked after every command of
// the Lemma 3.4.2 property: readers are exactly the inverse of the reads, sources exactly the
// inverse of the targets, every vertex in the leaf locate() gives (and listed there), leaves are
// the tree's leaves, nothing pending, valid adjacency caches equal the tree's adjacency.
template <std::size_t D>
auto WellSpacedSet<D>::Impl::check_internal_indexes() const -> std::string {
  auto name = [](const OpKey& k) { return "(" + fmt_point<D>(k.v) + " @" + k.t.str() + ")"; };
  if (!pending.empty()) return std::to_string(pending.size()) + " operations pending";
  std::size_t reads = 0;
  for (const auto& rec : ops) {
    const auto& [k, op] = rec;
    for (const K& s : op.reads) {
      ++reads;
      auto it = leaves.find(s);
      if (it == leaves.end() || std::count(it->second.readers.begin(), it->second.readers.end(), &rec) != 1)
        return "square " + s.str() + " read by " + name(k) + " does not list it once as a reader";
    }
    for (const OpKey& t : op.targets) {
      auto it = ops.find(t);
      if (it == ops.end()) return name(k) + " targets a missing operation " + name(t);
      if (std::count(it->second.sources.begin(), it->second.sources.end(), k) != 1)
        return name(t) + " does not list its source " + name(k) + " once";
    }
    for (const OpKey& src : op.sources) {
      auto it = ops.find(src);
      if (it == ops.end() || std::count(it->second.targets.begin(), it->second.targets.end(), k) != 1)
        return name(k) + " lists a source " + name(src) + " that does not target it once";
    }
  }
  std::size_t listed = 0;
  for (const auto& [s, L] : leaves) {
    listed += L.readers.size();
    for (const OpRec* r : L.readers) {
      auto it = ops.find(r->first);
      if (it == ops.end() || &*it != r || std::count(it->second.reads.begin(), it->second.reads.end(), s) != 1)
        return name(r->first) + " is a reader of " + s.str() + " without reading it";
    }
  }
  if (listed != reads) return "reader lists hold " + std::to_string(listed) + " entries for " + std::to_string(reads) + " reads";
  auto tl = tree.leaves();
  if (tl.size() != leaves.size()) return "leaf store holds " + std::to_string(leaves.size()) + " squares, the tree " + std::to_string(tl.size());
  std::size_t inside = 0;
  for (const K& l : tl) {
    auto it = leaves.find(l);
    if (it == leaves.end()) return "tree leaf " + l.str() + " missing from the leaf store";
    const Leaf& L = it->second;
    inside += L.verts.size();
    for (const Pt& x : L.verts)
      if (!(tree.locate(x) == l) || !vtx.count(x) || !(vtx.at(x).leaf == l))
        return "vertex " + fmt_point<D>(x) + " listed in " + l.str() + " but located elsewhere";
    if (L.adjacent_ok) {
      auto want = tree.adjacent_leaves(l);
      if (want.size() != L.adjacent.size()) return "stale adjacency cache at " + l.str();
      for (std::size_t i = 0; i < want.size(); ++i)
        if (!(L.adjacent[i]->key == want[i])) return "stale adjacency cache at " + l.str();
    }
  }
  if (inside != vtx.size()) return std::to_string(vtx.size()) + " vertices, " + std::to_string(inside) + " listed in leaves";
  return "";
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::canonical_graph() const -> std::vector<std::string> {
  std::vector<std::string> out;
  for (const K& l : tree.leaves()) out.push_back("S " + l.str());
  for (const auto& [k, op] : ops) {
    std::string name = "(" + fmt_point<D>(k.v) + " @" + k.t.str() + ")";
    out.push_back("O " + name + (op.executed ? " x" : ""));
    if (op.input_source) out.push_back("E (" + fmt_point<D>(k.v) + " @0) -> " + name);
    for (const OpKey& t : op.targets)
      out.push_back("E " + name + " -> (" + fmt_point<D>(t.v) + " @" + t.t.str() + ")");
    for (const K& s : op.reads) out.push_back("R " + s.str() + " -> " + name);
    for (const Pt& w : op.steiners) out.push_back("W " + name + " -> " + tree.locate(w).str() + " [" + fmt_point<D>(w) + "]");
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::computation_graph() const -> std::vector<GraphOperation<D>> {
  using Square = typename GraphOperation<D>::Square;
  auto square = [](const K& s) { return Square{s.level, s.k}; };
  std::map<OpKey, std::size_t> index;
  for (const auto& [k, op] : ops) index.emplace(k, index.size());
  std::vector<GraphOperation<D>> out;
  for (const auto& [k, op] : ops) {
    GraphOperation<D> g;
    g.v = k.v.below();
    g.rank = k.t.rank;
    g.fill = k.t.type == 1;
    g.color = k.t.color;
    g.executed = op.executed;
    g.input_dispatch = op.input_source;
    for (const OpKey& t : op.targets) g.targets.push_back(index.at(t));
    std::sort(g.targets.begin(), g.targets.end());
    for (const K& s : op.reads) g.reads.push_back(square(s));
    std::sort(g.reads.begin(), g.reads.end());
    for (const Pt& w : op.steiners) g.steiners.emplace_back(w.below(), square(tree.locate(w)));
    std::sort(g.steiners.begin(), g.steiners.end());
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace kmr::wellspaced
