// map, filter and sum (ΔML / CEAL benchmark set), self-adjusting and static.
#include "sacprograms/internal.hpp"

namespace kmr::sacprograms {

// 3x + 1 modulo 2^64 (unsigned arithmetic: defined for every input, no signed overflow; the static
// twin and the references call this same function).
long long map_fn(long long x) { return static_cast<long long>(3ULL * static_cast<unsigned long long>(x) + 1ULL); }
bool keep_fn(long long x) { return (x & 3) != 0; }

namespace {
constexpr Label kMap{"map"}, kMapOut{"map.out"};

// ΔML map's loop as a destination-passing memo whose body is one read: call, output cell, read and
// write share one trace node (memo_read).
List* map_list(Runtime* rt, List* l) {
  return rt->memo_read<Cell>(kMap, l, l, [rt](const Cell& c, List* dest) {
    if (c.nil) rt->write(dest, Cell{});
    else rt->write(dest, Cell{false, map_fn(c.head), map_list(rt, c.tail)});
  });
}

struct Keep {
  using Ctx = long long;
  static constexpr Label kFilter{"filter"}, kCell{"filter.cell"};
  static constexpr bool kByValue = false;
  static bool keep(Ctx, long long x) { return keep_fn(x); }
};
constexpr Label kFilterHead{"filter.head"}, kFilterOut{"filter.out"};

struct Plus {
  using Ctx = long long;
  static constexpr Label kHalf{"sum.half"}, kAbsorb{"sum.absorb"}, kReduce{"sum.reduce"};
  static long long combine(Ctx, long long a, long long b) {
    return static_cast<long long>(static_cast<unsigned long long>(a) + static_cast<unsigned long long>(b));
  }
  static long long identity(Ctx) { return 0; }
};
constexpr Label kSumOut{"sum.out"};

}  // namespace

Root* sa_map(Runtime& rt, Root* in) { return run_list_program(rt, in, kMapOut, map_list); }

Root* sa_filter(Runtime& rt, Root* in) {
  return run_list_program(rt, in, kFilterOut, [](Runtime* r, List* l) {
    List* head = r->alloc<Cell>(kFilterHead);
    Filter<Keep>::into(r, l, 0, head);
    return head;
  });
}

Mod<long long>* sa_sum(Runtime& rt, Root* in) {
  return rt.run([r = &rt, in] {
    Mod<long long>* out = r->alloc<long long>(kSumOut);
    r->read(in, [r, out](List* l) { Reduce<Plus>::run(r, l, 0, 0, out); });
    return out;
  });
}

SCell* static_map(const SCell* l, SArena& a) {
  SCell* head = nullptr;
  SCell** dest = &head;
  for (; l; l = l->tail) {
    *dest = a.cell(map_fn(l->head), nullptr);
    dest = &(*dest)->tail;
  }
  return head;
}

SCell* static_filter(const SCell* l, SArena& a) {
  SCell* head = nullptr;
  SCell** dest = &head;
  for (; l; l = l->tail) {
    if (!keep_fn(l->head)) continue;
    *dest = a.cell(l->head, nullptr);
    dest = &(*dest)->tail;
  }
  return head;
}

// The same contraction without tracing: blocks end before a cell whose coin (from its position in
// the round's list and the round) is heads.
long long static_sum(const SCell* l) {
  std::vector<long long> cur;
  for (; l; l = l->tail) cur.push_back(l->head);
  std::uint64_t r = 0;
  while (cur.size() > 1) {
    std::size_t w = 0;
    for (std::size_t j = 0; j < cur.size();) {
      long long acc = cur[j];
      std::size_t k = j + 1;
      for (; k < cur.size() && !(sac::mix(k, r * 0x9e37 + 17) & 1); ++k) acc = Plus::combine(0, acc, cur[k]);
      cur[w++] = acc;
      j = k;
    }
    cur.resize(w);
    ++r;
  }
  return cur.empty() ? 0 : cur[0];
}

}  // namespace kmr::sacprograms
