// kmr kmesh: the Chapter 4 mesh (Fig. 4.2) of a point file: satellites converted rank by rank over
// the deformable spanner, then the Delaunay triangulation of the output; --check runs the library's
// brute-force lemma checks (L4.2.4, L4.2.5, L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spacedness).
// Only the static construction at T = 0 is implemented: the kinetic/dynamic part of the issue
// (--until T > 0, --updates) is refused with a message saying so (spec/kmesh.md). The §4.3
// certificates of the mesh are built as polynomials of time and their first failure is reported.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "exact/error.hpp"
#include "exact/integer.hpp"
#include "kmesh/certificates.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"

namespace kmr::cli {
namespace {

using namespace kmr::kmesh;

struct Trajectory {
  exact::Integer x, y, vx, vy;
  std::size_t line;
};

std::vector<Trajectory> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read file '" + path + "'");
  std::vector<Trajectory> out;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    auto h = line.find('#');
    if (h != std::string::npos) line.resize(h);
    std::istringstream ss(line);
    std::vector<std::string> t;
    std::string w;
    while (ss >> w) t.push_back(w);
    if (t.empty()) continue;
    std::string where = path + ":" + std::to_string(n);
    if (t.size() != 2 && t.size() != 4)
      throw InputError(where + ": expected 'x y' or 'x y vx vy', got " + std::to_string(t.size()) + " values");
    auto num = [&](const std::string& s) {
      try {
        return exact::parse_integer(s);
      } catch (const InputError&) {
        throw InputError(where + ": '" + s + "' is not a decimal integer");
      }
    };
    Trajectory p{num(t[0]), num(t[1]), t.size() == 4 ? num(t[2]) : exact::Integer(0),
                 t.size() == 4 ? num(t[3]) : exact::Integer(0), n};
    out.push_back(p);
  }
  if (out.empty()) throw InputError(path + ": no input point");
  return out;
}

std::string num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

}  // namespace

