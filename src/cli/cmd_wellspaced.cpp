// kmr wellspaced: StableWS on an input file, dynamic updates with PropagateWS, optional
// from-scratch checking after each update (Lemma 3.4.2) and JSON statistics (thesis Chapter 3).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/output_file.hpp"
#include "cli/progress.hpp"
#include "cli/wellspaced_picture.hpp"
#include "cli/formats.hpp"
#include "exact/error.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace kmr::cli {
namespace {

using namespace kmr::wellspaced;

std::string json_num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// The default --max-vertices per dimension (spec/wellspaced.md, "Output-size estimate"): about
// 10 minutes at the measured construction speed (2D 0.1–0.3 ms, 3D 0.5–2.2 ms, 4D 5–35 ms per
// output vertex, 2 shared cores) and ≈ 10 KB of memory per vertex.
long long default_max_vertices(std::size_t dim) { return dim == 2 ? 1000000 : dim == 3 ? 300000 : 20000; }

std::string round_num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

// Refuses (InputError, exit 2) a run whose estimated output exceeds the limit, naming the estimate
// and the options that bring it within the limit (issue 11 §1: never an unbounded silent run). With
// --beta given (beta_fixed), a suggested rho stays below it, since rho < beta is required.
// With updates the estimate is of every point the run ever holds, the input and each insertion: the
// set after any update is a subset of it, and a subset's output is, up to the constants of
// size-optimality (T3.3.4: |M| = Θ(∫ 1/lfs^D)), no larger: its lfs is pointwise no smaller.
template <std::size_t D>
OutputEstimate refuse_out_of_reach_output(const std::vector<Point<D>>& input, const std::vector<WsUpdate<D>>& updates,
                                          const Params& params, bool beta_fixed, long long limit) {
  std::vector<Point<D>> held = input;
  std::size_t insertions = 0;
  if (!updates.empty()) {
    std::set<Point<D>> all(input.begin(), input.end());  // a duplicate input is left to the construction
    for (const WsUpdate<D>& u : updates)
      if (u.insert && all.insert(u.p).second) ++insertions;
    held.assign(all.begin(), all.end());
  }
  OutputEstimate e = estimate_output<D>(held, params.rho);
  if (limit == 0 || e.vertices <= double(limit)) return e;
  std::string msg = "the output is estimated at about " + round_num(e.vertices) + " vertices (n = " +
                    std::to_string(e.input) +
                    (insertions > 0 ? " with the " + std::to_string(insertions) + " new points of --updates" : "") +
                    ", " + std::to_string(e.leaves) + " squares in the 2^D-tree, depth " +
                    std::to_string(e.depth) + ", rho = " + json_num(params.rho) + ", dim " + std::to_string(D) +
                    "), more than --max-vertices " + std::to_string(limit) + "; ";
  std::string fit;
  for (double r : {1.05, 1.1, 1.2, 1.3, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 16.0, 32.0, 64.0})
    if (r > params.rho && (!beta_fixed || r < params.beta) && estimated_vertices(D, e.input, e.leaves, r) <= double(limit)) {
      fit = "--rho " + round_num(r) + " (about " + round_num(estimated_vertices(D, e.input, e.leaves, r)) + " vertices)";
      break;
    }
  msg += !fit.empty()  ? "use a larger rho, e.g. " + fit + ", or "
         : beta_fixed ? "no rho below --beta " + json_num(params.beta) + " fits (a larger --beta allows a larger rho); "
                      : "no rho <= 64 fits; ";
  msg += "raise --max-vertices (0 = no limit) to run it anyway";
  throw InputError(msg);
}

template <std::size_t D>
int run(const Args& args, const std::string& input_path, Params params) {
  std::ifstream in(input_path);
  if (!in) throw InputError("cannot read file '" + input_path + "'");
  std::vector<Point<D>> input = parse_ws_points<D>(in, input_path);
  std::vector<WsUpdate<D>> updates;
  if (auto up = args.value("updates")) {
    std::ifstream uf(*up);
    if (!uf) throw InputError("cannot read file '" + *up + "'");
    updates = parse_ws_updates<D>(uf, *up, input);
  }
  if (input.size() < 2) throw InputError(input_path + ": at least 2 input points are needed");
  OutputFile picture;  // opened before the run (a bad path fails fast), removed if the run fails
  if (auto f = args.value("svg")) picture.open(*f, "--svg");
  const OutputEstimate estimate =
      refuse_out_of_reach_output<D>(input, updates, params, args.value("beta").has_value(),
                                    args.integer("max-vertices", default_max_vertices(D), 0, 1LL << 53));
  Progress progress(args.has("quiet"));
  const std::string building = "kmr wellspaced: StableWS on " + std::to_string(input.size()) + " points";
  progress.message(building);
  bool constructing = true;  // the hook stays in params (and in ws): silent in updates and --check's scratch runs
  if (progress.enabled())
    params.progress = [&](std::size_t vertices, std::size_t) {
      if (constructing && progress.due())
        progress.message(building + ": " + std::to_string(vertices) + " vertices (about " +
                         round_num(estimate.vertices) + " estimated)");
    };
  WellSpacedSet<D> ws(input, params);
  constructing = false;
  Stats cstats = ws.stats();
  bool check = args.has("check");
  std::vector<std::pair<UpdateStats, double>> ustats;
  for (const WsUpdate<D>& u : updates) {
    progress.step(ustats.size(), updates.size(), "kmr wellspaced: updates");
    UpdateStats s;
    try {
      s = u.insert ? ws.insert(u.p) : ws.erase(u.p);
    } catch (const InputError& e) {
      throw InputError(u.where + ": " + e.what());
    }
    double scratch_seconds = 0;
    if (check) {
      auto t0 = std::chrono::steady_clock::now();
      WellSpacedSet<D> fresh(ws.input(), params);
      scratch_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      auto a = ws.vertices(), b = fresh.vertices();
      bool same = a.size() == b.size();
      for (std::size_t i = 0; same && i < a.size(); ++i) same = a[i].exact == b[i].exact && a[i].is_steiner == b[i].is_steiner;
      if (!same) {
        std::cerr << "kmr wellspaced: check failed after " << u.where << ": output differs from a from-scratch run ("
                  << a.size() << " vs " << b.size() << " vertices)\n";
        return 1;
      }
      if (ws.canonical_graph() != fresh.canonical_graph()) {
        std::cerr << "kmr wellspaced: check failed after " << u.where
                  << ": computation graph is not isomorphic to the from-scratch one\n";
        return 1;
      }
    }
    ustats.emplace_back(s, scratch_seconds);
  }
  if (picture.is_open()) {
    if constexpr (D == 2) {
      progress.message("kmr wellspaced: drawing " + *args.value("svg"));
      char caption[160];
      std::snprintf(caption, sizeof caption, "kmr wellspaced %s: rho = %g, beta = %g; Voronoi cells clipped to [0,1]^2",
                    input_path.substr(input_path.find_last_of('/') + 1).c_str(), params.rho, params.beta);
      picture.stream() << wellspaced_picture(ws, caption);
      picture.commit();
    }
  }
  progress.done();
  for (const auto& v : ws.vertices()) {
    // doubles as %.17g; a coordinate finer than a double (near-duplicate inputs) as an exact hex
    // float (spec/formats.md)
    for (std::size_t i = 0; i < D; ++i)
      if (v.exact.is_double(i)) std::printf("%.17g ", v.x[i]);
      else std::printf("%s ", v.exact.text(i).c_str());
    std::printf("%d\n", v.is_steiner ? 1 : 0);
  }
  if (auto sp = args.value("stats")) {
    std::ofstream js(*sp);
    if (!js) throw InputError("cannot write --stats file '" + *sp + "'");
    js << "{\n  \"dim\": " << D << ", \"rho\": " << json_num(params.rho) << ", \"beta\": " << json_num(params.beta)
       << ", \"kappa\": " << ws.kappa() << ",\n  \"construction\": {\"input\": " << input.size()
       << ", \"estimated_vertices\": " << json_num(estimate.vertices) << ", \"tree_leaves\": " << estimate.leaves
       << ", \"dispatches\": " << cstats.dispatches << ", \"fills\": " << cstats.fills << ", \"operations\": " << cstats.ops
       << ", \"steiner\": " << cstats.steiner << ", \"squares\": " << cstats.squares
       << ", \"cv_calls\": " << cstats.cv_calls << ", \"cv_squares_max\": " << cstats.cv_squares_max
       << ", \"cv_squares_mean\": " << json_num(cstats.cv_calls ? double(cstats.cv_squares_total) / cstats.cv_calls : 0)
       << ", \"cv_neighbors_max\": " << cstats.cv_neighbors_max << ", \"steiner_per_fill_max\": " << cstats.steiner_per_fill_max
       << ", \"exact_fallbacks\": " << cstats.exact_fallbacks
       << ", \"seconds\": " << json_num(cstats.seconds) << "},\n  \"updates\": [";
    for (std::size_t i = 0; i < ustats.size(); ++i) {
      const auto& [s, sc] = ustats[i];
      js << (i ? ",\n    " : "\n    ") << "{\"op\": \"" << (updates[i].insert ? "+" : "-") << "\", \"obsolete\": " << s.obsolete
         << ", \"fresh\": " << s.fresh << ", \"inconsistent\": " << s.inconsistent << ", \"steiner_inserted\": " << s.steiner_inserted
         << ", \"steiner_deleted\": " << s.steiner_deleted << ", \"obsolete_squares\": " << s.obsolete_squares
         << ", \"fresh_squares\": " << s.fresh_squares << ", \"seconds\": " << json_num(s.seconds);
      if (check) js << ", \"from_scratch_seconds\": " << json_num(sc);
      js << "}";
    }
    js << "\n  ]\n}\n";
  }
  return 0;
}

}  // namespace

