// kmr kmesh: the Chapter 4 mesh (Fig. 4.2) of a point file: satellites converted rank by rank over
// the deformable spanner, then the Delaunay triangulation of the output; --check runs the library's
// brute-force lemma checks (L4.2.4, L4.2.5, L4.2.6, L4.2.9, L4.2.10, Delaunay, 9/2-well-spacedness).
// Points at rest with --updates run on kmesh/update.hpp (the change-propagation update of Fig. 4.5).
// Moving points run on kmesh/kds.hpp: the §4.3 certificates are advanced on the lattice and every
// batch of failures (and every update) is repaired by Fig. 4.5; --rebuild runs the reference KDS
// (kmesh/rebuild_simulation.hpp) that repairs by a from-scratch rebuild instead.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/formats.hpp"
#include "cli/kmesh_picture.hpp"
#include "cli/output_file.hpp"
#include "exact/error.hpp"
#include "exact/integer.hpp"
#include "kmesh/certificates.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"
#include "kmesh/kds.hpp"
#include "kmesh/rebuild_simulation.hpp"
#include "kmesh/update.hpp"

namespace kmr::cli {
namespace {

using namespace kmr::kmesh;

using Trajectory = KmeshTrajectory;

// The point file, parsed by cli/formats (the entry point the fuzz harness kmesh_files calls).
std::vector<Trajectory> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read file '" + path + "'");
  return parse_kmesh_points(in, path);
}

std::string num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

}  // namespace

