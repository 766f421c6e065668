#pragma once
// Lists for self-adjusting programs, in ΔML's shape: `'a cell = NIL | CONS of 'a * 'a cell Box.t`
// (App. A.2), the generic stable building blocks the benchmark programs share, and the editable
// input list. Guarantees (tested in tests/sac and proptests/sac):
//  * ListInput holds the input as input modifiables named by element ids, so two runtimes given the
//    same (ids, values) build inputs with the same names (the from-scratch comparison relies on it);
//    insert/erase/set change O(1) modifiables; released cells are freed after propagation.
//  * filter_into keeps the elements with keep(ctx, x) in order; reduce folds an associative,
//    commutative Op by randomized contraction (coins from cell names and round), so an edit changes
//    O(1) expected cells per round and O(log n) expected rounds (a stable reduction, not a left fold).
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sac/runtime.hpp"

namespace kmr::sacprograms {

using sac::Label;
using sac::Mod;
using sac::Runtime;

template <class T>
struct Cons {
  bool nil = true;
  T head{};
  Mod<Cons>* tail = nullptr;
  bool operator==(const Cons&) const = default;
};
template <class T>
std::uint64_t canon_value(const Cons<T>& c) {  // the signature's digest of a cell (tail by name)
  return c.nil ? 0x4e11 : sac::mix(sac::mix(0xc0, sac::value_hash(c.head)), sac::canon_key(c.tail));
}
using Cell = Cons<long long>;
using List = Mod<Cell>;    // a list is a box holding a cell
using Root = Mod<List*>;   // the box holding the first box of the input (or output) list

struct Unit {
  bool operator==(const Unit&) const = default;
};
inline std::uint64_t canon_value(const Unit&) { return 0x0; }

inline bool coin(const sac::ModBase* m, std::uint64_t round) { return sac::mix(m->name, round * 0x9e37 + 17) & 1; }

// Reads a list through Meta.deref (no trace).
std::vector<long long> to_vector(const Runtime& rt, const List* l);
std::vector<long long> to_vector(const Runtime& rt, const Root* r);

// The editable input list: root → box(e0) → box(e1) → ... → nil box. Edits by cell are O(1)
// expected (predecessors in a side table); positional edits walk the list (for tests).
class ListInput {
 public:
  ListInput(Runtime& rt, const std::vector<long long>& values, const std::vector<std::uint64_t>& ids);
  Root* root() const { return root_; }
  std::size_t size() const { return pool_.size(); }
  List* insert_after(List* pred, std::uint64_t id, long long value);  // pred null: at the front
  void erase(List* cell);
  void set(List* cell, long long value);
  List* cell_at(std::size_t pos) const;           // O(pos)
  List* random_cell(std::uint64_t r) const;       // uniform over the live cells (for benchmarks)
  void insert(std::size_t pos, std::uint64_t id, long long value);  // new element at position pos
  void erase(std::size_t pos);
  void set(std::size_t pos, long long value);
  void propagate();  // rt.propagate(), then release the erased cells
  std::vector<long long> values() const;

 private:
  void point(List* pred, List* to);  // makes pred (or the root if null) point at `to`
  void add(List* cell, List* pred);
  Runtime& rt_;
  Root* root_;
  List* nil_;
  std::vector<List*> pool_;                      // live cells, in no particular order
  std::unordered_map<List*, std::size_t> where_;  // cell → index in pool_ (lookup only)
  std::unordered_map<List*, List*> prev_;        // cell → predecessor cell (null: first)
  std::vector<List*> released_;
};

// The entry point of a list program: inside rt.run, allocates the output root under `out_label`
// and, inside a read of the input root, writes body(rt, first box)'s result to it.
template <class F>
Root* run_list_program(Runtime& rt, Root* in, const Label& out_label, F body) {
  return rt.run([r = &rt, in, lab = &out_label, body] {
    Root* out = r->alloc<List*>(*lab);
    r->read(in, [r, out, body](List* l) { r->write(out, body(r, l)); });
    return out;
  });
}

// ---- filter with context: dest := [x ∈ l | P::keep(ctx, x)] (destination passing) -----------
template <class P>
struct Filter {
  using Ctx = typename P::Ctx;
  static Unit into(Runtime* rt, List* l, Ctx ctx, List* dest) {
    rt->memo_read<void>(P::kFilter, std::make_tuple(l, ctx, dest), l, [rt, l, ctx, dest](const Cell& c) {
      if (c.nil) {
        rt->write(dest, Cell{});
      } else if (P::keep(ctx, c.head)) {
        // P::kByValue: name the cell by the element's value, not by its cell (whose name may
        // itself come from an earlier filter and would shift with edits, cascading).
        List* cell = P::kByValue ? rt->alloc<Cell>(P::kCell, c.head, ctx) : rt->alloc<Cell>(P::kCell, l, ctx);
        rt->write(dest, Cell{false, c.head, cell});
        into(rt, c.tail, ctx, cell);
      } else {
        into(rt, c.tail, ctx, dest);
      }
    });
    return Unit{};
  }
};

// ---- reduce by randomized contraction: res := Op::combine over l (Op::identity if empty) -------
template <class Op>
struct Reduce {
  using Ctx = typename Op::Ctx;
  // One round: the blocks of l (a block ends before every cell whose coin is heads) → block sums.
  static List* half(Runtime* rt, List* l, Ctx ctx, std::uint64_t r) {
    return rt->memo_read<Cell>(Op::kHalf, std::make_tuple(l, ctx, r), l, [rt, ctx, r](const Cell& c, List* dest) {
      if (c.nil) rt->write(dest, Cell{});
      else absorb(rt, c.tail, c.head, ctx, r, dest);
    });
  }
  static Unit absorb(Runtime* rt, List* l, long long acc, Ctx ctx, std::uint64_t r, List* dest) {
    rt->memo_read<void>(Op::kAbsorb, std::make_tuple(l, acc, ctx, r, dest), l, [rt, l, acc, ctx, r, dest](const Cell& c) {
      if (c.nil || coin(l, r)) rt->write(dest, Cell{false, acc, half(rt, l, ctx, r)});
      else absorb(rt, c.tail, Op::combine(ctx, acc, c.head), ctx, r, dest);
    });
    return Unit{};
  }
  static Unit run(Runtime* rt, List* l, Ctx ctx, std::uint64_t r, Mod<long long>* res) {
    rt->memo_read<void>(Op::kReduce, std::make_tuple(l, ctx, r, res), l, [rt, l, ctx, r, res](const Cell& c) {
      if (c.nil) {
        rt->write(res, Op::identity(ctx));
        return;
      }
      long long h = c.head;
      rt->read(c.tail, [rt, l, ctx, r, res, h](const Cell& c2) {
        if (c2.nil) rt->write(res, h);
        else run(rt, half(rt, l, ctx, r), ctx, r + 1, res);
      });
    });
    return Unit{};
  }
};

// ---- static twins: the same algorithms without tracing, over plain heap lists ----------------
struct SCell {
  long long head;
  SCell* tail;
};
// A bump arena of cells, so static twins pay for allocation as the self-adjusting ones do.
class SArena {
 public:
  SArena() = default;
  SArena(const SArena&) = delete;
  ~SArena();
  SCell* cell(long long h, SCell* t);

 private:
  std::vector<SCell*> blocks_;
  std::size_t used_ = 0;
};
SCell* to_slist(SArena& arena, const std::vector<long long>& v);
std::vector<long long> to_vector(const SCell* l);

}  // namespace kmr::sacprograms
