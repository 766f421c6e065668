#pragma once
// The claims ledger (spec/claims.md) read at report time: its `## ` sections and the rows of their
// tables (ID, claim, where, check, tests, status). The ledger is compiled into the binary
// (claims_ledger(); src/audit/CMakeLists.txt), so the report never depends on the working directory.
// Guarantees (tests/audit/ledger_test): every table row whose first cell is not the header or the
// |---| rule becomes one LedgerRow, in file order, under the last `## ` heading above it; an escaped
// pipe `\|` stays inside its cell (as `|`); cells are trimmed; prose lines before a section's
// first table (not HTML comments) form its note; a row with other than 6 cells (e.g. an unescaped | in a cell) throws
// std::runtime_error naming its line.
#include <string>
#include <string_view>
#include <vector>

namespace kmr::audit {

struct LedgerRow {
  std::string id, claim, where, check, tests, status;
  int line = 0;  // 1-based line in the ledger
};

struct LedgerSection {
  std::string title;  // the `## ` heading without the hashes
  std::string note;   // prose between the heading and the first table (e.g. why its claims are todo)
  std::vector<LedgerRow> rows;
};

std::vector<LedgerSection> parse_ledger(std::string_view markdown);
// spec/claims.md as it was when this binary was built.
std::string_view claims_ledger();

// The ledger row a check belongs to: its ID equals the row's, or starts with the row's ID and "-"
// (e.g. check "T3.4.3-speed" belongs to row "T3.4.3").
bool check_belongs_to(const std::string& check_claim, const std::string& row_id);

}  // namespace kmr::audit
