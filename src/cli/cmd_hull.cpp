// kmr hull: the static 3D convex hull of §2.2 (exact by default, --float for the Fig. 2.4 baseline).
#include <chrono>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/hull_picture.hpp"
#include "exact/error.hpp"
#include "hull/hull.hpp"
#include "hull/xyz_file.hpp"

namespace kmr::cli {

int hull_command(const Argv& argv) {
  Args args(argv, {"stats", "svg"}, {"float"});
  if (args.help() || args.positional().size() != 1) {
    std::cout << "usage: kmr hull FILE [--float] [--stats FILE] [--svg FILE]\n"
                 "FILE has one point per line, 'x y z' (decimal numbers, read as the nearest doubles; '#' comments).\n"
                 "Computes the 3D convex hull with the randomized incremental algorithm of thesis §2.2, with\n"
                 "exact predicates (a filtered orient3d with exact fallback); --float uses plain doubles\n"
                 "(the Fig. 2.4 baseline; NOT robust on degenerate or near-degenerate input).\n"
                 "Prints JSON {\"n\", \"vertices\", \"facets\"}: vertices are the 0-based indices of the extreme\n"
                 "points (the lowest index among equal points), increasing; facets are triangles\n"
                 "counter-clockwise seen from outside, smallest index first, sorted. --stats FILE writes\n"
                 "counters (insertions, history steps, orientation tests, exact fallbacks, seconds) as JSON.\n"
                 "--svg FILE draws the hull (orthographic, a fixed view): front faces filled, back-face edges dashed,\n"
                 "hull vertices marked, other input points small grey dots.\n";
    return args.help() ? 0 : 2;
  }
  const std::string& name = args.positional()[0];
  std::ifstream file(name);
  if (!file) throw InputError("cannot open '" + name + "'");
  auto points = hull::read_xyz(file, name);
  OutputFile picture;  // opened before the run (a bad path fails fast), removed if the run fails
  if (auto f = args.value("svg")) picture.open(*f, "--svg");
  auto start = std::chrono::steady_clock::now();
  hull::Hull h;
  try {
    h = hull::convex_hull(points, args.has("float") ? hull::Arithmetic::floating : hull::Arithmetic::exact);
  } catch (const ContractError& e) {
    if (!args.has("float")) throw;
    throw std::runtime_error(std::string("the --float baseline failed (it is not robust; run without --float): ") + e.what());
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (picture.is_open()) {
    picture.stream() << hull_picture(points, h, "kmr hull " + name.substr(name.find_last_of('/') + 1) + ": " +
                                                    std::to_string(points.size()) + " points, orthographic view");
    picture.commit();
  }
  std::cout << "{\"n\": " << h.n << ", \"vertices\": [";
  for (std::size_t i = 0; i < h.vertices.size(); ++i) std::cout << (i ? ", " : "") << h.vertices[i];
  std::cout << "], \"facets\": [";
  for (std::size_t i = 0; i < h.facets.size(); ++i)
    std::cout << (i ? ", " : "") << "[" << h.facets[i][0] << ", " << h.facets[i][1] << ", " << h.facets[i][2] << "]";
  std::cout << "]}\n";
  if (auto stats = args.value("stats")) {
    std::ofstream out(*stats);
    if (!out) throw InputError("cannot write '" + *stats + "'");
    const hull::HullStats& s = h.stats;
    out << "{\"arithmetic\": \"" << (args.has("float") ? "float" : "exact") << "\", \"points\": " << s.points
        << ", \"inserted\": " << s.inserted << ", \"discarded\": " << s.discarded << ", \"duplicates\": " << s.duplicates
        << ", \"faces_created\": " << s.faces_created << ", \"history_steps\": " << s.history_steps
        << ", \"orientation_tests\": " << s.orientation_tests << ", \"exact_fallbacks\": " << s.exact_fallbacks
        << ", \"hull_vertices\": " << h.vertices.size() << ", \"hull_facets\": " << h.facets.size()
        << ", \"seconds\": " << seconds << "}\n";
  }
  return 0;
}

}  // namespace kmr::cli
