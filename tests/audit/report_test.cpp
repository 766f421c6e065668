// The claims report (src/audit/ledger, report): the ledger parser on hand-written tables, the
// embedded ledger against an independent line count of spec/claims.md, and a real quick audit's
// report whose plot markers must equal the points of its JSON (read back with Boost.PropertyTree,
// sharing no code with the writers).
#include <gtest/gtest.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "audit/audit.hpp"
#include "audit/ledger.hpp"
#include "audit/report.hpp"
#include "exact/error.hpp"

#ifndef KMR_CLAIMS_MD
#error "KMR_CLAIMS_MD (path of spec/claims.md) is defined by tests/audit/CMakeLists.txt"
#endif

namespace {

using namespace kmr::audit;
namespace pt = boost::property_tree;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Ledger, ParsesSectionsRowsAndEscapedPipes) {
  const char* md =
      "# Claims ledger\n\nintro | not a table\n\n## Chapter A (§1)\n\n| ID | claim | where | check | tests | status |\n"
      "|---|---|---|---|---|---|\n| X1 | size \\|s\\| grows | §1.2 | brute force | `Suite.X1_Test` | checked |\n"
      "| X2 | two | §1.3 | — | — | todo: not built |\n\n## Empty section\n\ntext\n\n## Chapter B\nNot built yet;\n<!-- owner -->\nsee below.\n"
      "| ID | claim | where | check | tests | status |\n|---|---|---|---|---|---|\n| Y1 | y | §2 | c | t | measured: 3x |\n";
  auto s = parse_ledger(md);
  ASSERT_EQ(s.size(), 2u);  // the section without rows is dropped
  EXPECT_EQ(s[0].title, "Chapter A (§1)");
  EXPECT_EQ(s[0].note, "");
  EXPECT_EQ(s[1].note, "Not built yet; see below.");
  ASSERT_EQ(s[0].rows.size(), 2u);
  EXPECT_EQ(s[0].rows[0].claim, "size |s| grows");
  EXPECT_EQ(s[0].rows[0].tests, "`Suite.X1_Test`");
  EXPECT_EQ(s[0].rows[1].status, "todo: not built");
  EXPECT_EQ(s[0].rows[1].line, 10);
  EXPECT_EQ(s[1].rows.at(0).id, "Y1");
  EXPECT_THROW(parse_ledger("## A\n| a | b | c |\n"), std::runtime_error);
  // an unescaped pipe inside a cell makes a 7th cell: the text after it would be lost
  EXPECT_THROW(parse_ledger("## A\n| a | b | c | d | e | size |M| = 3 |\n"), std::runtime_error);
}

TEST(Ledger, EmbeddedLedgerIsSpecClaimsMdWithEveryRow) {
  std::string file = slurp(KMR_CLAIMS_MD);
  EXPECT_EQ(std::string(claims_ledger()), file) << "rebuild: the embedded ledger is stale";
  // independent count: table lines that are neither a header nor the |---| rule
  std::size_t rows = 0;
  std::istringstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| ", 0) == 0 && line.rfind("| ID |", 0) != 0) ++rows;
  std::size_t parsed = 0;
  for (const auto& s : parse_ledger(file)) parsed += s.rows.size();
  EXPECT_EQ(parsed, rows);
  EXPECT_GT(rows, 50u);
}

TEST(Ledger, ChecksBelongToTheirRow) {
  EXPECT_TRUE(check_belongs_to("T3.4.3", "T3.4.3"));
  EXPECT_TRUE(check_belongs_to("T3.4.3-speed", "T3.4.3"));
  EXPECT_FALSE(check_belongs_to("T3.3.11", "T3.3.1"));
  EXPECT_FALSE(check_belongs_to("T3.4.3", "T3.4.3-speed"));
}

