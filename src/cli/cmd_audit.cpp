#include <fstream>
#include <iostream>

#include "audit/audit.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "exact/error.hpp"

namespace kmr::cli {

int audit_command(const Argv& argv) {
  Args args(argv, {"json", "only", "seed"}, {"quick"});
  if (args.help()) {
    std::cout << "usage: kmr audit [--quick] [--only CLAIM-PREFIX] [--seed N] [--json FILE]\n"
                 "Runs every check of the claims ledger (spec/claims.md) on built-in seeded defaults and\n"
                 "prints a table: claim, verdict, measured figures. Exit status 1 if any claim fails.\n"
                 "  --quick   smaller inputs (what ctest runs)\n"
                 "  --only    run only the claims whose ID starts with the prefix\n"
                 "  --json    also write the verdicts and figures as JSON to FILE\n";
    return 0;
  }
  if (!args.positional().empty()) throw InputError("kmr audit takes no positional argument");
  audit::Options options;
  options.quick = args.has("quick");
  options.only = args.value("only").value_or("");
  if (!options.only.empty()) {  // a prefix that selects nothing is a typo, not a passing audit
    bool any = false;
    for (const auto& c : audit::all_checks()) any = any || c.claim.rfind(options.only, 0) == 0;
    if (!any) throw InputError("--only '" + options.only + "' matches no claim ID (see spec/claims.md)");
  }
  options.seed = static_cast<std::uint64_t>(args.integer("seed", 20121, 0, 1LL << 62));
  std::ofstream json;
  if (auto path = args.value("json")) {
    json.open(*path);
    if (!json) throw InputError("cannot write --json file '" + *path + "'");
  }
  return audit::run_audit(options, std::cout, json.is_open() ? &json : nullptr);
}

}  // namespace kmr::cli
