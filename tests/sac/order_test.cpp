// OrderList (sac/order.hpp): the order of stamps under adversarial insertion and deletion patterns.
#include <gtest/gtest.h>

#include <list>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

#include "exact/error.hpp"
#include "sac/order.hpp"

using kmr::sac::OrderList;
using kmr::sac::Stamp;

namespace {

// Holds the list and a reference std::list of the same stamps; checks every order query.
struct Harness {
  OrderList om;
  std::list<Stamp*> ref{om.base()};
  std::unordered_map<Stamp*, std::list<Stamp*>::iterator> at{{om.base(), ref.begin()}};
  std::vector<std::unique_ptr<Stamp>> owned;
  std::size_t inserts = 0;

  Stamp* insert_after(Stamp* x) {
    owned.push_back(std::make_unique<Stamp>());
    Stamp* y = owned.back().get();
    om.insert_after(x, y);
    at[y] = ref.insert(std::next(at.at(x)), y);
    ++inserts;
    return y;
  }
  void remove(Stamp* y) {
    om.remove(y);
    ref.erase(at.at(y));
    at.erase(y);
  }
  // Full check: labels increase along the list and the list is the reference order.
  void verify(std::mt19937_64& rng, int samples = 2000) {
    om.check();
    ASSERT_EQ(om.size(), ref.size());
    std::vector<Stamp*> v(ref.begin(), ref.end());
    Stamp* s = om.base();
    for (Stamp* r : v) {
      ASSERT_EQ(s, r);
      s = s->next;
    }
    for (int k = 0; k < samples && v.size() > 1; ++k) {
      std::size_t i = rng() % v.size(), j = rng() % v.size();
      ASSERT_EQ(OrderList::before(v[i], v[j]), i < j) << i << " vs " << j;
    }
  }
};

TEST(SacOrder, S1_3_OrderUnderRepeatedInsertAfterSameStamp) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  Harness h;
  std::mt19937_64 rng(1);
  Stamp* x = h.insert_after(h.om.base());
  for (int i = 0; i < 20000; ++i) h.insert_after(x);  // every new stamp right after x: gaps halve
  h.verify(rng);
  EXPECT_GT(h.om.splits(), 0u);
}

TEST(SacOrder, S1_3_OrderUnderAppendAndPrepend) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  Harness h;
  std::mt19937_64 rng(2);
  Stamp* last = h.om.base();
  for (int i = 0; i < 20000; ++i) last = h.insert_after(last);        // append (initial runs)
  for (int i = 0; i < 20000; ++i) h.insert_after(h.om.base());        // always at the front
  h.verify(rng);
}

TEST(SacOrder, S1_3_OrderUnderAlternatingAndNewestInsertions) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  Harness h;
  std::mt19937_64 rng(3);
  Stamp* a = h.insert_after(h.om.base());
  Stamp* b = h.insert_after(a);
  Stamp* newest = b;
  for (int i = 0; i < 10000; ++i) {
    h.insert_after(i % 2 ? a : b);      // alternate between two hot spots
    newest = h.insert_after(newest);    // and always after the newest stamp
  }
  h.verify(rng);
}

TEST(SacOrder, S1_3_OrderUnderRandomInsertionsAndDeletions) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  Harness h;
  std::mt19937_64 rng(4);
  std::vector<Stamp*> live;
  for (int i = 0; i < 30000; ++i) {
    if (!live.empty() && rng() % 3 == 0) {
      std::size_t k = rng() % live.size();
      h.remove(live[k]);
      live[k] = live.back();
      live.pop_back();
    } else {
      Stamp* x = live.empty() || rng() % 8 == 0 ? h.om.base() : live[rng() % live.size()];
      live.push_back(h.insert_after(x));
    }
    if (i % 10000 == 9999) h.verify(rng, 500);
  }
  h.verify(rng);
  // Deleting everything leaves the base alone, and the list still works.
  for (Stamp* s : live) h.remove(s);
  h.verify(rng);
  Stamp* y = h.insert_after(h.om.base());
  EXPECT_TRUE(OrderList::before(h.om.base(), y));
}

TEST(SacOrder, S1_3_DenseRegionInTheMiddle) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  // Many groups, then a burst of insertions at one point in the middle: forces group relabelling
  // of ever larger label ranges.
  Harness h;
  std::mt19937_64 rng(5);
  Stamp* last = h.om.base();
  std::vector<Stamp*> all;
  for (int i = 0; i < 5000; ++i) all.push_back(last = h.insert_after(last));
  Stamp* mid = all[2500];
  for (int i = 0; i < 30000; ++i) mid = h.insert_after(mid);
  h.verify(rng);
  RecordProperty("relabels_per_insert", std::to_string(static_cast<double>(h.om.relabels()) / h.inserts));
}

// Branch sac12: appends fill a group to kAppendFill stamps, so a group of an initial run takes
// kGroupMax − kAppendFill insertions in its middle (re-execution) before it splits. Hand-derived:
// the base's group holds the base and 31 appended stamps, then one group per 32 appends.
TEST(SacOrder, S1_3_AppendsLeaveRoomForInsertionsBeforeASplit) {
  RecordProperty("claim", "S1.3.3-order-maintenance");
  static_assert(OrderList::kGroupMax == 64 && OrderList::kAppendFill == 32, "hand-derived counts below");
  Harness h;
  std::mt19937_64 rng(7);
  std::vector<Stamp*> run;
  Stamp* last = h.om.base();
  for (int i = 0; i < 320; ++i) run.push_back(last = h.insert_after(last));
  EXPECT_EQ(h.om.groups(), 11u);  // 1 + ceil((320 − 31) / 32)
  EXPECT_EQ(h.om.splits(), 0u);
  Stamp* x = run[40];  // in the second group (stamps 31..62 of the run)
  for (int i = 0; i < 32; ++i) x = h.insert_after(x);
  EXPECT_EQ(h.om.splits(), 0u) << "32 insertions fit in a group filled to 32 by appends";
  h.insert_after(x);
  EXPECT_EQ(h.om.splits(), 1u);
  h.verify(rng);
}

TEST(SacOrder, BaseCannotBeRemoved) {
  OrderList om;
  EXPECT_THROW(om.remove(om.base()), kmr::ContractError);
}

}  // namespace