int kmesh_command(const Argv& argv) {
  Args args(argv, {"until", "lattice-bits", "updates", "stats"}, {"check"});
  if (args.help()) {
    std::cout << "usage: kmr kmesh FILE [--until T] [--lattice-bits B] [--updates FILE] [--check] [--stats FILE]\n"
                 "The Chapter 4 mesh of the points in FILE: satellites (24 rays, orbits 2^l) converted rank by rank\n"
                 "over a deformable spanner (Fig. 4.2), and the Delaunay triangulation of the output.\n"
                 "  FILE          one point per line, 'x y vx vy' or 'x y' (decimal integers of any size): the\n"
                 "                trajectory (x + vx t, y + vy t); '#' starts a comment\n"
                 "  --until T     the time of the output; only T = 0 (the static construction) is implemented\n"
                 "  --lattice-bits B  the time lattice 2^-B (default 10; used by the kinetic part, not yet here)\n"
                 "  --updates F   dynamic updates 'T + x y vx vy' / 'T - x y vx vy' (not implemented yet)\n"
                 "  --check       brute-force checks of L4.2.4, L4.2.5, L4.2.6, L4.2.9, L4.2.10, the spanner, Delaunay\n"
                 "                and 9/2-well-spacedness; exit status 1 on a violation\n"
                 "  --stats F     per-rank counts, operation counts and measured constants as JSON\n"
                 "stdout: JSON {\"time\", \"vertices\": [[x, y, kind]...] (kind 1 = Steiner), \"triangles\" (ccw),\n"
                 "\"events\", \"batches\" (0: no kinetic simulation yet), \"certificates\" (the number of §4.3\n"
                 "certificates of this mesh), \"first_failure\" (the first lattice interval, within 2^20, where one of\n"
                 "them fails, i.e. how long the T = 0 mesh stays valid; null if none)}.\n"
                 "Bad input: a message naming the file and line, exit status 2.\n";
    return 0;
  }
  if (args.positional().size() != 1) throw InputError("kmr kmesh needs exactly one input FILE (see --help)");
  long long bits = args.integer("lattice-bits", 10, 0, 62);
  if (auto t = args.value("until")) {
    exact::Integer T;
    try {
      T = exact::parse_integer(*t);
    } catch (const InputError&) {
      throw InputError("--until: '" + *t + "' is not a lattice time (an integer number of 2^-B steps)");
    }
    if (T != 0)
      throw InputError("--until " + *t + ": the kinetic simulation of Chapter 4 (§4.3) is not implemented yet; only T = 0");
  }
  if (args.value("updates"))
    throw InputError("--updates: dynamic insertions and deletions (Fig. 4.5) are not implemented yet");
  const std::string& path = args.positional()[0];
  auto traj = read_points(path);
  // Two trajectories in the same place at T = 0 (identical, or colliding now): infinite spread.
  std::map<std::pair<exact::Integer, exact::Integer>, std::size_t> at;
  for (auto& p : traj) {
    auto [it, fresh] = at.insert({{p.x, p.y}, p.line});
    if (!fresh)
      throw InputError(path + ":" + std::to_string(p.line) + " and line " + std::to_string(it->second) +
                       ": two points at (" + p.x.str() + ", " + p.y.str() + ") at time 0" +
                       " (identical trajectories or a collision; the spread would be infinite)");
  }
  std::vector<InputPoint> in;
  for (auto& p : traj) in.push_back({p.x, p.y, p.vx, p.vy});
  auto t0 = std::chrono::steady_clock::now();
  Mesh m = construct(in);
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::ostringstream out;
  out << "{\"time\": 0, \"vertices\": [";
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Point2& p = m.spanner.position(static_cast<int>(i));
    out << (i ? ", " : "") << "[" << num(p[0].to_double() / double(kScale)) << ", "
        << num(p[1].to_double() / double(kScale)) << ", " << (m.info[i].steiner ? 1 : 0) << "]";
  }
  out << "], \"triangles\": [";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    auto& t = m.triangles[i];
    out << (i ? ", " : "") << "[" << t[0] << ", " << t[1] << ", " << t[2] << "]";
  }
  // The certificates of §4.3 that certify this mesh, and the first lattice interval (within 2^20
  // time units) in which one of them fails: the mesh at T = 0 is valid until then.
  auto certs = certificates(m);
  auto fail = first_failure(certs, static_cast<int>(bits), Dyadic(1 << 20));
  out << "], \"events\": 0, \"batches\": 0, \"certificates\": " << certs.size() << ", \"first_failure\": ";
  if (fail)
    out << "{\"interval\": " << fail->first.str() << ", \"time\": " << num(Dyadic(fail->first, -bits).to_double())
        << ", \"kind\": \"" << kind_name(certs[fail->second].kind) << "\"}";
  else
    out << "null";
  out << "}\n";

  int status = 0;
  std::vector<CheckResult> checks;
  if (args.has("check")) {
    checks = check_all(m);
    for (auto& c : checks)
      for (auto& v : c.violations) {
        std::cerr << "kmr kmesh --check: " << c.claim << ": " << v << "\n";
        status = 1;
      }
  }
  if (auto sf = args.value("stats")) {
    std::ofstream st(*sf);
    if (!st) throw InputError("cannot write --stats file '" + *sf + "'");
    std::size_t steiner = m.size() - m.n();
    st << "{\"n\": " << m.n() << ", \"vertices\": " << m.size() << ", \"steiner\": " << steiner
       << ", \"triangles\": " << m.triangles.size() << ", \"lowest_rank\": " << m.lowest
       << ", \"highest_rank\": " << m.highest << ", \"ops\": {\"spanner\": " << m.ops_spanner
       << ", \"convert\": " << m.ops_convert << ", \"delaunay\": " << m.ops_delaunay << "}, \"seconds\": " << num(secs)
       << ", \"ranks\": [";
    for (std::size_t i = 0; i < m.ranks.size(); ++i) {
      auto& r = m.ranks[i];
      std::size_t centers = 0;
      for (std::size_t v = 0; v < m.size(); ++v)
        if (m.spanner.top(static_cast<int>(v)) >= r.rank && m.spanner.min_rank(static_cast<int>(v)) <= r.rank) ++centers;
      st << (i ? ", " : "") << "{\"rank\": " << r.rank << ", \"active\": " << r.active << ", \"considered\": "
         << r.considered << ", \"converted\": " << r.converted << ", \"promoted\": " << r.promoted
         << ", \"centers\": " << centers << "}";
    }
    st << "], \"checks\": [";
    for (std::size_t i = 0; i < checks.size(); ++i)
      st << (i ? ", " : "") << "{\"claim\": \"" << checks[i].claim << "\", \"ok\": " << (checks[i].ok() ? "true" : "false")
         << ", \"measured\": " << num(checks[i].measured) << "}";
    std::map<std::string, std::size_t> per_kind;
    for (auto& c : certs) ++per_kind[kind_name(c.kind)];
    st << "], \"certificates\": {";
    bool first = true;
    for (auto& [k, c] : per_kind) st << (first ? "" : ", ") << "\"" << k << "\": " << c, first = false;
    st << "}, \"events\": [], \"updates\": []}\n";
  }
  std::cout << out.str();
  return status;
}

}  // namespace kmr::cli