int wellspaced_command(const Argv& argv) {
  Args args(argv, {"dim", "rho", "beta", "updates", "stats", "svg", "max-vertices"}, {"check", "quiet"});
  if (args.help()) {
    std::cout << "usage: kmr wellspaced --dim D [--rho R] [--beta B] [--updates FILE] [--check] [--stats FILE] [--svg FILE] [--max-vertices N] [--quiet] INPUT\n"
                 "Builds a rho-well-spaced, size-optimal superset of the points in INPUT (thesis Ch. 3, StableWS),\n"
                 "then applies dynamic updates (PropagateWS). D is 2, 3 or 4.\n"
                 "  INPUT       one point per line: D decimal coordinates in [0,1]; '#' starts a comment\n"
                 "  --rho R     well-spacedness ratio (default 1.5; every Voronoi cell within rho*NN)\n"
                 "  --beta B    clipping ratio, B > R (default 3)\n"
                 "  --updates   lines '+ x1 .. xD' (insert) or '- x1 .. xD' (delete), applied in order\n"
                 "  --check     after every update compare with a from-scratch run (output and computation\n"
                 "              graph); exit status 1 on a difference\n"
                 "  --stats     write construction and per-update counts as JSON\n"
                 "  --svg       (2D) draw the final output to FILE: Voronoi cells clipped to [0,1]^2, input\n"
                 "              vertices filled, Steiner vertices open\n"
                 "  --max-vertices N  refuse (exit 2) when the output is estimated above N vertices\n"
                 "              (default 1000000 in 2D, 300000 in 3D, 20000 in 4D; 0 = no limit)\n"
                 "  --quiet     no progress on stderr (shown only when stderr is a terminal)\n"
                 "stdout: the output vertices, 'x1 .. xD flag' with %.17g coordinates, flag 1 = Steiner;\n"
                 "a coordinate finer than a double (near-duplicate inputs) is an exact hex float (0x1.<hex>p<e>).\n"
                 "Bad input: a message naming the line, exit status 2, nothing applied.\n";
    return 0;
  }
  if (args.positional().size() != 1) throw InputError("kmr wellspaced needs exactly one INPUT file (see --help)");
  long long dim = args.integer("dim", 0, 2, 4);
  if (!args.value("dim")) throw InputError("--dim D is required (2, 3 or 4)");
  Params params;
  if (auto r = args.value("rho")) params.rho = parse_ws_number(*r, "--rho");
  if (auto b = args.value("beta")) params.beta = parse_ws_number(*b, "--beta");
  else if (args.value("rho")) params.beta = std::max(params.beta, 2 * params.rho);
  if (!(params.rho > 1)) throw InputError("--rho must be > 1");
  if (!(params.beta > params.rho)) throw InputError("--beta must be > --rho");
  if (args.value("svg") && dim != 2) throw InputError("--svg draws 2D outputs only (use --dim 2)");
  const std::string& input = args.positional()[0];
  switch (dim) {
    case 2: return run<2>(args, input, params);
    case 3: return run<3>(args, input, params);
    default: return run<4>(args, input, params);
  }
}

}  // namespace kmr::cli