// --only is a prefix; "ID$" is exactly ID, the form of the report's replay commands.
TEST(Report, OnlySelectsByPrefixOrExactly) {
  EXPECT_TRUE(selected("T3.4.3-speed", "T3.4.3"));
  EXPECT_TRUE(selected("T3.4.3", "T3."));
  EXPECT_TRUE(selected("T3.4.3", ""));
  EXPECT_TRUE(selected("T3.4.3", "T3.4.3$"));
  EXPECT_FALSE(selected("T3.4.3-speed", "T3.4.3$"));
  EXPECT_FALSE(selected("T3.4.3", "T3.4$"));
  Options o;
  o.only = "T3.4.3";
  EXPECT_GE(select_checks(o).size(), 2u);  // T3.4.3 and T3.4.3-speed
  // every check's replay command in a report names exactly that check
  std::vector<Result> results;
  for (const Check& c : all_checks()) {
    Result r;
    r.claim = c.claim;
    r.title = c.title;
    results.push_back(r);
  }
  auto dir = std::filesystem::temp_directory_path() / "kmr_only_test";
  std::filesystem::remove_all(dir);
  write_report(dir.string(), results, Options{}, parse_ledger(claims_ledger()));
  std::string md = slurp(dir / "report.md");
  std::size_t commands = 0;
  for (std::size_t at = md.find("`kmr audit --only '"); at != std::string::npos; at = md.find("`kmr audit --only '", at + 1)) {
    std::size_t b = at + 19, e = md.find('\'', b);
    o.only = md.substr(b, e - b);
    auto chosen = select_checks(o);
    ASSERT_EQ(chosen.size(), 1u) << o.only;
    EXPECT_EQ(chosen[0].claim + "$", o.only);
    ++commands;
  }
  EXPECT_GE(commands, results.size());  // via rows repeat some
  EXPECT_THROW(select_checks(Options{false, 20121, "T3.4$", {}}), kmr::InputError);
  // a report of no results: every check of the registry is NOT RUN on its row, with its command
  write_report(dir.string(), {}, Options{}, parse_ledger(claims_ledger()));
  md = slurp(dir / "report.md");
  std::set<std::string> want, got;
  for (const Check& c : all_checks()) want.insert(c.claim);
  for (std::size_t at = md.find("`kmr audit --only '"); at != std::string::npos; at = md.find("`kmr audit --only '", at + 1)) {
    std::size_t b = at + 19, e = md.find("$'", b);
    got.insert(md.substr(b, e - b));
    std::size_t heading = md.rfind("\n### ", at);
    EXPECT_NE(md.find(" — NOT RUN\n", heading), std::string::npos) << md.substr(heading, 40);
    EXPECT_LT(md.find(" — NOT RUN\n", heading), at);
  }
  EXPECT_EQ(got, want);
  std::filesystem::remove_all(dir);
}

TEST(Report, CtestRegexNamesTheTestsOfACell) {
  EXPECT_EQ(ctest_regex("`WellspacedProp.L3_4_2_*`, `tests/sac/runtime_test.cpp` (S1_3_EqualWrite…)"),
            "S1_3_EqualWrite|WellspacedProp\\.L3_4_2_");
  EXPECT_EQ(ctest_regex("`tests/exact` Dyadic.*, Integer.*"), "Dyadic\\.|Integer\\.");
  EXPECT_EQ(ctest_regex("—"), "");
}

