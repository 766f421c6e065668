// The guarantees of proptests/check_cases.hpp, with hand-derived parameter values.
#include "../check_cases.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace {
using kmr::proptest::capped_params;

rc::detail::TestParams params(int max_success, int max_size) {
  rc::detail::TestParams p;
  p.maxSuccess = max_success;
  p.maxSize = max_size;
  return p;
}

TEST(ProptestHarness, DefaultRunIsCappedAndNeverAboveRcParams) {
  auto p = capped_params(params(100, 100), 7, 3, false);
  EXPECT_EQ(p.maxSuccess, 7);
  EXPECT_EQ(p.maxSize, 3);
  p = capped_params(params(1000, 200), 7, 3, false);  // outside a campaign, RC_PARAMS does not lift caps
  EXPECT_EQ(p.maxSuccess, 7);
  EXPECT_EQ(p.maxSize, 3);
  p = capped_params(params(2, 1), 7, 3, false);  // a smaller RC_PARAMS wins
  EXPECT_EQ(p.maxSuccess, 2);
  EXPECT_EQ(p.maxSize, 1);
}

TEST(ProptestHarness, CampaignScalesTheCapsWithRcParams) {
  auto p = capped_params(params(1000, 200), 7, 3, true);  // 10x the suite's max_success, 2x its size
  EXPECT_EQ(p.maxSuccess, 70);
  EXPECT_EQ(p.maxSize, 6);
  p = capped_params(params(100, 100), 7, 3, true);  // the suite's defaults: as in CI
  EXPECT_EQ(p.maxSuccess, 7);
  EXPECT_EQ(p.maxSize, 3);
  p = capped_params(params(50, 50), 7, 3, true);  // never fewer than the default run's caps
  EXPECT_EQ(p.maxSuccess, 7);
  EXPECT_EQ(p.maxSize, 3);
  p = capped_params(params(1000, 200), 7, std::numeric_limits<int>::max(), true);  // no size cap
  EXPECT_EQ(p.maxSize, 200);
}

TEST(ProptestHarness, CheckCasesRunsTheCappedNumberOfCases) {
  int calls = 0;
  kmr::proptest::check_cases(7, [&] { ++calls; });
  const auto expected = capped_params(rc::detail::configuration().testParams, 7,
                                      std::numeric_limits<int>::max(), kmr::proptest::campaign());
  EXPECT_EQ(calls, expected.maxSuccess);
  EXPECT_LE(calls, 7 * 100);
}
}  // namespace
