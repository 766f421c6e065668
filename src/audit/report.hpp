#pragma once
// `kmr audit --report DIR`: the claims report, generated from the audit's results (the same data
// `--json` writes) and the claims ledger compiled into the binary.
// Guarantees (tests/audit/report_test, tests/cli/report_test.sh): DIR/report.md and a self-contained
// DIR/index.html (inline CSS, no scripts, nothing fetched) hold one section per ledger chapter and
// one entry per ledger row — checked or not — with ID, statement, thesis section, verdict, measured
// figures, the thesis's figure when the check gives one, the ledger status and a replay command;
// every plot of every result is DIR/<file>.svg, referenced by both documents; a result whose claim
// belongs to no ledger row is listed under "Checks not in the ledger" (never dropped).
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "audit/ledger.hpp"

namespace kmr::audit {

struct ReportFiles {
  std::vector<std::string> svgs;  // file names inside DIR, in report order
};

// Writes the report into dir (created if missing). Throws InputError if a file cannot be written.
ReportFiles write_report(const std::string& dir, const std::vector<Result>& results, const Options& options,
                         const std::vector<LedgerSection>& ledger);

// The ctest regular expression that runs the tests a ledger row's "tests" cell names (gtest
// Suite.Name items and claim-style names such as S1_3_Foo), or "" if it names none.
std::string ctest_regex(const std::string& tests_cell);

}  // namespace kmr::audit
