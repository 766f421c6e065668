// The kinetic sorting judge's last look (src/audit/kinetic_checks.cpp, A2.1-batch): after the last
// batch it compares the order at the horizon with the exact sort, a look of its own that the other
// judge tests (fail_verdict_test.cpp: the first and the third look) never break (issue 13 §2).
// In quick mode the judge looks once at t = 0, once after every batch and once at the horizon, so
// an untampered run passes its order through the seam batches + 2 times (batches: its own figure).
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <string>
#include <vector>

#include "audit/audit.hpp"

namespace {

using namespace kmr::audit;

// Runs the quick A2.1-batch check, reversing the order it judges at look number `reverse_at`
// (none when negative); counts the looks.
Result run_batch(int reverse_at, int& looks) {
  Options o;
  o.quick = true;
  o.only = "A2.1-batch$";
  looks = 0;
  o.tamper = [&](const std::string& name, std::any& value) {
    if (name != "A2.1-batch order") return;
    if (looks++ == reverse_at) {
      auto& order = std::any_cast<std::vector<std::size_t>&>(value);
      std::reverse(order.begin(), order.end());
    }
  };
  auto results = run_checks(o);
  EXPECT_EQ(results.size(), 1u);
  return results.empty() ? Result{} : results.front();
}

std::string figure(const Verdict& v, const std::string& name) {
  for (const auto& [k, value] : v.figures)
    if (k == name) return value;
  return "";
}

TEST(AuditFinalLook, KineticSortWrongOnlyAtTheHorizonFails) {
  int looks = 0;
  Result clean = run_batch(-1, looks);
  ASSERT_TRUE(clean.verdict.pass) << clean.verdict.summary;
  const std::string batches = figure(clean.verdict, "batches");
  ASSERT_FALSE(batches.empty());
  EXPECT_EQ(looks, std::stoi(batches) + 2);
  const int last = looks - 1;
  Result broken = run_batch(last, looks);
  EXPECT_FALSE(broken.verdict.pass);
  EXPECT_EQ(broken.verdict.summary, "final order differs from the exact sort");
  EXPECT_EQ(looks, last + 1);
}

}  // namespace