// A quick audit of two checks with plots: every ledger ID is in both documents, and every SVG
// marker equals a point of the JSON (same claim, same plot, same series, same order).
TEST(Report, PlotMarkersEqualTheJsonPointsAndEveryLedgerIdIsListed) {
  Options o;
  o.quick = true;
  o.only = "L3.4.4";
  auto results = run_checks(o);
  o.only = "S1.3.4";
  auto more = run_checks(o);
  results.insert(results.end(), more.begin(), more.end());
  o.only = "";
  auto dir = std::filesystem::temp_directory_path() / "kmr_report_test";
  std::filesystem::remove_all(dir);
  auto ledger = parse_ledger(claims_ledger());
  ReportFiles files = write_report(dir.string(), results, o, ledger);
  std::ostringstream js;
  write_json(results, js);
  pt::ptree json;
  std::istringstream jin(js.str());
  pt::read_json(jin, json);

  std::string md = slurp(dir / "report.md"), html = slurp(dir / "index.html");
  for (const auto& s : ledger)
    for (const auto& row : s.rows) {
      EXPECT_NE(md.find(std::string("\n### ").append(row.id).append(" — ")), std::string::npos) << row.id;
      EXPECT_NE(html.find(std::string("<h3>").append(row.id).append(" <span")), std::string::npos) << row.id;
    }
  std::size_t svg_index = 0, points = 0;
  for (const auto& [unused, check] : json) {
    std::string claim = check.get<std::string>("claim");
    std::size_t plot_no = 0;
    for (const auto& [u2, plot] : check.get_child("plots")) {
      ++plot_no;
      std::string file = "plot-" + claim + "-" + std::to_string(plot_no) + ".svg";
      ASSERT_NE(std::find(files.svgs.begin(), files.svgs.end(), file), files.svgs.end()) << file;
      ++svg_index;
      EXPECT_NE(md.find("](" + file + ")"), std::string::npos);
      EXPECT_NE(html.find("src=\"" + file + "\""), std::string::npos);
      pt::ptree svg;
      std::ifstream in(dir / file);
      pt::read_xml(in, svg);
      std::vector<std::tuple<std::string, std::string, std::string>> marks;
      std::function<void(const pt::ptree&)> walk = [&](const pt::ptree& n) {
        for (const auto& [name, c] : n) {
          if (name == "circle" && c.get("<xmlattr>.class", "") == "pt")
            marks.emplace_back(c.get<std::string>("<xmlattr>.data-series"), c.get<std::string>("<xmlattr>.data-x"),
                               c.get<std::string>("<xmlattr>.data-y"));
          walk(c);
        }
      };
      walk(svg);
      std::size_t k = 0;
      for (const auto& [u3, series] : plot.get_child("series"))
        for (const auto& [u4, point] : series.get_child("points")) {
          ASSERT_LT(k, marks.size()) << file;
          auto it = point.begin();
          std::string x = it->second.data(), y = (++it)->second.data();
          EXPECT_EQ(std::get<0>(marks[k]), series.get<std::string>("name")) << file;
          EXPECT_EQ(std::stod(std::get<1>(marks[k])), std::stod(x)) << file;
          EXPECT_EQ(std::stod(std::get<2>(marks[k])), std::stod(y)) << file;
          ++k, ++points;
        }
      EXPECT_EQ(k, marks.size()) << file;
    }
    EXPECT_EQ(plot_no, claim == "L3.4.4" ? 1u : 2u) << claim;
  }
  EXPECT_EQ(svg_index, files.svgs.size());
  EXPECT_GE(points, 3u + 7u);
  std::filesystem::remove_all(dir);
}

// --include: results read back from JSON write the same JSON (plots included), and a result of a
// claim the audit has no check for (the CGAL benchmark's I2-root-solver-speed) is reported on its row.
TEST(Report, IncludedResultsRoundTripAndLandOnTheirLedgerRow) {
  Result r;
  r.claim = "I2-root-solver-speed";
  r.title = "bench \"quoted\" back\\slash\ttab\x01" "ctl\nline";  // control characters are escaped in JSON
  r.seconds = 0.25;
  r.verdict.pass = true;
  r.verdict.summary = "s";
  r.verdict.thesis = "t";
  r.verdict.figure("ratio", "0.4");
  kmr::svg::Plot p;
  p.title = "q";
  p.x = kmr::svg::category_axis("program", {"a", "b"});
  p.y = kmr::svg::log_axis("us", "µs");
  p.series = {{"kmr", {{0, 1.0 / 3}, {1, 7e-9}}}};
  p.bounds = {{"half", {{0, 0.5}, {1, std::numeric_limits<double>::quiet_NaN()}}}};
  r.verdict.plot(p);
  auto dir = std::filesystem::temp_directory_path() / "kmr_include_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ostringstream a;
  write_json({r}, a);
  std::ofstream(dir / "in.json") << a.str();
  auto back = read_json((dir / "in.json").string());
  std::ostringstream b;
  write_json(back, b);
  EXPECT_EQ(a.str(), b.str());
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].title, r.title);
  EXPECT_EQ(back[0].verdict.plots.at(0).series.at(0).points.at(0).y, 1.0 / 3);
  Options o;
  Result t338;  // L3.3.9's row names "audit T3.3.8": it shows that check's verdict
  t338.claim = "T3.3.8";
  t338.title = "squares";
  back.push_back(t338);
  write_report((dir / "r").string(), back, o, parse_ledger(claims_ledger()));
  std::string md = slurp(dir / "r" / "report.md");
  auto at = md.find("\n### I2-root-solver-speed — PASS");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NE(md.find("plot-I2-root-solver-speed-1.svg", at), std::string::npos);
  EXPECT_EQ(md.find("Checks not in the ledger"), std::string::npos);
  auto l339 = md.find("\n### L3.3.9 — FAIL");
  ASSERT_NE(l339, std::string::npos);
  EXPECT_EQ(md.find("**Verdict (via audit check T3.3.8).** FAIL", l339), md.find("**Verdict", l339));
  EXPECT_NE(md.find("\n### L3.3.10 — "), std::string::npos);
  EXPECT_EQ(md.find("\n### L3.3.10 — FAIL"), std::string::npos);  // "audit T3.3.8" is not L3.3.10's
  // the same claim twice (a run and an --include of an earlier run): each keeps its own plot file
  Result again = back[0];
  again.verdict.plots.at(0).series.at(0).points.at(0).y = 42;
  back.push_back(again);
  auto twice = write_report((dir / "r2").string(), back, o, parse_ledger(claims_ledger()));
  ASSERT_EQ(twice.svgs.size(), 2u);
  EXPECT_NE(twice.svgs[0], twice.svgs[1]);
  EXPECT_EQ(slurp(dir / "r2" / twice.svgs[0]).find("data-y=\"42\""), std::string::npos);
  EXPECT_NE(slurp(dir / "r2" / twice.svgs[1]).find("data-y=\"42\""), std::string::npos);
  std::string md2 = slurp(dir / "r2" / "report.md");
  EXPECT_NE(md2.find("](" + twice.svgs[0] + ")"), std::string::npos);
  EXPECT_NE(md2.find("](" + twice.svgs[1] + ")"), std::string::npos);
  std::ofstream(dir / "bad.json") << "[{\"claim\": \"x\"}]";
  EXPECT_THROW(read_json((dir / "bad.json").string()), kmr::InputError);
  EXPECT_THROW(read_json((dir / "missing.json").string()), kmr::InputError);
  std::filesystem::remove_all(dir);
}

