// The Chapter 3 audit checks pass on their quick defaults (what `kmr audit --quick` prints).
#include <gtest/gtest.h>

#include "audit/audit.hpp"

TEST(WellspacedAudit, Chapter3ChecksPassQuick) {
  kmr::audit::Options o;
  o.quick = true;
  for (const auto& c : kmr::audit::wellspaced_checks()) {
    RecordProperty("claim", c.claim);
    auto v = c.run(o);
    EXPECT_TRUE(v.pass) << c.claim << ": " << v.summary;
  }
}
