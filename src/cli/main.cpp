// kmr: the command-line entry point. Dispatches to one command per file (cli/commands.hpp).
#include <malloc.h>

#include <exception>
#include <iostream>
#include <string>

#include "audit/audit.hpp"
#include "cli/commands.hpp"
#include "exact/error.hpp"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const kmr::cli::Argv&);
};

const Command kCommands[] = {
    {"audit", "check the thesis's claims on built-in defaults and report figures", kmr::cli::audit_command},
    {"roots", "isolate the real roots of a polynomial to lattice intervals", kmr::cli::roots_command},
    {"simulate", "run a kinetic simulation on the lattice (kinetic sorting)", kmr::cli::simulate_command},
    {"wellspaced", "dynamic well-spaced point sets (thesis Ch. 3): StableWS, updates, checks", kmr::cli::wellspaced_command},
    {"hull", "the static 3D convex hull of thesis Ch. 2 (exact, or --float)", kmr::cli::hull_command},
    {"kmesh", "kinetic mesh refinement in 2D (thesis Ch. 4): the static construction of Fig. 4.2, checks", kmr::cli::kmesh_command},
    {"bench", "measure performance (bench sac: self-adjusting programs vs static twins)", kmr::cli::bench_command},
};

int usage(std::ostream& out) {
  out << "usage: kmr <command> [options]   (kmr <command> --help for details; kmr --version)\n\ncommands:\n";
  for (const Command& c : kCommands) out << "  " << c.name << std::string(12 - std::string(c.name).size(), ' ') << c.summary << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Freed memory stays for reuse: glibc's mmap threshold starts at 128 KiB (and rises only as
  // mmapped blocks are freed) and the heap's free top is trimmed past 128 KiB, so a run after a run
  // (the audit's best of 5 kinetic hulls: their simulator records and tables) faulted its pages in
  // afresh, ≈ 6–12 µs a page in this VM (spec/hull.md, "Warm memory"). Blocks below 32 MiB (glibc's
  // largest threshold) now come from the heap, and up to 256 MiB of free heap top stays mapped. A
  // refused setting leaves glibc's default. (No result depends on it.)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  if (argc < 2) {
    usage(std::cerr);
    return 2;
  }
  std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") return usage(std::cout);
  if (name == "--version") {
    std::cout << "kmr " << kmr::audit::version() << "\n";
    return 0;
  }
  kmr::cli::Argv args(argv + 2, argv + argc);
  for (const Command& c : kCommands) {
    if (name != c.name) continue;
    try {
      return c.run(args);
    } catch (const kmr::InputError& e) {
      std::cerr << "kmr " << name << ": error: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "kmr " << name << ": internal error: " << e.what() << "\n";
      return 3;
    }
  }
  std::cerr << "kmr: unknown command '" << name << "'\n";
  usage(std::cerr);
  return 2;
}
