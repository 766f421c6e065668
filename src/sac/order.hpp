#pragma once
// OrderList: the order-maintenance list of timestamps behind the trace (§1.3.1: "function calls get
// assigned two time stamps ... so that the function calls can be ordered sequentially").
// Two-level labelling (Dietz–Sleator; Bender et al. 2002): stamps live in groups of at most
// kGroupMax with 32-bit labels inside the group; groups carry 62-bit labels, relabelled over the
// smallest sparse-enough aligned label range (Bender et al.'s density thresholds). Guarantees (each tested in tests/sac/order_test.cpp):
//  * before(a, b) is the list order, for every pair of live stamps, after any sequence of
//    insert_after / remove, including adversarial patterns (always after the same stamp, always
//    after the newest, alternating, front-heavy);
//  * insert_after and remove are amortized O(1); before is O(1) worst case;
//  * check() verifies that labels increase strictly along the list (group, then item label).
// Stamps are intrusive: the trace nodes of the runtime derive from Stamp.
#include <cstddef>
#include <cstdint>

namespace kmr::sac {

struct OmGroup;

// 28 bytes and 4 bytes of tail padding, which classes deriving from Stamp reuse (trace nodes keep
// their kind and size there): in-group labels are 32 bits (a group holds at most kGroupMax stamps).
struct Stamp {
  OmGroup* group = nullptr;
  Stamp* prev = nullptr;
  Stamp* next = nullptr;
  std::uint32_t label = 0;
};

struct OmGroup {
  std::uint64_t label = 0;
  OmGroup* prev = nullptr;
  OmGroup* next = nullptr;
  Stamp* first = nullptr;
  std::uint32_t size = 0;
};

class OrderList {
 public:
  static constexpr std::uint32_t kGroupMax = 64;
  // Appends at the end of the list (an initial run) fill a group to kAppendFill stamps only, so a
  // group of the initial trace takes kGroupMax − kAppendFill insertions by re-execution before it
  // splits (a split walks and relabels the group's stamps, cold trace: spec/sac.md, branch sac12).
  static constexpr std::uint32_t kAppendFill = 32;

  OrderList();
  ~OrderList();
  OrderList(const OrderList&) = delete;
  OrderList& operator=(const OrderList&) = delete;

  Stamp* base() { return &base_; }  // the first stamp; never removed
  const Stamp* base() const { return &base_; }
  Stamp* last() { return last_; }
  static constexpr std::uint32_t kLabelEnd = ~std::uint32_t{0};         // in-group labels lie in [0, kLabelEnd]
  static constexpr std::uint32_t kAppendStep = std::uint32_t{1} << 25;  // kGroupMax + 1 steps fit in 32 bits
  void insert_after(Stamp* x, Stamp* y) {  // y (unlinked) goes right after x
    OmGroup* g = x->group;
    if (!x->next && g->size < kAppendFill && kLabelEnd - x->label > 2 * kAppendStep) {
      // Fast path, appending at the end of the list (what an initial run does).
      y->label = x->label + kAppendStep;
      y->group = g;
      y->prev = x;
      y->next = nullptr;
      x->next = y;
      last_ = y;
      ++g->size;
      ++size_;
      return;
    }
    insert_after_slow(x, y);
  }
  void remove(Stamp* y);                  // unlinks y (not the base)
  static bool before(const Stamp* a, const Stamp* b) {
    return a->group == b->group ? a->label < b->label : a->group->label < b->group->label;
  }

  std::size_t size() const { return size_; }  // stamps, base included
  std::size_t groups() const { return groups_; }
  std::uint64_t relabels() const { return relabels_; }  // stamps or groups given a new label
  std::uint64_t splits() const { return splits_; }
  std::size_t bytes() const { return groups_ * sizeof(OmGroup); }
  void check() const;  // throws ContractError if the labels do not increase along the list

 private:
  void relabel_group(OmGroup* g);
  void split(OmGroup* g);
  OmGroup* insert_group_after(OmGroup* g);
  void remove_group(OmGroup* g);
  void link_after(Stamp* x, Stamp* y);  // list links only
  void insert_after_slow(Stamp* x, Stamp* y);

  Stamp base_;
  Stamp* last_ = &base_;
  OmGroup* first_group_ = nullptr;
  std::size_t size_ = 1;
  std::size_t groups_ = 0;
  std::uint64_t relabels_ = 0;
  std::uint64_t splits_ = 0;
};

}  // namespace kmr::sac
