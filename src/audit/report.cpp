#include "audit/report.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "exact/error.hpp"
#include "svg/plot.hpp"
#include "svg/svg.hpp"

namespace kmr::audit {

namespace {

std::string html_escape(const std::string& s) { return svg::escape(s); }

// The little Markdown the ledger's cells use, as HTML: `code`, **bold**; everything else escaped.
std::string inline_html(const std::string& md) {
  std::string out;
  bool code = false, bold = false;
  for (std::size_t i = 0; i < md.size(); ++i) {
    if (md[i] == '`') {
      out += code ? "</code>" : "<code>";
      code = !code;
    } else if (!code && md.compare(i, 2, "**") == 0) {
      out += bold ? "</b>" : "<b>";
      bold = !bold;
      ++i;
    } else {
      out += html_escape(std::string(1, md[i]));
    }
  }
  if (code) out += "</code>";
  if (bold) out += "</b>";
  return out;
}

// Plain text (a check's title, summary, figures, plot titles — not the ledger's Markdown) as Markdown
// inline text on one line: every character Markdown or a GFM table could read as markup is
// backslash-escaped (CommonMark: any ASCII punctuation may be), line breaks become spaces.
std::string md_text(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '\n' || c == '\r') c = ' ';
    if (std::string_view("\\`*_[]<>|&$~").find(c) != std::string_view::npos) r += '\\';
    r += c;
  }
  return r;
}
// Plain text as a Markdown code span (a fence longer than any backtick run inside it).
std::string md_code(const std::string& s) {
  std::size_t run = 0, longest = 0;
  for (char c : s) longest = std::max(longest, run = c == '`' ? run + 1 : 0);
  std::string fence(longest + 1, '`'), body;
  for (char c : s) body += c == '\n' ? ' ' : c;
  return longest ? fence + " " + body + " " + fence : fence + body + fence;
}

std::string file_stem(const std::string& claim) {
  std::string r;
  for (char c : claim) r += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return r;
}

std::string anchor(const std::string& id) {
  std::string r = "claim-";
  for (char c : id) r += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return r;
}

std::string audit_command(const std::string& claim, const Options& o) {
  std::string c = "kmr audit --only '" + claim + "$'";  // exact: T3.4.3 without T3.4.3-speed
  if (o.quick) c += " --quick";
  if (o.seed != Options{}.seed) c += " --seed " + std::to_string(o.seed);
  return c;
}

struct Entry {
  const LedgerRow* row = nullptr;         // null for results outside the ledger
  std::vector<const Result*> results;     // the checks of this row that ran
  std::vector<std::string> plot_files;    // per plot of those results, in order
  std::vector<std::string> plot_titles;
  bool via = false;                       // results are of the audit check(s) the row's "tests" cell names
  std::string verdict;                    // PASS, FAIL, NOT RUN, TESTS, MEASURED, TODO, NOT CHECKABLE
  std::vector<std::string> replay;
};

std::string todo_reason(const std::string& status) {
  std::string r = status.substr(4);  // after "todo"
  while (!r.empty() && (r[0] == ':' || r[0] == ' ')) r.erase(0, 1);
  return r.empty() ? "not implemented yet (see the chapter's note)" : r;
}

void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
  if (!f) throw InputError("cannot write report file '" + p.string() + "'");
}

