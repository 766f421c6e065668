// The claims report's verdict words on a hand-written ledger (issue 13 §2): the real ledger's rows
// change with every branch, so each rule of report.cpp is pinned here on rows made for it, with the
// expected report text typed by hand from report.hpp's guarantees — the worst verdict of a row's
// checks (MISSED over PASS), TODO with and without a reason, NOT CHECKABLE, MEASURED (a benchmark's
// figures) against TESTS (a "measured" row whose tests name the audit), a row shown through the
// check its "check" cell names, a result of no row (listed, never dropped), plain text that
// Markdown would read as markup, a replay command holding a backtick, unclosed ledger markup.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "audit/audit.hpp"
#include "audit/ledger.hpp"
#include "audit/report.hpp"

namespace {

using namespace kmr::audit;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Result result(const std::string& claim, bool pass, const std::string& title = "t") {
  Result r;
  r.claim = claim;
  r.title = title;
  r.verdict.pass = pass;
  return r;
}

TEST(ReportVerdicts, EveryVerdictRuleOnAHandWrittenLedger) {
  const char* md =
      "## Chapter Z (§9)\n\nA note with `code` and **bold\n\n"
      "| ID | claim | where | check | tests | status |\n|---|---|---|---|---|---|\n"
      "| Z1 | first `x` | §9.1 | brute force | `Zed.Z1_Test` | checked |\n"
      "| Z2 | second | §9.2 | — | — | todo |\n"
      "| Z3 | third | §9.3 | — | — | todo: needs the engine |\n"
      "| Z4 | fourth | §9.4 | — | — | not checkable: no oracle |\n"
      "| Z5 | fifth | §9.5 | bench | bench_x | measured: 3x |\n"
      "| Z6 | sixth | §9.6 | bench | audit Q9 | measured |\n"
      "| Z7 | seventh | §9.7 | audit Z1 | — | checked |\n";
  const auto ledger = parse_ledger(md);
  ASSERT_EQ(ledger.size(), 1u);
  ASSERT_EQ(ledger[0].rows.size(), 7u);
  Result z1 = result("Z1", true), speed = result("Z1-speed", true), orphan = result("Q7", false, "a|b*c_[d]");
  speed.verdict.set_target("ratio <= 2", false);
  orphan.replay = "bench `x` --y";
  orphan.verdict.summary = "line one\nline two";
  auto dir = std::filesystem::temp_directory_path() / "kmr_report_verdicts_test";
  std::filesystem::remove_all(dir);
  write_report(dir.string(), {z1, speed, orphan}, Options{}, ledger);
  const std::string r = slurp(dir / "report.md"), h = slurp(dir / "index.html");
  auto has = [&](const std::string& part) { return r.find(part) != std::string::npos; };
  // Z1 has two checks, one MISSED: the row is MISSED; each check's replay names it exactly, and the
  // tests cell gives the ctest command.
  EXPECT_TRUE(has("\n### Z1 — MISSED\n")) << r;
  EXPECT_TRUE(has("- **Replay.** `kmr audit --only 'Z1$'`\n"));
  EXPECT_TRUE(has("- **Replay.** `kmr audit --only 'Z1-speed$'`\n"));
  EXPECT_TRUE(has("- **Replay.** `ctest --test-dir build -R 'Zed\\.Z1_Test'`\n"));
  EXPECT_TRUE(has("- **Target.** ratio \\<= 2 — **missed**\n"));  // md_text escapes <
  EXPECT_TRUE(has("\n### Z2 — TODO\n"));
  EXPECT_TRUE(has("- **Not checked yet:** not implemented yet (see the chapter's note)\n"));
  EXPECT_TRUE(has("\n### Z3 — TODO\n"));
  EXPECT_TRUE(has("- **Not checked yet:** needs the engine\n"));
  EXPECT_TRUE(has("\n### Z4 — NOT CHECKABLE\n"));
  EXPECT_TRUE(has("\n### Z5 — MEASURED\n"));
  EXPECT_TRUE(has("\n### Z6 — TESTS\n"));
  // Z7's check cell names audit check Z1 (not Z1-speed): Z1's verdict, marked as borrowed.
  EXPECT_TRUE(has("\n### Z7 — PASS\n"));
  EXPECT_TRUE(has("- **Verdict (via audit check Z1).** PASS"));
  EXPECT_FALSE(has("- **Verdict (via audit check Z1-speed)."));
  // Q7 belongs to no row: its own chapter, its title escaped, its summary on one line, its replay a
  // code span whose fence is longer than the backtick inside.
  const auto orphans = r.find("\n## Checks not in the ledger\n");
  ASSERT_NE(orphans, std::string::npos);
  EXPECT_GT(r.find("\n### Q7 — FAIL\n"), orphans);
  EXPECT_TRUE(has("- **Verdict (Q7).** FAIL — a\\|b\\*c\\_\\[d\\]: line one line two ("));
  EXPECT_TRUE(has("- **Replay.** `` bench `x` --y ``\n"));
  // The tally counts rows (and the orphan), not checks.
  EXPECT_TRUE(has("1 PASS, 1 MISSED, 1 FAIL, 1 TESTS, 1 MEASURED, 2 TODO, 1 NOT CHECKABLE.\n")) << r.substr(0, 400);
  // HTML: the note's unclosed bold is closed, code spans become <code>, every verdict is a class.
  EXPECT_NE(h.find("<p>A note with <code>code</code> and <b>bold</b></p>"), std::string::npos);
  EXPECT_NE(h.find("<dt>Claim</dt><dd>first <code>x</code></dd>"), std::string::npos);
  for (const char* cls : {"MISSED", "TODO", "NOTCHECKABLE", "MEASURED", "TESTS", "PASS", "FAIL"})
    EXPECT_NE(h.find(std::string("class=\"v ") + cls + "\""), std::string::npos) << cls;
  EXPECT_NE(h.find("<h2 id=\"chapter-1\">Checks not in the ledger</h2>"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Ledger rows outside the tables' usual shape: a row before any `## ` heading (kept, in an untitled
// section), a row without its closing pipe, a backslash that escapes no pipe (kept as it is).
TEST(ReportVerdicts, LedgerRowsOfUnusualShape) {
  auto s = parse_ledger("| A1 | a \\n b | w | c | t | checked |\n## B\n| B1 | b | w | c | t | todo\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].title, "");
  ASSERT_EQ(s[0].rows.size(), 1u);
  EXPECT_EQ(s[0].rows[0].claim, "a \\n b");
  EXPECT_EQ(s[0].rows[0].line, 1);
  ASSERT_EQ(s[1].rows.size(), 1u);
  EXPECT_EQ(s[1].rows[0].status, "todo");
  EXPECT_EQ(s[1].rows[0].line, 3);
  // Five cells: the message names the line and the count, without the hint meant for a stray |.
  try {
    parse_ledger("## C\n\n| C1 | c | w | t | checked |\n");
    ADD_FAILURE() << "a 5-cell row was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "claims ledger line 3: a table row needs 6 cells, has 5");
  }
}

}  // namespace
