// kmr bench <subcommand>: performance measurements. Subcommands: sac (self-adjusting programs, §1.3).
#include <algorithm>
#include <iomanip>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "exact/error.hpp"
#include "sacprograms/bench.hpp"
#include "sacprograms/programs.hpp"

namespace kmr::cli {

namespace {
int bench_sac(const Argv& argv) {
  Args args(argv, {"n", "edits", "seed", "program"}, {"json", "quiet"});
  if (args.help()) {
    std::cout << "usage: kmr bench sac [--n N] [--edits E] [--seed S] [--program NAME] [--json] [--quiet]\n"
                 "Runs each self-adjusting program (map, filter, sum, quicksort, mergesort, quickhull,\n"
                 "exptree) and its static twin on n seeded random elements; then E random single-element\n"
                 "insertions/deletions, each followed by change propagation. Reports static_s, initial_s,\n"
                 "overhead = initial_s / static_s, edit_s (mean per edit), speedup = static_s / edit_s,\n"
                 "trace_nodes, bytes_per_node. Exit status 1 if an output differs from the static twin.\n"
                 "Progress goes to stderr when it is a terminal (--quiet: none).\n";
    return 0;
  }
  if (!args.positional().empty()) throw InputError("kmr bench sac takes no positional argument");
  auto n = static_cast<std::size_t>(args.integer("n", 100000, 0, 100000000));
  auto edits = static_cast<std::size_t>(args.integer("edits", 200, 0, 100000000));
  auto seed = static_cast<std::uint64_t>(args.integer("seed", 20121, 0, 1LL << 62));
  std::vector<std::string> names, only;
  for (const auto& p : sacprograms::list_programs()) names.push_back(p.name);
  names.push_back("exptree");
  if (auto p = args.value("program")) {
    if (std::find(names.begin(), names.end(), *p) == names.end()) throw InputError("kmr bench sac: unknown --program");
    only = {*p};
  }
  Progress progress(args.has("quiet"));
  auto rows = sacprograms::bench_all(n, edits, seed, only, [&](std::size_t i, std::size_t count, const std::string& name) {
    progress.message("kmr bench sac [" + std::to_string(i + 1) + "/" + std::to_string(count) + "] " + name);
  });
  progress.done();
  bool ok = true;
  for (const auto& r : rows) ok = ok && r.output_ok;
  if (args.has("json")) {
    std::cout << sacprograms::bench_json(rows);
  } else {
    std::cout << std::left << std::setw(11) << "program" << std::right << std::setw(10) << "n" << std::setw(11)
              << "static_s" << std::setw(11) << "initial_s" << std::setw(10) << "overhead" << std::setw(11)
              << "edit_s" << std::setw(11) << "speedup" << std::setw(12) << "trace_nodes" << std::setw(9)
              << "B/node" << "  output\n";
    for (const auto& r : rows)
      std::cout << std::left << std::setw(11) << r.program << std::right << std::setw(10) << r.n << std::setw(11)
                << std::setprecision(4) << r.static_s << std::setw(11) << r.initial_s << std::setw(10) << r.overhead
                << std::setw(11) << r.edit_s << std::setw(11) << r.speedup << std::setw(12) << r.trace_nodes
                << std::setw(9) << r.bytes_per_node << "  " << (r.output_ok ? "ok" : "WRONG") << "\n";
  }
  return ok ? 0 : 1;
}
}  // namespace

int bench_command(const Argv& argv) {
  if (argv.empty() || argv[0] == "--help" || argv[0] == "-h") {
    std::cout << "usage: kmr bench <subcommand> [options]   (kmr bench <subcommand> --help)\n"
                 "subcommands:\n  sac   self-adjusting computation programs vs static twins (§1.3)\n";
    return argv.empty() ? 2 : 0;
  }
  Argv rest(argv.begin() + 1, argv.end());
  if (argv[0] == "sac") return bench_sac(rest);
  throw InputError("kmr bench: unknown subcommand '" + argv[0] + "'");
}

}  // namespace kmr::cli
