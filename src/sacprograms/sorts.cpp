// quicksort and mergesort (ΔML / CEAL benchmark set), self-adjusting and static.
#include "sacprograms/internal.hpp"

namespace kmr::sacprograms {

namespace {
// ---- quicksort: qs(l, rest) = sort(l) ++ rest, first element as pivot -------------------------
constexpr Label kQs{"qsort"}, kQsSplit{"qsort.split"}, kQsLes{"qsort.les"}, kQsGrt{"qsort.grt"},
    kQsMid{"qsort.mid"}, kQsMidTail{"qsort.midtail"}, kQsLCell{"qsort.lcell"}, kQsGCell{"qsort.gcell"},
    kQsNil{"qsort.nil"}, kQsHead{"qsort.head"}, kQsOut{"qsort.out"};

// Cells are keyed by (element cell, pivot cell): unique within a run, as keys must be.
Unit qs_split(Runtime* rt, List* l, long long p, List* pk, List* dl, List* dg) {
  rt->memo_read<void>(kQsSplit, std::make_tuple(l, p, pk, dl, dg), l, [rt, l, p, pk, dl, dg](const Cell& c) {
    if (c.nil) {
      rt->write(dl, Cell{});
      rt->write(dg, Cell{});
    } else if (c.head < p) {
      List* cell = rt->alloc<Cell>(kQsLCell, l, pk);
      rt->write(dl, Cell{false, c.head, cell});
      qs_split(rt, c.tail, p, pk, cell, dg);
    } else {
      List* cell = rt->alloc<Cell>(kQsGCell, l, pk);
      rt->write(dg, Cell{false, c.head, cell});
      qs_split(rt, c.tail, p, pk, dl, cell);
    }
  });
  return Unit{};
}

Unit qs(Runtime* rt, List* l, List* rest, List* dest) {
  rt->memo_read<void>(kQs, std::make_tuple(l, rest, dest), l, [rt, l, rest, dest](const Cell& c) {
    if (c.nil) {
      rt->read(rest, [rt, dest](const Cell& v) { rt->write(dest, v); });
      return;
    }
    List* les = rt->alloc<Cell>(kQsLes, l);
    List* grt = rt->alloc<Cell>(kQsGrt, l);
    qs_split(rt, c.tail, c.head, l, les, grt);
    List* mid = rt->alloc<Cell>(kQsMid, l);
    List* midtail = rt->alloc<Cell>(kQsMidTail, l);
    rt->write(mid, Cell{false, c.head, midtail});
    qs(rt, grt, rest, midtail);
    qs(rt, les, mid, dest);
  });
  return Unit{};
}

// ---- mergesort: split by coins of cell names, sort halves, merge (ΔML msort) -----------------
constexpr Label kMs{"msort"}, kMsSplit{"msort.split"}, kMsMerge{"msort.merge"}, kMsA{"msort.a"},
    kMsB{"msort.b"}, kMsSA{"msort.sa"}, kMsSB{"msort.sb"}, kMsCA{"msort.ca"}, kMsCB{"msort.cb"},
    kMsCell{"msort.cell"}, kMsHead{"msort.head"}, kMsOut{"msort.out"};

// The side of an element at depth d: a coin of its value (so an edit moves no other element), or,
// past depth 48 (only runs of equal values get there), of its cell's name.
bool ms_coin(const List* l, long long x, std::uint64_t d) {
  return d < 48 ? (sac::mix(static_cast<std::uint64_t>(x), d + 1000) & 1) : coin(l, d + 1000);
}

Unit ms_split(Runtime* rt, List* l, std::uint64_t d, List* a, List* b) {
  rt->memo_read<void>(kMsSplit, std::make_tuple(l, d, a, b), l, [rt, l, d, a, b](const Cell& c) {
    if (c.nil) {
      rt->write(a, Cell{});
      rt->write(b, Cell{});
    } else if (ms_coin(l, c.head, d)) {
      List* cell = rt->alloc<Cell>(kMsCA, l, d);
      rt->write(a, Cell{false, c.head, cell});
      ms_split(rt, c.tail, d, cell, b);
    } else {
      List* cell = rt->alloc<Cell>(kMsCB, l, d);
      rt->write(b, Cell{false, c.head, cell});
      ms_split(rt, c.tail, d, a, cell);
    }
  });
  return Unit{};
}

Unit ms_merge(Runtime* rt, List* a, List* b, std::uint64_t d, List* dest) {
  rt->memo_read<void>(kMsMerge, std::make_tuple(a, b, d, dest), a, [rt, a, b, d, dest](const Cell& ca) {
    rt->read(b, [rt, a, b, d, dest, ca](const Cell& cb) {
      if (ca.nil) {
        rt->write(dest, cb);
      } else if (cb.nil) {
        rt->write(dest, ca);
      } else if (ca.head <= cb.head) {
        List* cell = rt->alloc<Cell>(kMsCell, a);
        rt->write(dest, Cell{false, ca.head, cell});
        ms_merge(rt, ca.tail, b, d, cell);
      } else {
        List* cell = rt->alloc<Cell>(kMsCell, b);
        rt->write(dest, Cell{false, cb.head, cell});
        ms_merge(rt, a, cb.tail, d, cell);
      }
    });
  });
  return Unit{};
}

Unit ms(Runtime* rt, List* l, std::uint64_t d, std::uint64_t path, List* dest) {
  rt->memo_read<void>(kMs, std::make_tuple(l, d, path, dest), l, [rt, l, d, path, dest](const Cell& c) {
    if (c.nil) {
      rt->write(dest, Cell{});
      return;
    }
    rt->read(c.tail, [rt, l, d, path, dest, c](const Cell& c2) {
      if (c2.nil) {
        rt->write(dest, c);
        return;
      }
      List* a = rt->alloc<Cell>(kMsA, path);
      List* b = rt->alloc<Cell>(kMsB, path);
      ms_split(rt, l, d, a, b);
      List* sa = rt->alloc<Cell>(kMsSA, path);
      List* sb = rt->alloc<Cell>(kMsSB, path);
      ms(rt, a, d + 1, sac::mix(path, 1), sa);
      ms(rt, b, d + 1, sac::mix(path, 2), sb);
      ms_merge(rt, sa, sb, d, dest);
    });
  });
  return Unit{};
}
}  // namespace

Root* sa_quicksort(Runtime& rt, Root* in) {
  return run_list_program(rt, in, kQsOut, [](Runtime* r, List* l) {
    List* nil = r->alloc<Cell>(kQsNil);
    r->write(nil, Cell{});
    List* head = r->alloc<Cell>(kQsHead);
    qs(r, l, nil, head);
    return head;
  });
}

Root* sa_mergesort(Runtime& rt, Root* in) {
  return run_list_program(rt, in, kMsOut, [](Runtime* r, List* l) {
    List* head = r->alloc<Cell>(kMsHead);
    ms(r, l, 0, 0x6d73, head);
    return head;
  });
}

// ---- static twins -----------------------------------------------------------------------------
namespace {
SCell* static_qs(const SCell* l, SCell* rest, SArena& a) {
  if (!l) return rest;
  long long p = l->head;
  SCell *les = nullptr, *grt = nullptr;
  SCell **dl = &les, **dg = &grt;
  for (const SCell* c = l->tail; c; c = c->tail) {
    SCell* n = a.cell(c->head, nullptr);
    if (c->head < p) {
      *dl = n;
      dl = &n->tail;
    } else {
      *dg = n;
      dg = &n->tail;
    }
  }
  return static_qs(les, a.cell(p, static_qs(grt, rest, a)), a);
}

SCell* static_merge(SCell* x, SCell* y, SArena& a) {
  SCell* head = nullptr;
  SCell** dest = &head;
  while (x && y) {
    SCell*& from = (x->head <= y->head) ? x : y;
    *dest = a.cell(from->head, nullptr);
    dest = &(*dest)->tail;
    from = from->tail;
  }
  *dest = x ? x : y;
  return head;
}

// Split by coins of the position and depth (the self-adjusting version uses cell names).
SCell* static_ms(const SCell* l, std::uint64_t d, SArena& a) {
  if (!l || !l->tail) return const_cast<SCell*>(l);
  SCell *x = nullptr, *y = nullptr;
  SCell **dx = &x, **dy = &y;
  std::uint64_t i = 0;
  for (const SCell* c = l; c; c = c->tail, ++i) {
    SCell* n = a.cell(c->head, nullptr);
    if (sac::mix(i, d + 1000) & 1) {
      *dx = n;
      dx = &n->tail;
    } else {
      *dy = n;
      dy = &n->tail;
    }
  }
  return static_merge(static_ms(x, d + 1, a), static_ms(y, d + 1, a), a);
}
}  // namespace

SCell* static_quicksort(const SCell* l, SArena& a) { return static_qs(l, nullptr, a); }
SCell* static_mergesort(const SCell* l, SArena& a) { return static_ms(l, 0, a); }

}  // namespace kmr::sacprograms
