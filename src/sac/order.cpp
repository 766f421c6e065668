#include "sac/order.hpp"

#include <string>

#include "exact/error.hpp"

namespace kmr::sac {

namespace {
constexpr std::uint64_t kTopEnd = std::uint64_t{1} << 62;  // group labels lie in [0, kTopEnd)
constexpr std::uint32_t kLabelEnd = OrderList::kLabelEnd;
constexpr std::uint32_t kAppendStep = OrderList::kAppendStep;
constexpr std::uint64_t kGroupAppendStep = std::uint64_t{1} << 32;   // 2^30 appended groups fit
static_assert((std::uint64_t{OrderList::kGroupMax} + 1) * kAppendStep <= kLabelEnd);
static_assert(OrderList::kAppendFill >= 1 && OrderList::kAppendFill <= OrderList::kGroupMax);
}

OrderList::OrderList() {
  auto* g = new OmGroup;
  g->label = kTopEnd / 2;
  g->first = &base_;
  g->size = 1;
  first_group_ = g;
  groups_ = 1;
  base_.group = g;
  base_.label = 0;
}

OrderList::~OrderList() {
  for (OmGroup* g = first_group_; g;) {
    OmGroup* n = g->next;
    delete g;
    g = n;
  }
}

// Spreads the stamps of g evenly over the 32-bit label space.
void OrderList::relabel_group(OmGroup* g) {
  std::uint32_t step = kLabelEnd / (g->size + 1);
  std::uint32_t l = 0;
  for (Stamp* s = g->first; s && s->group == g; s = s->next) {
    s->label = l;
    l += step;
    ++relabels_;
  }
}

// Bender et al. (2002): if g has no free label after it, find the smallest aligned label range
// [lo, lo + 2^i) around g whose group count is below (2/T)^i (T ≈ 1.41) and spread its groups
// evenly. Amortized O(log #groups) relabels per new group; a new group comes once per Θ(kGroupMax)
// stamps, so stamps pay amortized O(1).
OmGroup* OrderList::insert_group_after(OmGroup* g) {
  std::uint64_t hi = g->next ? g->next->label : kTopEnd;
  if (hi - g->label < 2) {
    OmGroup *first = g, *last = g;
    std::uint64_t count = 1;
    double cap = 1;
    bool done = false;
    for (int i = 1; i <= 62 && !done; ++i) {
      cap *= 1.41;
      std::uint64_t size = std::uint64_t{1} << i;
      std::uint64_t lo = g->label & ~(size - 1);
      std::uint64_t end = lo + size;
      while (first->prev && first->prev->label >= lo) first = first->prev, ++count;
      while (last->next && last->next->label < end) last = last->next, ++count;
      if (static_cast<double>(count + 1) <= cap && size / (count + 1) >= 2) {
        std::uint64_t step = size / (count + 1), l = lo;
        for (OmGroup* t = first;; t = t->next) {
          t->label = l;
          l += step;
          ++relabels_;
          if (t == last) break;
        }
        done = true;
      }
    }
    if (!done) {  // more groups than the label space allows at this density: spread them all (untested: i = 62 takes up to 1.41^62 ≈ 1.78·10^9 groups)
      std::uint64_t step = kTopEnd / (groups_ + 2), l = step;
      for (OmGroup* t = first_group_; t; t = t->next, l += step) {
        t->label = l;
        ++relabels_;
      }
    }
    hi = g->next ? g->next->label : kTopEnd;
    KMR_CHECK(hi - g->label >= 2, "OrderList: no free group label after relabelling");
  }
  auto* h = new OmGroup;
  std::uint64_t half = (hi - g->label) / 2;  // after the last group: a bounded step (appends)
  h->label = g->label + (!g->next && half > kGroupAppendStep ? kGroupAppendStep : half);
  h->prev = g;
  h->next = g->next;
  if (g->next) g->next->prev = h;
  g->next = h;
  ++groups_;
  return h;
}

void OrderList::remove_group(OmGroup* g) {
  // Never the first group: that one holds the base stamp, which is never removed (and a split
  // leaves the base in its group), so g->prev exists.
  g->prev->next = g->next;
  if (g->next) g->next->prev = g->prev;
  --groups_;
  delete g;
}

void OrderList::split(OmGroup* g) {
  OmGroup* h = insert_group_after(g);
  ++splits_;
  Stamp* s = g->first;
  for (std::uint32_t i = 0; i < g->size / 2; ++i) s = s->next;
  h->first = s;
  std::uint32_t moved = 0;
  for (; s && s->group == g; s = s->next) {
    s->group = h;
    ++moved;
  }
  g->size -= moved;
  h->size = moved;
  relabel_group(g);
  relabel_group(h);
}

void OrderList::insert_after_slow(Stamp* x, Stamp* y) {
  Stamp* nx = x->next;
  bool at_group_end = !nx || nx->group != x->group;
  if (x->group->size >= kGroupMax || (!nx && x->group->size >= kAppendFill)) {
    if (at_group_end) {
      // Appending after a full group's last stamp, or at the end of the list after kAppendFill
      // stamps (the common case: a run appends at the end of the trace): start a new group
      // instead of splitting, so no stamp is relabelled.
      OmGroup* h = insert_group_after(x->group);
      h->first = y;
      h->size = 1;
      y->label = kAppendStep;
      y->group = h;
      link_after(x, y);
      return;
    }
    split(x->group);
    at_group_end = nx->group != x->group;  // nx exists: x was not at its group's end before the split
  }
  OmGroup* g = x->group;
  std::uint32_t hi = at_group_end ? kLabelEnd : nx->label;
  if (hi - x->label < 2) {
    relabel_group(g);
    hi = at_group_end ? kLabelEnd : nx->label;
  }
  // After the group's last stamp, step by at most kAppendStep (kGroupMax such steps fit), so runs
  // of appends never exhaust the labels; elsewhere, the midpoint.
  std::uint32_t gap = (hi - x->label) / 2;
  y->label = x->label + (at_group_end && gap > kAppendStep ? kAppendStep : gap);
  y->group = g;
  link_after(x, y);
  ++g->size;
}

void OrderList::link_after(Stamp* x, Stamp* y) {
  Stamp* nx = x->next;
  y->prev = x;
  y->next = nx;
  if (nx) nx->prev = y;
  else last_ = y;
  x->next = y;
  ++size_;
}

void OrderList::remove(Stamp* y) {
  KMR_CHECK(y != &base_, "OrderList: the base stamp cannot be removed");
  OmGroup* g = y->group;
  if (g->first == y) g->first = (y->next && y->next->group == g) ? y->next : nullptr;
  y->prev->next = y->next;
  if (y->next) y->next->prev = y->prev;
  else last_ = y->prev;
  --size_;
  if (--g->size == 0) remove_group(g);
  y->prev = y->next = nullptr;
  y->group = nullptr;
}

void OrderList::check() const {
  std::size_t n = 0;
  for (const Stamp* s = &base_; s; s = s->next) {
    ++n;
    if (s->next) KMR_CHECK(before(s, s->next), "OrderList: labels do not increase at stamp " + std::to_string(n));
    KMR_CHECK(s->group->first != nullptr, "OrderList: group without first stamp");
  }
  KMR_CHECK(n == size_, "OrderList: size mismatch");
}

}  // namespace kmr::sac
