#pragma once
// PropagateWS, Insert and Delete (Fig. 3.8). After an update, the computation graph equals that of
// a from-scratch run on the new input (Lemma 3.4.2; test WellspacedDynamic.L3_4_2_*). The proof
// rests on these invariants, kept here and in computation_graph.hpp:
//  (I1) Time order. Every effect of an operation at time t lands strictly later: Enqueue creates
//       only targets with time > t, and a Steiner vertex created at t is visible only to
//       operations later than t (QTClippedVoronoi reads vertices created before its caller).
//       So popping `pending` in increasing (time, vertex) order, each operation sees everything
//       earlier already consistent with the new input, and is processed at most once per update.
//  (I2) Locality. An operation's result (reads, targets, Steiner vertices) is a function of its
//       key and of the vertices visible to it in the squares it reads; so only operations that
//       read a changed square, or whose sources changed, can change.
//  (I3) Marking. Every change to the contents of a square at time t — v̂ itself (t = 0), obsolete
//       and fresh squares of the tree change, a Steiner vertex inserted or deleted by an operation
//       at t — queues the readers of that square later than t (MarkReaders).
//  (I4) Existence. An operation exists iff it has the input edge v_(0) or a source; when its last
//       source drops it, it is queued and, when popped, undone and deleted (obsolete, Ω⊖).
//  (I5) Indexes (check_internal_indexes): the readers of leaf s are exactly the executed
//       operations that read s, and only leaves are read; sources are the inverse of targets;
//       each vertex is in the leaf locate() gives; nothing is pending between updates.
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
auto WellSpacedSet<D>::Impl::undo(const OpKey& k, Op& op) -> void {
  const OpRec* self = &*ops.find(k);
  for (const K& s : op.reads) {
    auto it = leaves.find(s);  // gone: s stopped being a leaf, and its reader list went with it
    if (it != leaves.end()) {
      auto& rs = it->second.readers;
      auto at = std::find(rs.begin(), rs.end(), self);
      KMR_CHECK(at != rs.end(), "undo: operation missing from its square's readers");
      *at = rs.back();
      rs.pop_back();
    }
  }
  for (const OpKey& t : op.targets) {
    auto& src = ops.at(t).sources;
    src.erase(std::find(src.begin(), src.end(), k));
  }
  for (const Pt& w : op.steiners) {
    unplace(w);
    vtx.erase(w);
  }
  op.reads.clear();
  op.executed = false;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::process(const OpKey& k) -> void {
  auto it = ops.find(k);
  if (it == ops.end()) return;
  Op& op = it->second;
  bool had = op.executed;
  std::vector<OpKey> old_targets = op.targets;
  std::vector<Pt> old_steiners = op.steiners;
  std::vector<K> old_steiner_leaves;
  for (const Pt& w : old_steiners) old_steiner_leaves.push_back(vtx.at(w).leaf);
  if (had) undo(k, op);
  op.targets.clear();
  op.steiners.clear();
  bool exists = op.input_source || !op.sources.empty();
  if (exists && k.t.rank <= rmax) {
    KMR_CHECK(vtx.count(k.v), "operation on a vertex that does not exist");
    if (k.t.type == 0) dispatch(k, op);
    else fill(k, op);
    op.executed = true;
    for (Leaf* L : read_leaves) L->readers.push_back(&*it);
  }
  // targets no longer enqueued by k
  for (const OpKey& t : old_targets)
    if (std::find(op.targets.begin(), op.targets.end(), t) == op.targets.end()) {
      const Op& o = ops.at(t);
      if (!o.input_source && o.sources.empty()) pending.insert(t);
    }
  // Steiner vertices changed: MarkReaders(square of w, t)
  for (std::size_t i = 0; i < old_steiners.size(); ++i)
    if (std::find(op.steiners.begin(), op.steiners.end(), old_steiners[i]) == op.steiners.end()) {
      mark_readers(old_steiner_leaves[i], k.t);
      if (upd) upd->steiner_deleted++;
    }
  for (const Pt& w : op.steiners)
    if (std::find(old_steiners.begin(), old_steiners.end(), w) == old_steiners.end()) {
      mark_readers(vtx.at(w).leaf, k.t);
      if (upd) upd->steiner_inserted++;
    }
  if (upd) {
    if (had && exists) upd->inconsistent++;
    else if (had && !exists) upd->obsolete++;
    else if (!had && exists) upd->fresh++;
    else upd->obsolete++;
  }
  if (!exists) erase_op(it);
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::propagate() -> void {
  std::size_t processed = 0;
  auto step = [&](const OpKey& k) {
    process(k);
    if (params.progress && ++processed % 1024 == 0) params.progress(vtx.size(), processed);
  };
  if (params.bucket_shuffle_seed == 0) {
    while (!pending.empty()) {
      OpKey k = *pending.begin();
      pending.erase(pending.begin());
      step(k);
    }
    return;
  }
  // test hook: each time bucket in a seeded random order ((I1): processing adds only later times)
  std::mt19937_64 rng(params.bucket_shuffle_seed);
  std::vector<OpKey> bucket;
  while (!pending.empty()) {
    const Time t = pending.begin()->t;
    bucket.clear();
    for (auto it = pending.begin(); it != pending.end() && it->t == t;) {
      bucket.push_back(*it);
      it = pending.erase(it);
    }
    std::shuffle(bucket.begin(), bucket.end(), rng);
    for (const OpKey& k : bucket) step(k);
  }
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::set_input_dispatch(const Pt& v) -> void {
  Time t = input_dispatch_time(v);
  OpKey k{t, v};
  Op& op = get_op(k);
  op.input_source = true;
  pending.insert(k);
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::clear_input_dispatch(const Pt& v) -> void {
  // the input dispatch of v is the unique dispatch of v with input_source
  for (auto& [k, op] : ops_of(v))
    if (op->input_source) {
      op->input_source = false;
      pending.insert(k);
    }
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::ops_of(const Pt& v) -> std::vector<std::pair<OpKey, Op*>> {
  std::vector<std::pair<OpKey, Op*>> out;
  auto bv = ops_by_vertex.find(v);
  if (bv == ops_by_vertex.end()) return out;
  for (const Time& t : bv->second) {
    OpKey k{t, v};
    out.emplace_back(k, &ops.at(k));
  }
  return out;
}

// Applies a tree change: moves the vertices of obsolete squares into the fresh ones, and returns
// the input vertices that moved (their dispatch time may change).
template <std::size_t D>
auto WellSpacedSet<D>::Impl::apply_tree_change(const typename Quadtree<D>::Change& ch) -> std::vector<Pt> {
  std::vector<Pt> moved;
  for (const K& s : ch.obsolete) {
    auto it = leaves.find(s);
    if (it == leaves.end()) continue;
    for (const Pt& x : it->second.verts) moved.push_back(x);
    leaves.erase(it);
  }
  for (const K& s : ch.fresh) leaf_of(s);
  // a leaf's adjacency changes only if an adjacent leaf appeared or disappeared; every leaf now
  // covering a vanished leaf's region is fresh, so the fresh leaves and their neighbours suffice
  for (const K& s : ch.fresh)
    for (const K& n : tree.adjacent_leaves(s)) leaves.at(n).adjacent_ok = false;
  std::vector<Pt> inputs;
  for (const Pt& x : moved) {
    place(x);
    if (!vtx.at(x).steiner) inputs.push_back(x);
  }
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::redo_input_dispatch(const Pt& u) -> void {
  Time t = input_dispatch_time(u);
  for (auto& [k, op] : ops_of(u))
    if (op->input_source && !(k.t == t)) {
      op->input_source = false;
      pending.insert(k);
    }
  OpKey k{t, u};
  Op& op = get_op(k);
  if (!op.input_source) {
    op.input_source = true;
    pending.insert(k);
  }
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::insert(const Point<D>& p) -> UpdateStats {
  auto t0 = std::chrono::steady_clock::now();
  validate_point<D>(p, "inserted point");
  if (vtx.count(p) && !vtx.at(p).steiner) throw InputError("inserted point " + fmt_point<D>(p) + " is already an input point");
  UpdateStats us;
  upd = &us;
  auto ch = tree.update(p, +1, [&](const K& l) { return leaf_input(l); });  // QTInsertInput (may throw: nothing changed)
  us.obsolete_squares = ch.obsolete.size();
  us.fresh_squares = ch.fresh.size();
  for (const K& s : ch.obsolete) mark_readers(s, Time{});  // MarkReaders(s, 0)
  // A Steiner vertex at exactly p becomes an input vertex: take it from its creator, which is
  // re-executed (it reads p's square after time 0).
  if (vtx.count(p)) {
    for (auto& [k, op] : ops) {
      auto w = std::find(op.steiners.begin(), op.steiners.end(), p);
      if (w == op.steiners.end()) continue;
      op.steiners.erase(w);
      mark_readers(vtx.at(p).leaf, k.t);
      pending.insert(k);
      break;
    }
    unplace(p);
    vtx.erase(p);
    us.steiner_deleted++;
  }
  std::vector<Pt> moved = apply_tree_change(ch);
  Vtx V;
  vtx.emplace(p, std::move(V));
  place(p);
  ++n_input;
  mark_readers(vtx.at(p).leaf, Time{});
  for (const Pt& u : moved) redo_input_dispatch(u);
  set_input_dispatch(p);
  propagate();
  upd = nullptr;
  us.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return us;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::erase(const Point<D>& p) -> UpdateStats {
  auto t0 = std::chrono::steady_clock::now();
  validate_point<D>(p, "deleted point");
  auto it = vtx.find(p);
  if (it == vtx.end() || it->second.steiner) throw InputError("deleted point " + fmt_point<D>(p) + " is not an input point");
  if (n_input <= 2) throw InputError("cannot delete: at least 2 input points must remain");
  UpdateStats us;
  upd = &us;
  K old_leaf = it->second.leaf;
  auto ch = tree.update(p, -1, [&](const K& l) { return leaf_input(l); });  // QTDeleteInput
  us.obsolete_squares = ch.obsolete.size();
  us.fresh_squares = ch.fresh.size();
  mark_readers(old_leaf, Time{});
  for (const K& s : ch.obsolete) mark_readers(s, Time{});
  unplace(p);
  clear_input_dispatch(p);
  vtx.erase(p);
  --n_input;
  std::vector<Pt> moved = apply_tree_change(ch);
  for (const Pt& u : moved) redo_input_dispatch(u);
  propagate();
  upd = nullptr;
  us.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return us;
}

}  // namespace kmr::wellspaced
