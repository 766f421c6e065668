#pragma once
// The claims auditor behind `kmr audit`. Each check names a claim ID of spec/claims.md, runs on
// built-in deterministic defaults (seeded), and returns a verdict with the figures it measured.
// Guarantees: checks run in registry order; the same binary and options print the same verdicts and
// counts (timings excepted); run_audit's status is non-zero iff some check failed or threw.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace kmr::audit {

struct Options {
  bool quick = false;          // smaller sizes (used by the ctest `audit` label)
  std::uint64_t seed = 20121;  // every random input derives from this seed
  std::string only;            // run only the checks whose claim ID starts with this prefix
};

struct Verdict {
  bool pass = false;
  std::string summary;                                       // one line: what was checked, on what
  std::vector<std::pair<std::string, std::string>> figures;  // measured figures, name → value
  void figure(std::string name, std::string value) { figures.emplace_back(std::move(name), std::move(value)); }
};

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
std::vector<Check> kmesh_checks();

// A measured figure as text with 3 significant digits (one format for every check).
std::string fmt(double x);

// Runs the checks, prints a table to `out` (and JSON to `json` when not null). Returns 0 iff all pass.
int run_audit(const Options& options, std::ostream& out, std::ostream* json);

}  // namespace kmr::audit
