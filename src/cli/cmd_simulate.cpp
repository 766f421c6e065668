// kmr simulate sort: kinetic sorting on the lattice motion simulator (§2.1).
#include <fstream>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "exact/error.hpp"
#include "kinetic/kinetic_sort.hpp"
#include "kinetic/point_file.hpp"

namespace kmr::cli {

int simulate_command(const Argv& argv) {
  if (!argv.empty() && argv[0] == "hull") return simulate_hull_command(argv);
  Args args(argv, {"until", "lattice-bits"}, {});
  if (args.help() || args.positional().empty()) {
    std::cout << "usage: kmr simulate sort FILE [--until T] [--lattice-bits B]\n"
                 "       kmr simulate hull FILE ... (see kmr simulate hull --help)\n"
                 "FILE has one point per line, 'x0 v' (decimal integers): position x0 + v·t ('#' comments).\n"
                 "Simulates kinetic sorting from time 0 to T (a decimal dyadic, a multiple of δ = 2^-B;\n"
                 "default T = 2^27, B = 10), processing the failures of each lattice interval as one batch.\n"
                 "Prints JSON: events (certificate failures processed), batches, max_batch, and order\n"
                 "(0-based point indices sorted by position at T, ties broken by the order just before T).\n";
    return args.help() ? 0 : 2;
  }
  const auto& pos = args.positional();
  if (pos[0] != "sort") throw InputError("unknown structure '" + pos[0] + "' (known: sort, hull)");
  if (pos.size() != 2) throw InputError("kmr simulate sort takes exactly one FILE");
  int bits = static_cast<int>(args.integer("lattice-bits", 10, 0, 62));
  exact::Dyadic until = args.value("until") ? exact::Dyadic::parse(*args.value("until")) : exact::Dyadic::pow2(27);
  if (until.sign() < 0) throw InputError("--until must be >= 0");
  if (!until.shifted(bits).is_integer())
    throw InputError("--until " + until.to_decimal() + " is not a multiple of the lattice step 2^-" + std::to_string(bits));
  std::ifstream file(pos[1]);
  if (!file) throw InputError("cannot open '" + pos[1] + "'");
  std::vector<poly::Polynomial> positions;
  for (const auto& m : kinetic::parse_sort_points(file, pos[1]))
    positions.emplace_back(std::vector<exact::Integer>{m.x0, m.v});
  kinetic::MotionSimulator sim(bits, until);
  kinetic::KineticSort sort(std::move(positions), sim);
  sort.run_until(until);
  const auto& c = sim.counters();
  std::cout << "{\"events\": " << c.events << ", \"batches\": " << c.batches << ", \"max_batch\": " << c.max_batch
            << ", \"order\": [";
  for (std::size_t i = 0; i < sort.order().size(); ++i) std::cout << (i ? ", " : "") << sort.order()[i];
  std::cout << "]}\n";
  return 0;
}

}  // namespace kmr::cli