int kmesh_command(const Argv& argv) {
  Args args(argv, {"until", "lattice-bits", "updates", "stats", "svg"}, {"check", "rebuild"});
  if (args.help()) {
    std::cout << "usage: kmr kmesh FILE [--until T] [--lattice-bits B] [--updates FILE] [--check] [--rebuild] [--stats FILE] [--svg FILE]\n"
                 "The Chapter 4 mesh of the points in FILE: satellites (24 rays, orbits 2^l) converted rank by rank\n"
                 "over a deformable spanner (Fig. 4.2), and the Delaunay triangulation of the output.\n"
                 "  FILE          one point per line, 'x y vx vy' or 'x y' (decimal integers of any size): the\n"
                 "                trajectory (x + vx t, y + vy t); '#' starts a comment\n"
                 "  --until T     the time of the output (a multiple of 2^-B; default 0, the static construction)\n"
                 "  --lattice-bits B  the time lattice 2^-B (default 10)\n"
                 "  --updates F   dynamic updates 'T + x y vx vy' (insert) / 'T - x y vx vy' (delete) at lattice time T\n"
                 "  (motion and updates: the certificates of §4.3 are simulated on the lattice; each batch of failures\n"
                 "   and each update is repaired by the update of Fig. 4.5)\n"
                 "  --rebuild     repair every batch and update by rebuilding from scratch instead (the reference KDS)\n"
                 "  --check       after the construction, every batch, every update and at T: brute-force checks of\n"
                 "                L4.2.5, L4.2.6, L4.2.9, L4.2.10, the spanner, Delaunay and 9/2-well-spacedness, L4.2.4 after\n"
                 "                every construction (--rebuild: at every check), and (motion) the kept certificates against a\n"
                 "                recomputation from scratch; exit 1 on a violation (--stats: each check's runs and violations)\n"
                 "  --stats F     per-rank counts, operation counts and measured constants as JSON\n"
                 "  --svg F       draw the mesh at time T: Delaunay triangles, input vertices filled, Steiner vertices open\n"
                 "stdout: JSON {\"time\", \"vertices\": [[x, y, kind]...] (kind 1 = Steiner), \"triangles\" (ccw),\n"
                 "\"events\", \"batches\" (certificate failures and their lattice intervals up to T), \"certificates\" (of §4.3\n"
                 "certificates of this mesh), \"first_failure\" (the first lattice interval (kδ, (k+1)δ] after T, within\n"
                 "2^20, in which one of them fails, \"time\" its start T + kδ; null if none)}. Bad input also: identical trajectories, two points colliding before T.\n"
                 "Bad input: a message naming the file and line, exit status 2.\n";
    return 0;
  }
  if (args.positional().size() != 1) throw InputError("kmr kmesh needs exactly one input FILE (see --help)");
  long long bits = args.integer("lattice-bits", 10, 0, 62);
  auto lattice_time = [&](const std::string& text, const std::string& where) { return parse_kmesh_time(text, where, bits); };
  Dyadic until = args.value("until") ? lattice_time(*args.value("until"), "--until") : Dyadic(0);
  const std::string& path = args.positional()[0];
  auto traj = read_points(path);
  struct Update {
    Dyadic t;
    bool insert;
    InputPoint p;
    std::string where;
  };
  std::vector<Update> updates;
  if (auto uf = args.value("updates")) {
    std::ifstream in(*uf);
    if (!in) throw InputError("cannot read file '" + *uf + "'");
    for (auto& u : parse_kmesh_updates(in, *uf, bits))
      updates.push_back({u.t, u.insert, {u.p.x, u.p.y, u.p.vx, u.p.vy}, u.where});
    std::stable_sort(updates.begin(), updates.end(), [](auto& a, auto& b) { return a.t < b.t; });
    for (auto& u : updates)
      if (u.t > until) throw InputError(u.where + ": update at time " + u.t.to_decimal() + " is after --until " + until.to_decimal());
  }
  // Validate everything before running: membership of every update, and no two trajectories in the
  // same place at a common time in [0, T] (the spread would be infinite). A life runs from its
  // insertion to its deletion, ordered by (time, place in the run: updates at one time apply in file
  // order), so a trajectory deleted at T and one inserted after it at T never coexist.
  constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();
  struct Life {
    InputPoint p;
    Dyadic from, to;
    std::string where;
    std::size_t from_seq = 0, to_seq = kNever;  // 0: the point file; k + 1: the k-th update in order
  };
  std::vector<Life> lives;
  std::vector<std::size_t> present;
  for (auto& p : traj) {
    present.push_back(lives.size());
    lives.push_back({{p.x, p.y, p.vx, p.vy}, Dyadic(0), until, path + ":" + std::to_string(p.line)});
  }
  auto same = [](const InputPoint& a, const InputPoint& b) { return a.x == b.x && a.y == b.y && a.vx == b.vx && a.vy == b.vy; };
  for (std::size_t k = 0; k < updates.size(); ++k) {
    const Update& u = updates[k];
    auto it = std::find_if(present.begin(), present.end(), [&](std::size_t i) { return same(lives[i].p, u.p); });
    if (u.insert) {
      if (it != present.end()) throw InputError(u.where + ": inserts a trajectory that is already present");
      present.push_back(lives.size());
      lives.push_back({u.p, u.t, until, u.where, k + 1, kNever});
    } else {
      if (it == present.end()) throw InputError(u.where + ": deletes a trajectory that is not present");
      if (present.size() == 1) throw InputError(u.where + ": deletes the last trajectory");
      lives[*it].to = u.t;
      lives[*it].to_seq = k + 1;
      present.erase(it);
    }
  }
  for (std::size_t i = 0; i < lives.size(); ++i)
    for (std::size_t j = i + 1; j < lives.size(); ++j) {
      auto start = [](const Life& l) { return std::pair{l.from, l.from_seq}; };
      auto end = [](const Life& l) { return std::pair{l.to, l.to_seq}; };
      if (!(std::max(start(lives[i]), start(lives[j])) < std::min(end(lives[i]), end(lives[j])))) continue;
      Dyadic from = std::max(lives[i].from, lives[j].from), to = std::min(lives[i].to, lives[j].to);
      if (same(lives[i].p, lives[j].p))
        throw InputError(lives[j].where + " and " + lives[i].where + ": identical trajectories");
      if (auto c = first_collision({lives[i].p, lives[j].p}, from, to))
        throw InputError(lives[j].where + " and " + lives[i].where + ": the two points collide at time " +
                         std::get<0>(*c).str() + " (the spread would be infinite)");
    }

  OutputFile picture;  // opened before the run (a bad path fails fast), removed if the run fails
  if (auto f = args.value("svg")) picture.open(*f, "--svg");
  std::vector<InputPoint> in;
  for (auto& p : traj) in.push_back({p.x, p.y, p.vx, p.vy});
  auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  std::vector<CheckResult> checks;
  // Every check run, by claim, for --stats: how often it ran, its violations, its largest measured
  // constant (9/2-well-spacedness, size conformity).
  struct Tally {
    std::size_t runs = 0, violations = 0;
    double measured = 0;
  };
  std::map<std::string, Tally> tally;
  auto report = [&](const std::string& when) {
    for (auto& c : checks) {
      Tally& t = tally[c.claim];
      ++t.runs, t.violations += c.violations.size(), t.measured = std::max(t.measured, c.measured);
      for (auto& v : c.violations) {
        std::cerr << "kmr kmesh --check (" << when << "): " << c.claim << ": " << v << "\n";
        status = 1;
      }
    }
  };
  // After the construction the checks of an updated mesh and L4.2.4, which reads the construction's
  // order of conversion (after an update U1 and L4.3.2 take its place: kmesh/invariants.hpp).
  auto constructed_checks = [](const Mesh& x) {
    auto c = check_all_updated(x);
    c.push_back(check_ball_empty(x));
    return c;
  };
  // Points at rest with insertions and deletions: the update of Fig. 4.5 (kmesh/update.hpp). Moving
  // points: the KDS (kmesh/kds.hpp), which repairs every batch by Fig. 4.5 (the nuclei of the failed
  // certificates relocated, spec/kmesh.md); --rebuild: the reference that rebuilds at every batch.
  bool at_rest = std::all_of(in.begin(), in.end(), [](auto& p) { return p.vx == 0 && p.vy == 0; }) &&
                 std::all_of(updates.begin(), updates.end(), [](auto& u) { return u.p.vx == 0 && u.p.vy == 0; });
  std::vector<Batch> batches;
  std::vector<UpdateStats> update_stats;
  std::size_t events = 0;
  // The kinetic KDS: the certificates the construction built, and per batch those built and dropped.
  bool incremental_certificates = false;
  std::size_t initial_certificates = 0, kept_certificates = 0;
  Mesh m;
  if (at_rest && !updates.empty()) {
    Updater U(in);
    m = U.mesh();
    if (args.has("check")) checks = constructed_checks(m), report("construction");
    for (auto& u : updates) {
      auto steiner = [](const Mesh& x) {
        std::set<std::pair<Dyadic, Dyadic>> s;
        for (std::size_t v = 0; v < x.size(); ++v)
          if (x.info[v].steiner) s.insert({x.spanner.position(int(v))[0], x.spanner.position(int(v))[1]});
        return s;
      };
      auto before = steiner(m);
      if (u.insert) U.insert(u.p);
      else U.erase(u.p);
      m = U.mesh();
      auto now = steiner(m);
      std::size_t kept = 0;
      for (auto& q : before) kept += now.count(q);
      batches.push_back({u.t, 0, u.insert ? "insert" : "delete", m.size(), kept, before.size()});
      update_stats.push_back(U.last());
      if (args.has("check"))
        checks = check_all_updated(m), report(std::string(u.insert ? "insert" : "delete") + " at time " + u.t.to_decimal());
    }
  } else if (!args.has("rebuild")) {
    KineticMesh kds(in, static_cast<int>(bits));
    initial_certificates = kds.certificates_created();
    std::optional<std::pair<std::size_t, Dyadic>> checked;  // (batches, now) at the last check
    auto check_now = [&](const std::string& when, bool construction = false) {
      if (!args.has("check")) return;
      checks = construction ? constructed_checks(kds.mesh()) : check_all_updated(kds.mesh());
      // L4.3.1: the repaired mesh is certified now, by the certificates recomputed from scratch.
      checks.push_back(check_kept_certificates(kds));
      checked = {kds.batches().size(), kds.now()};
      report(when);
    };
    check_now("construction", true);
    auto after = [&](const Batch& b) {
      update_stats.push_back(b.moved ? kds.last() : UpdateStats{});
      check_now("batch at time " + b.time.to_decimal());
    };
    for (auto& u : updates) {
      kds.run_until(u.t, after);
      if (u.insert) kds.insert(u.p);
      else kds.erase(u.p);
      update_stats.push_back(kds.last());
      check_now(std::string(u.insert ? "insert" : "delete") + " at time " + u.t.to_decimal());
    }
    kds.run_until(until, after);
    // The mesh at T, also when the last stretch had no batch (moved, and its certificates kept).
    if (checked != std::pair{kds.batches().size(), kds.now()}) check_now("at time " + until.to_decimal());
    m = kds.mesh();
    batches = kds.batches();
    incremental_certificates = true;
    kept_certificates = kds.certificates_kept();
    events = kds.events();
  } else {
    RebuildSimulation sim(in, static_cast<int>(bits));
    auto check_now = [&](const std::string& when) {
      if (!args.has("check")) return;
      checks = check_all(sim.snapshot());
      report(when);
    };
    check_now("construction");
    auto after = [&](const Batch& b) { check_now("batch at time " + b.time.to_decimal()); };
    for (auto& u : updates) {
      sim.run_until(u.t, after);
      if (u.insert) sim.insert(u.p);
      else sim.erase(u.p);
      check_now(std::string(u.insert ? "insert" : "delete") + " at time " + u.t.to_decimal());
    }
    sim.run_until(until, after);
    if (args.has("check")) {  // the mesh at T: the last snapshot moved to T, certified there (L4.3.1)
      checks = check_all(sim.mesh_now());
      CheckResult held{"L4.3.1", {}, 0};
      for (auto& c : sim.current_certificates())
        if (!holds_at(c, sim.now() - sim.snapshot_time()))
          held.violations.push_back(std::string(kind_name(c.kind)) + " certificate of " + std::to_string(c.a) + ", " +
                                    std::to_string(c.b) + " fails at " + sim.now().to_decimal());
      checks.push_back(held);
      report("at time " + until.to_decimal());
    }
    m = sim.mesh_now();
    batches = sim.batches();
    events = sim.events();
  }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<KmeshVertex> vertices;  // in input units: printed and drawn
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Point2& p = m.spanner.position(static_cast<int>(i));
    vertices.push_back({p[0].to_double() / double(kScale), p[1].to_double() / double(kScale), m.info[i].steiner});
  }
  std::ostringstream out;
  out << "{\"time\": " << until.to_decimal() << ", \"vertices\": [";
  for (std::size_t i = 0; i < vertices.size(); ++i)
    out << (i ? ", " : "") << "[" << num(vertices[i].x) << ", " << num(vertices[i].y) << ", " << (vertices[i].steiner ? 1 : 0) << "]";
  out << "], \"triangles\": [";
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    auto& t = m.triangles[i];
    out << (i ? ", " : "") << "[" << t[0] << ", " << t[1] << ", " << t[2] << "]";
  }
  // The certificates of §4.3 that certify this mesh, and the first lattice interval (kδ, (k+1)δ]
  // (within 2^20 time units) in which one of them fails: the mesh is valid until T + kδ.
  auto certs = certificates(m);
  auto fail = first_failure(certs, static_cast<int>(bits), Dyadic(1 << 20));
  std::size_t event_batches = 0;
  for (auto& b : batches) event_batches += b.what == "events";
  out << "], \"events\": " << events << ", \"batches\": " << event_batches << ", \"certificates\": " << certs.size()
      << ", \"first_failure\": ";
  if (fail)
    out << "{\"interval\": " << fail->first.str() << ", \"time\": " << num((until + Dyadic(fail->first, -bits)).to_double())
        << ", \"kind\": \"" << kind_name(certs[fail->second].kind) << "\"}";
  else
    out << "null";
  out << "}\n";

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
    bool first_check = true;
    for (auto& [claim, t] : tally)
      st << (first_check ? "" : ", ") << "{\"claim\": \"" << claim << "\", \"runs\": " << t.runs << ", \"violations\": "
         << t.violations << ", \"ok\": " << (t.violations == 0 ? "true" : "false") << ", \"measured\": " << num(t.measured)
         << "}",
          first_check = false;
    std::map<std::string, std::size_t> per_kind;
    for (auto& c : certs) ++per_kind[kind_name(c.kind)];
    st << "], ";
    if (incremental_certificates)
      st << "\"certificates_initial\": " << initial_certificates << ", \"certificates_kept\": " << kept_certificates << ", ";
    st << "\"certificates\": {";
    bool first = true;
    for (auto& [k, c] : per_kind) st << (first ? "" : ", ") << "\"" << k << "\": " << c, first = false;
    st << "}, \"batches\": [";
    for (std::size_t i = 0; i < batches.size(); ++i) {
      auto& b = batches[i];
      st << (i ? ", " : "") << "{\"time\": " << b.time.to_decimal() << ", \"what\": \"" << b.what << "\", \"events\": " << b.events
         << ", \"vertices\": " << b.vertices << ", \"steiner_before\": " << b.steiner_before << ", \"steiner_kept\": " << b.steiner_kept;
      if (incremental_certificates)
        st << ", \"certificates_created\": " << b.certs_created << ", \"certificates_destroyed\": " << b.certs_destroyed;
      if (i < update_stats.size()) {
        auto& u = update_stats[i];
        st << ", \"repair\": \"fig4.5\", \"affected\": " << u.affected << ", \"removed\": " << u.removed
           << ", \"converted\": " << u.converted << ", \"ranks\": " << u.ranks << ", \"ops\": " << u.ops
           << ", \"ops_delaunay\": " << u.ops_delaunay;
      } else {
        st << ", \"repair\": \"rebuild\"";
      }
      st << "}";
    }
    st << "]}\n";
  }
  if (picture.is_open()) {
    picture.stream() << kmesh_picture(vertices, m.triangles,
                                      "kmr kmesh " + path.substr(path.find_last_of('/') + 1) + " at time " + until.to_decimal());
    picture.commit();
  }
  std::cout << out.str();
  return status;
}

}  // namespace kmr::cli