const char* kCss = R"(body{font-family:sans-serif;max-width:70em;margin:1em auto;padding:0 1em;color:#222;line-height:1.4}
h1{font-size:1.6em}h2{border-bottom:2px solid #ccc;margin-top:2em}h3{margin-bottom:.3em}
.claim{border:1px solid #ddd;border-radius:4px;padding:.5em 1em;margin:1em 0}
.v{font-weight:bold;padding:0 .4em;border-radius:3px}
.PASS{background:#d7f0d7;color:#155d15}.FAIL{background:#f7d4d4;color:#8a1010}.MISSED{background:#f7e7c4;color:#7a4a00}.TODO{background:#eee;color:#555}
.TESTS{background:#dde8f7;color:#1b3d6d}.MEASURED{background:#e6def5;color:#45226b}.NOTRUN{background:#f5ecd0;color:#6b5000}.NOTCHECKABLE{background:#eee;color:#555}
table{border-collapse:collapse;margin:.4em 0}td,th{border:1px solid #ddd;padding:.15em .5em;text-align:left;vertical-align:top}
code{background:#f4f4f4;padding:0 .2em}dt{font-weight:bold;margin-top:.3em}dd{margin-left:1.5em}
img{max-width:100%;border:1px solid #eee;margin:.3em 0}li a.v{display:inline-block;margin:.1em 0;text-decoration:none;font-weight:normal}
)";

// Does a ledger cell name audit check `claim` ("audit T3.4.3", "audit `A2.1-batch`", "audit T3.3.8, ...")?
bool names_audit_check(const std::string& cell, const std::string& claim) {
  for (const std::string& form : {"audit " + claim, "audit `" + claim + "`"}) {
    for (std::size_t at = cell.find(form); at != std::string::npos; at = cell.find(form, at + 1)) {
      std::size_t end = at + form.size();
      if (end == cell.size() || !(std::isalnum(static_cast<unsigned char>(cell[end])) || cell[end] == '.' || cell[end] == '-'))
        return true;
    }
  }
  return false;
}

}  // namespace

std::string ctest_regex(const std::string& tests) {
  static const std::regex name(R"(([A-Z][A-Za-z0-9]*\.)?[A-Z][0-9]+(_[0-9]+)+_[A-Za-z0-9_]+|[A-Z][A-Za-z0-9]+\.([A-Z][A-Za-z0-9_]+|\*))");
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(tests.begin(), tests.end(), name); it != std::sregex_iterator(); ++it) {
    std::string n = it->str();
    if (n.back() == '*') n.pop_back();  // "Suite.*": every test of the suite
    if (n.find('.') != std::string::npos && n.rfind("src.", 0) == 0) continue;
    names.insert(n);
  }
  std::string r;
  for (const std::string& n : names) {
    std::string e;
    for (char c : n) e += c == '.' ? std::string("\\.") : std::string(1, c);
    r += (r.empty() ? "" : "|") + e;
  }
  return r;
}

ReportFiles write_report(const std::string& dir, const std::vector<Result>& results, const Options& options,
                         const std::vector<LedgerSection>& ledger) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw InputError("cannot create report directory '" + dir + "'");

  // Attach each result to its ledger row: the row with the same ID, else the longest "ID-" prefix.
  auto row_of = [&](const std::string& claim) {
    const LedgerRow* best = nullptr;
    for (const auto& s : ledger)
      for (const auto& row : s.rows)
        if (check_belongs_to(claim, row.id) && (!best || row.id == claim || (best->id != claim && row.id.size() > best->id.size())))
          best = &row;
    return best;
  };
  std::map<const Result*, const LedgerRow*> owner;
  for (const Result& r : results) owner[&r] = row_of(r.claim);
  // The audit's own checks (run or not): a row with one that did not run is NOT RUN, with its command.
  std::map<const LedgerRow*, std::vector<std::string>> registered;
  for (const Check& c : all_checks()) {
    if (const LedgerRow* row = row_of(c.claim)) registered[row].push_back(c.claim);
    for (const auto& s : ledger)
      for (const auto& row : s.rows)
        if (row_of(c.claim) != &row && (names_audit_check(row.tests, c.claim) || names_audit_check(row.check, c.claim)))
          registered[&row].push_back(c.claim);
  }
  ReportFiles files;
  std::map<const Result*, std::vector<std::string>> plot_files;  // every plot drawn once, in result order
  std::map<std::string, int> seen;  // a claim may come twice (run and --include): plot-C+2-1.svg, ...
  for (const Result& r : results) {
    std::string stem = "plot-" + file_stem(r.claim);
    if (int k = ++seen[stem]; k > 1) stem += "+" + std::to_string(k);  // file_stem never writes '+'
    stem += "-";
    for (std::size_t i = 0; i < r.verdict.plots.size(); ++i) {
      std::string f = stem + std::to_string(i + 1) + ".svg";
      write_file(fs::path(dir) / f, svg::render(r.verdict.plots[i]));
      files.svgs.push_back(f);
      plot_files[&r].push_back(f);
    }
  }
  auto build = [&](const LedgerRow* row, std::vector<const Result*> rs, bool via) {
    Entry e;
    e.row = row;
    e.via = via;
    e.results = std::move(rs);
    for (const Result* r : e.results)
      for (std::size_t i = 0; i < r->verdict.plots.size(); ++i) {
        e.plot_files.push_back(plot_files[r][i]);
        e.plot_titles.push_back(r->verdict.plots[i].title);
      }
    std::string status = row ? row->status : "";
    if (!e.results.empty()) {
      e.verdict = "PASS";  // the worst of its checks: FAIL over MISSED over PASS
      for (const Result* r : e.results) {
        std::string w = verdict_word(r->verdict);
        if (w == "FAIL" || (w == "MISSED" && e.verdict == "PASS")) e.verdict = w;
      }
      for (const Result* r : e.results) e.replay.push_back(r->replay.empty() ? audit_command(r->claim, options) : r->replay);
    } else if (status.rfind("todo", 0) == 0) {
      e.verdict = "TODO";
    } else if (status.rfind("not checkable", 0) == 0) {
      e.verdict = "NOT CHECKABLE";
    } else if (status.rfind("measured", 0) == 0 && row->tests.find("audit") == std::string::npos) {
      e.verdict = "MEASURED";  // by a benchmark outside the audit: its figures are the ledger's
    } else {
      e.verdict = "TESTS";
    }
    if (row && e.results.empty() && !registered[row].empty() && (e.verdict == "TESTS" || e.verdict == "MEASURED")) {
      e.verdict = "NOT RUN";  // the row has an audit check that this run did not include (--only)
      for (const std::string& claim : registered[row]) e.replay.push_back(audit_command(claim, options));
    }
    if (row) {
      std::string re = ctest_regex(row->tests);
      if (!re.empty()) e.replay.push_back("ctest --test-dir build -R '" + re + "'");
    }
    return e;
  };
  std::vector<std::pair<std::string, std::vector<Entry>>> chapters;
  std::vector<std::string> notes;
  for (const auto& s : ledger) {
    chapters.push_back({s.title, {}});
    notes.push_back(s.note);
    for (const auto& row : s.rows) {
      std::vector<const Result*> rs;
      for (const Result& r : results)
        if (owner[&r] == &row) rs.push_back(&r);
      bool via = false;
      if (rs.empty())  // a row measured by another claim's check, e.g. L3.3.16 by "audit T3.4.3"
        for (const Result& r : results)
          if (names_audit_check(row.tests, r.claim) || names_audit_check(row.check, r.claim)) rs.push_back(&r), via = true;
      chapters.back().second.push_back(build(&row, rs, via));
    }
  }
  std::vector<const Result*> orphans;
  for (const Result& r : results)
    if (!owner[&r]) orphans.push_back(&r);
  if (!orphans.empty()) {
    chapters.push_back({"Checks not in the ledger", {}});
    notes.push_back("Results whose claim ID matches no row of spec/claims.md.");
    for (const Result* r : orphans) chapters.back().second.push_back(build(nullptr, {r}, false));
  }

  std::map<std::string, int> counts;
  for (const auto& [t, es] : chapters)
    for (const auto& e : es) ++counts[e.verdict];
  std::string mode = std::string(options.quick ? "--quick" : "default sizes") + ", seed " + std::to_string(options.seed) +
                     (options.only.empty() ? "" : ", --only " + options.only);
  std::string tally;
  for (const char* v : {"PASS", "MISSED", "FAIL", "TESTS", "MEASURED", "NOT RUN", "TODO", "NOT CHECKABLE"})
    if (counts[v]) tally += (tally.empty() ? "" : ", ") + std::to_string(counts[v]) + " " + v;
  const char* legend =
      "PASS/FAIL: the `kmr audit` check(s) of the claim ran in this audit. MISSED: the check passed, but a measured figure "
      "missed the speed or size target stated for it. TESTS: checked by the test suite, not by the "
      "audit (replay with ctest; property tests run with RC_PARAMS=\"seed=20121\", which `ctest -V` prints). MEASURED: by a "
      "benchmark outside the audit; the figures are the ledger's (include a benchmark's results with `kmr audit --include FILE`). NOT RUN: an audit "
      "check exists but this audit did not run it. TODO: not checked yet (reason given). NOT CHECKABLE: see the reason.";

  // ---- report.md
  std::ostringstream md;
  md << "# kmr claims report\n\n"
     << "kmr " << version() << " · `kmr audit` (" << mode << ") · ledger: `spec/claims.md` as built into this binary\n\n"
     << tally << ".\n\n" << legend << "\n";
  for (std::size_t c = 0; c < chapters.size(); ++c) {
    const auto& [title, es] = chapters[c];
    md << "\n## " << title << "\n";
    if (!notes[c].empty()) md << "\n" << notes[c] << "\n";
    for (const Entry& e : es) {
      std::string id = e.row ? e.row->id : md_text(e.results.front()->claim);
      md << "\n### " << id << " — " << e.verdict << "\n\n";
      if (e.row)
        md << "- **Claim.** " << e.row->claim << "\n- **Where.** " << e.row->where << "\n- **How it is checked.** " << e.row->check
           << "\n- **Tests.** " << e.row->tests << "\n";
      for (const Result* r : e.results) {
        md << "- **Verdict (" << (e.via ? "via audit check " : "") << md_text(r->claim) << ").** " << verdict_word(r->verdict)
           << " — " << md_text(r->title) << (r->verdict.summary.empty() ? "" : ": " + md_text(r->verdict.summary)) << " ("
           << fmt(r->seconds) << " s)\n";
        if (r->verdict.target_met)
          md << "- **Target.** " << md_text(r->verdict.target) << (*r->verdict.target_met ? " — met" : " — **missed**") << "\n";
        if (!r->verdict.thesis.empty()) md << "- **Thesis's figure.** " << md_text(r->verdict.thesis) << "\n";
      }
      if (e.verdict == "TODO") md << "- **Not checked yet:** " << todo_reason(e.row->status) << "\n";
      if (e.row) md << "- **Ledger status.** " << e.row->status << "\n";
      for (const std::string& c : e.replay) md << "- **Replay.** " << md_code(c) << "\n";
      for (const Result* r : e.results) {
        if (r->verdict.figures.empty()) continue;
        md << "\n| " << md_text(r->claim) << " figure | value |\n|---|---|\n";
        for (const auto& [k, v] : r->verdict.figures) md << "| " << md_text(k) << " | " << md_text(v) << " |\n";
      }
      for (std::size_t i = 0; i < e.plot_files.size(); ++i) md << "\n![" << md_text(e.plot_titles[i]) << "](" << e.plot_files[i] << ")\n";
    }
  }
  write_file(fs::path(dir) / "report.md", md.str());

  // ---- index.html (HTML 4 elements only, so that any HTML parser, xmllint --html included, reads it)
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>kmr claims report</title>\n<style>\n"
    << kCss << "</style>\n</head>\n<body>\n<h1>kmr claims report</h1>\n<p>kmr " << html_escape(version()) << " &middot; <code>kmr audit</code> ("
    << html_escape(mode) << ") &middot; ledger: <code>spec/claims.md</code> as built into this binary</p>\n<p>"
    << html_escape(tally) << ".</p>\n<p>" << inline_html(legend) << "</p>\n<ul>\n";
  for (std::size_t c = 0; c < chapters.size(); ++c) {
    h << "<li><a href=\"#chapter-" << c << "\">" << inline_html(chapters[c].first) << "</a><br>";
    for (const Entry& e : chapters[c].second) {  // an overview: every claim with its verdict
      std::string id = e.row ? e.row->id : e.results.front()->claim, cls = e.verdict;
      cls.erase(std::remove(cls.begin(), cls.end(), ' '), cls.end());
      h << "<a class=\"v " << cls << "\" href=\"#" << anchor(id) << "\" title=\"" << html_escape(e.verdict) << "\">"
        << html_escape(id) << "</a> ";
    }
    h << "</li>\n";
  }
  h << "</ul>\n";
  for (std::size_t c = 0; c < chapters.size(); ++c) {
    h << "<h2 id=\"chapter-" << c << "\">" << inline_html(chapters[c].first) << "</h2>\n";
    if (!notes[c].empty()) h << "<p>" << inline_html(notes[c]) << "</p>\n";
    for (const Entry& e : chapters[c].second) {
      std::string id = e.row ? e.row->id : e.results.front()->claim;
      std::string cls = e.verdict;
      cls.erase(std::remove(cls.begin(), cls.end(), ' '), cls.end());
      h << "<div class=\"claim\" id=\"" << anchor(id) << "\">\n<h3>" << html_escape(id) << " <span class=\"v " << cls << "\">"
        << html_escape(e.verdict) << "</span></h3>\n<dl>\n";
      if (e.row)
        h << "<dt>Claim</dt><dd>" << inline_html(e.row->claim) << "</dd>\n<dt>Where</dt><dd>" << inline_html(e.row->where)
          << "</dd>\n<dt>How it is checked</dt><dd>" << inline_html(e.row->check) << "</dd>\n<dt>Tests</dt><dd>"
          << inline_html(e.row->tests) << "</dd>\n";
      for (const Result* r : e.results) {
        h << "<dt>Verdict (" << (e.via ? "via audit check " : "") << html_escape(r->claim) << ")</dt><dd><span class=\"v " << verdict_word(r->verdict) << "\">"
          << verdict_word(r->verdict) << "</span> " << html_escape(r->title)
          << (r->verdict.summary.empty() ? "" : ": " + html_escape(r->verdict.summary)) << " (" << fmt(r->seconds) << " s)</dd>\n";
        if (r->verdict.target_met)
          h << "<dt>Target</dt><dd>" << html_escape(r->verdict.target) << (*r->verdict.target_met ? " — met" : " — <b>missed</b>") << "</dd>\n";
        if (!r->verdict.thesis.empty()) h << "<dt>Thesis's figure</dt><dd>" << inline_html(r->verdict.thesis) << "</dd>\n";
      }
      if (e.verdict == "TODO") h << "<dt>Not checked yet</dt><dd>" << inline_html(todo_reason(e.row->status)) << "</dd>\n";
      if (e.row) h << "<dt>Ledger status</dt><dd>" << inline_html(e.row->status) << "</dd>\n";
      for (const std::string& cmd : e.replay) h << "<dt>Replay</dt><dd><code>" << html_escape(cmd) << "</code></dd>\n";
      h << "</dl>\n";
      for (const Result* r : e.results) {
        if (r->verdict.figures.empty()) continue;
        h << "<table>\n<tr><th>" << html_escape(r->claim) << " figure</th><th>value</th></tr>\n";
        for (const auto& [k, v] : r->verdict.figures) h << "<tr><td>" << html_escape(k) << "</td><td>" << html_escape(v) << "</td></tr>\n";
        h << "</table>\n";
      }
      for (std::size_t i = 0; i < e.plot_files.size(); ++i)
        h << "<p><img src=\"" << html_escape(e.plot_files[i]) << "\" alt=\"" << html_escape(e.plot_titles[i]) << "\"></p>\n";
      h << "</div>\n";
    }
  }
  h << "</body>\n</html>\n";
  write_file(fs::path(dir) / "index.html", h.str());
  return files;
}

}  // namespace kmr::audit
