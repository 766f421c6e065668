#pragma once
// The claims auditor behind `kmr audit`. Each check names a claim ID of spec/claims.md, runs on
// built-in deterministic defaults (seeded), and returns a verdict with the figures it measured.
// Guarantees: checks run in registry order; the same binary and options print the same verdicts and
// counts (timings excepted); run_audit's status is non-zero iff some check failed or threw.
#include <any>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "svg/plot.hpp"

namespace kmr::audit {

struct Options {
  bool quick = false;          // smaller sizes (used by the ctest `audit` label)
  std::uint64_t seed = 20121;  // every random input derives from this seed
  std::string only;            // run only the checks whose claim ID starts with this prefix ("ID$": exactly ID)
  // Called before each check (index from 0, count, claim ID) and once more with index == count at
  // the end; the CLI shows it on stderr when stderr is a terminal. Never writes to `out`.
  std::function<void(std::size_t, std::size_t, const std::string&)> progress;
  // A seam for tests of the judges (tests/audit/fail_verdict_test.cpp, threshold_test.cpp), never
  // set by `kmr audit`:
  // a check passes the measured result it is about to judge through measured(options, name, value),
  // and tamper may replace that value (held in the std::any) with a wrong one, so that a test sees
  // the check's FAIL path. Unset, measured() returns the value untouched: the audit measures and
  // judges exactly what it did without the seam.
  std::function<void(const std::string& name, std::any& value)> tamper;
};

// The measured value `value`, named `name` (claim ID and quantity), as the check should judge it:
// itself unless a test's Options::tamper changed it (see Options::tamper).
template <class T>
T measured(const Options& options, const std::string& name, T value) {
  if (!options.tamper) return value;
  std::any held(std::move(value));
  options.tamper(name, held);
  return std::any_cast<T>(std::move(held));
}

struct Verdict {
  bool pass = false;
  std::string summary;                                       // one line: what was checked, on what
  std::vector<std::pair<std::string, std::string>> figures;  // measured figures, name → value
  void figure(std::string name, std::string value) { figures.emplace_back(std::move(name), std::move(value)); }
  // The pictures of the measured figures: fill an svg::Plot (series of (x, y) points, axis labels and
  // units, optional bounds) and the report draws it; the JSON carries the same points.
  std::vector<svg::Plot> plots;
  void plot(svg::Plot p) { plots.push_back(std::move(p)); }
  std::string thesis;  // the thesis's (or its cited anchor's) own figure for this claim, when it gives one
  // A speed or size target the issue or the thesis sets for a measured figure, and whether this run
  // met it. `pass` stays the correctness verdict; a missed target shows as MISSED, never as PASS.
  std::string target;
  std::optional<bool> target_met;
  void set_target(std::string what, bool met) { target = std::move(what), target_met = met; }
};
// The word for a verdict: FAIL (pass is false), MISSED (pass, but a stated target was not met), PASS.
const char* verdict_word(const Verdict& v);

struct Check {
  std::string claim;  // claim ID from spec/claims.md, e.g. "A2.1-lattice"
  std::string title;
  std::function<Verdict(const Options&)> run;
};

// The registry: every chapter's checks in a fixed order (audit/registry.cpp).
std::vector<Check> all_checks();

// Per-chapter check lists (one file each under src/audit/).
std::vector<Check> roots_checks();
std::vector<Check> kinetic_checks();
std::vector<Check> sac_checks();
std::vector<Check> wellspaced_checks();
std::vector<Check> hull_checks();
std::vector<Check> kmesh_checks();

// A measured figure as text with 3 significant digits (one format for every check).
std::string fmt(double x);

// kmr's version (CMake project version), printed by `kmr --version` and written into JSON and report.
const char* version();

// One check's outcome.
struct Result {
  std::string claim, title;
  Verdict verdict;
  double seconds = 0;
  std::string replay;  // the command that reproduces it when it is not `kmr audit --only CLAIM` (e.g. a benchmark's)
};
// Does --only selector `only` choose check `claim`: `claim` starts with `only`, or, when `only` ends
// with "$", equals it without the "$" ("T3.4.3" chooses T3.4.3 and T3.4.3-speed, "T3.4.3$" only T3.4.3).
bool selected(const std::string& claim, const std::string& only);
// The checks options.only selects, in registry order. Throws InputError naming the selector and
// listing the known claim IDs when none matches.
std::vector<Check> select_checks(const Options& options);
// Runs the checks options.only selects (select_checks), in registry order (a throwing check FAILs).
// Throws InputError naming the prefix and listing the known claim IDs when none matches.
std::vector<Result> run_checks(const Options& options);
void print_table(const std::vector<Result>& results, std::ostream& out);
void write_json(const std::vector<Result>& results, std::ostream& json);
// Reads results that write_json wrote — e.g. a benchmark's that links CGAL, which the audit does
// not (bench/roots/roots_bench --audit-json FILE) — so that `kmr audit --include FILE` reports them
// beside its own. Throws InputError naming the file and the problem on malformed input.
std::vector<Result> read_json(const std::string& path);
// 0 iff at least one check ran and every check passed.
int status(const std::vector<Result>& results);

// Runs the checks, prints a table to `out` (and JSON to `json` when not null). Returns 0 iff all pass.
int run_audit(const Options& options, std::ostream& out, std::ostream* json);

}  // namespace kmr::audit