// A check that passes but misses its stated target is MISSED in the table, the JSON (which reads
// back) and the report, never PASS; a met target stays PASS, a failed check FAIL.
TEST(Report, AMissedTargetIsMissedNotPass) {
  Result missed, met, failed;
  missed.claim = "I2-root-solver-speed", missed.title = "m";
  missed.verdict.pass = true;
  missed.verdict.set_target("ratio ≤ 1", false);
  met.claim = "F2.4-exact-vs-float", met.title = "t";
  met.verdict.pass = true;
  met.verdict.set_target("ratio ≤ 9", true);
  failed.claim = "T3.3.8", failed.title = "f";
  failed.verdict.pass = false;
  failed.verdict.set_target("ratio ≤ 1", false);
  std::ostringstream table;
  print_table({missed, met, failed}, table);
  std::string t = table.str();
  EXPECT_NE(t.find("I2-root-solver-speed        MISSED"), std::string::npos) << t;
  EXPECT_NE(t.find("F2.4-exact-vs-float         PASS"), std::string::npos) << t;
  EXPECT_NE(t.find("T3.3.8                      FAIL"), std::string::npos) << t;
  EXPECT_NE(t.find("2 passed, 1 failed (1 of the passed missed a stated target: MISSED)"), std::string::npos) << t;
  EXPECT_EQ(status({missed, met}), 0);  // a missed target is a measurement, not a wrong answer
  auto dir = std::filesystem::temp_directory_path() / "kmr_target_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ostringstream a;
  write_json({missed, met}, a);
  std::ofstream(dir / "in.json") << a.str();
  pt::ptree root;  // read with Boost, not with read_json
  std::istringstream in(a.str());
  pt::read_json(in, root);
  std::vector<std::string> verdicts, met_flags;
  for (const auto& [k, c] : root) verdicts.push_back(c.get<std::string>("verdict")), met_flags.push_back(c.get<std::string>("target_met"));
  EXPECT_EQ(verdicts, (std::vector<std::string>{"MISSED", "PASS"}));
  EXPECT_EQ(met_flags, (std::vector<std::string>{"false", "true"}));
  auto back = read_json((dir / "in.json").string());
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(std::string(verdict_word(back[0].verdict)), "MISSED");
  EXPECT_EQ(back[0].verdict.target, "ratio ≤ 1");
  write_report((dir / "r").string(), back, Options{}, parse_ledger(claims_ledger()));
  std::string md = slurp(dir / "r" / "report.md");
  EXPECT_NE(md.find("\n### I2-root-solver-speed — MISSED"), std::string::npos);
  EXPECT_NE(md.find("- **Target.** ratio ≤ 1 — **missed**"), std::string::npos);
  EXPECT_NE(md.find("\n### F2.4-exact-vs-float — PASS"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
