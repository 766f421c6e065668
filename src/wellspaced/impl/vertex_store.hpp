#pragma once
// The vertex store: the vertices in the leaves of the 2^D-tree (QTInsertSteiner, §3.1.2) and the
// cached adjacency of the leaves.
// Internal: included only by well_spaced_set.cpp (after impl/state.hpp).
#include "wellspaced/impl/state.hpp"

namespace kmr::wellspaced {

template <std::size_t D>
auto WellSpacedSet<D>::Impl::leaf_input(const K& leaf) const -> const Point<D>* {
  auto it = leaves.find(leaf);
  return it == leaves.end() ? nullptr : it->second.input;
}

// The leaf record of square s (created on first use).
template <std::size_t D>
auto WellSpacedSet<D>::Impl::leaf_of(const K& s) -> Leaf& {
  auto [it, fresh] = leaves.try_emplace(s);
  if (fresh) it->second.key = s;
  return it->second;
}

// Leaves adjacent to leaf L (sorted by key), cached per leaf (apply_tree_change invalidates).
template <std::size_t D>
auto WellSpacedSet<D>::Impl::adjacent_leaves(Leaf& L) -> const std::vector<Leaf*>& {
  if (!L.adjacent_ok) {
    L.adjacent.clear();
    for (const K& n : tree.adjacent_leaves(L.key)) L.adjacent.push_back(&leaves.at(n));
    L.adjacent_ok = true;
  }
  return L.adjacent;
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::place(const Pt& x) -> void {
  auto& V = vtx.at(x);
  K l = tree.locate(x);
  V.leaf = l;
  auto& L = leaf_of(l);
  L.verts.push_back(x);
  L.born.push_back(V.created);
  if (!V.steiner) {
    KMR_CHECK(L.input == nullptr, "crowding violated: two inputs in one square");
    L.input = &vtx.find(x)->first.below();  // inputs are doubles
  }
}

template <std::size_t D>
auto WellSpacedSet<D>::Impl::unplace(const Pt& x) -> void {
  auto& V = vtx.at(x);
  auto& L = leaves.at(V.leaf);
  const auto at = std::find(L.verts.begin(), L.verts.end(), x) - L.verts.begin();
  L.verts.erase(L.verts.begin() + at);
  L.born.erase(L.born.begin() + at);
  if (!V.steiner) L.input = nullptr;
}

}  // namespace kmr::wellspaced
