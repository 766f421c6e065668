#pragma once
// Runs a RapidCheck property from a GoogleTest TEST with a bounded number of cases, for properties
// whose cases are expensive (long state-machine sequences, updates judged by brute force).
//
// Guarantees (the caps are checked by every property that uses it; the campaign path by
// scripts/campaign.sh runs):
//  * Default run: at most `cases` successful cases with sizes up to `max_size`, and never more than
//    RC_PARAMS asks for, so ctest stays fast.
//  * Campaign (KMR_CAMPAIGN set and not "0", as scripts/campaign.sh sets it): the caps scale with
//    what RC_PARAMS asks for relative to the suite's defaults (max_success 100, max_size 100), e.g.
//    max_success=1000 runs 10 × `cases`; never fewer than the default run — a campaign is never
//    silently held at CI's size.
//  * RC_PARAMS's seed applies in both; a failure fails the TEST with RapidCheck's message.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

namespace kmr::proptest {

inline bool campaign() {
  const char* c = std::getenv("KMR_CAMPAIGN");
  return c != nullptr && *c != '\0' && std::string(c) != "0";
}

// The parameters check_cases runs with (separate so that its guarantees are tested directly).
inline rc::detail::TestParams capped_params(rc::detail::TestParams params, int cases, int max_size, bool in_campaign) {
  if (in_campaign) {
    constexpr double kSuiteDefault = 100;  // kmr_gtest's RC_RUNS and RapidCheck's max_size
    cases = std::max(cases, int(cases * (params.maxSuccess / kSuiteDefault)));
    if (max_size < std::numeric_limits<int>::max() / 4)
      max_size = std::max(max_size, int(max_size * (params.maxSize / kSuiteDefault)));
  }
  params.maxSuccess = std::min(params.maxSuccess, cases);
  params.maxSize = std::min(params.maxSize, max_size);
  return params;
}

template <class F>
void check_cases(int cases, int max_size, F f) {
  const auto params = capped_params(rc::detail::configuration().testParams, cases, max_size, campaign());
  rc::detail::TestMetadata md;
  md.id = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  md.description = md.id;
  auto result = rc::detail::checkProperty(rc::detail::toProperty(f), md, params);
  std::ostringstream ss;
  rc::detail::printResultMessage(result, ss);
  if (!result.template is<rc::detail::SuccessResult>()) FAIL() << ss.str();
}

template <class F>
void check_cases(int cases, F f) {
  check_cases(cases, std::numeric_limits<int>::max(), f);
}

}  // namespace kmr::proptest
