#include <filesystem>
#include <fstream>
#include <iostream>

#include "audit/audit.hpp"
#include "audit/ledger.hpp"
#include "audit/report.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "exact/error.hpp"

namespace kmr::cli {

int audit_command(const Argv& argv) {
  Args args(argv, {"json", "only", "seed", "report", "include"}, {"quick", "quiet"});
  if (args.help()) {
    std::cout << "usage: kmr audit [--quick] [--only CLAIM-PREFIX] [--seed N] [--json FILE] [--report DIR] [--include FILE] [--quiet]\n"
                 "Runs every check of the claims ledger (spec/claims.md) on built-in seeded defaults and\n"
                 "prints a table: claim, verdict, measured figures. Exit status 1 if any claim fails.\n"
                 "  --quick   smaller inputs (what ctest runs)\n"
                 "  --only    run only the claims whose ID starts with the prefix ('ID$': exactly ID)\n"
                 "  --json    also write the verdicts, figures and plot data as JSON to FILE\n"
                 "  --report  also write DIR/report.md, DIR/index.html (offline) and DIR/*.svg plots: one\n"
                 "            entry per ledger claim with verdict, figures and the command that replays it\n"
                 "  --include also report the results in FILE (JSON in the --json format, e.g. written by\n"
                 "            bench/roots/roots_bench --audit-json FILE: the root solver vs CGAL)\n"
                 "  --quiet   no progress on stderr (shown only when stderr is a terminal)\n";
    return 0;
  }
  if (!args.positional().empty()) throw InputError("kmr audit takes no positional argument");
  audit::Options options;
  options.quick = args.has("quick");
  options.only = args.value("only").value_or("");
  options.seed = static_cast<std::uint64_t>(args.integer("seed", 20121, 0, 1LL << 62));
  audit::select_checks(options);  // an --only without a match fails before any file is written
  std::vector<audit::Result> included;  // read before --json truncates a file (it may be the same one)
  if (auto path = args.value("include")) included = audit::read_json(*path);
  std::ofstream json;
  if (auto path = args.value("json")) {
    json.open(*path);
    if (!json) throw InputError("cannot write --json file '" + *path + "'");
  }
  std::vector<audit::LedgerSection> ledger;
  if (auto dir = args.value("report")) {  // fail before the run, not after it
    std::error_code ec;
    std::filesystem::create_directories(*dir, ec);
    if (ec || !std::filesystem::is_directory(*dir)) throw InputError("cannot create report directory '" + *dir + "'");
    ledger = audit::parse_ledger(audit::claims_ledger());
  }
  Progress progress(args.has("quiet"));
  if (progress.enabled())
    options.progress = [&](std::size_t i, std::size_t n, const std::string& claim) {
      if (i < n) progress.message("kmr audit [" + std::to_string(i + 1) + "/" + std::to_string(n) + "] " + claim);
      else progress.done();
    };
  auto results = audit::run_checks(options);
  results.insert(results.end(), included.begin(), included.end());
  audit::print_table(results, std::cout);
  if (json.is_open()) audit::write_json(results, json);
  if (auto dir = args.value("report")) {
    audit::write_report(*dir, results, options, ledger);
    std::cout << "report: " << *dir << "/index.html, " << *dir << "/report.md\n";
  }
  return audit::status(results);
}

}  // namespace kmr::cli
