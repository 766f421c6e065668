#pragma once
// The `kmr` commands. Each takes the arguments after its name, writes its result to stdout and
// returns the exit status: 0 success, 1 a check failed, 2 bad input (message on stderr).
#include <string>
#include <vector>

namespace kmr::cli {

using Argv = std::vector<std::string>;

int audit_command(const Argv& args);
int roots_command(const Argv& args);
int simulate_command(const Argv& args);
int simulate_hull_command(const Argv& args);  // kmr simulate hull (cmd_simulate_hull.cpp)
int bench_command(const Argv& args);
int wellspaced_command(const Argv& args);
int hull_command(const Argv& args);
int kmesh_command(const Argv& args);

}  // namespace kmr::cli
