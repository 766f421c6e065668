// The §1.3 audit checks (kmr audit --quick --only S1.3) pass.
#include <gtest/gtest.h>

#include <sstream>

#include "audit/audit.hpp"

TEST(SacAudit, S1_3_QuickAuditPasses) {
  RecordProperty("claim", "S1.3.1-change-propagation");
  kmr::audit::Options o;
  o.quick = true;
  o.only = "S1.3";
  std::ostringstream out;
  EXPECT_EQ(kmr::audit::run_audit(o, out, nullptr), 0) << out.str();
  EXPECT_NE(out.str().find("S1.3.1-change-propagation"), std::string::npos);
}
