// Fig. 2.3 (simulations compared): events of kmr's kinetic hull vs a kinetic 3D Delaunay
// triangulation (kinetic_delaunay.hpp: CGAL Delaunay_triangulation_3 rebuilt after every batch,
// certificates on the same lattice MotionSimulator) on identical §2.4 motions (Bℓ = 20, Bv = 8 bits,
// δ = 2^-10, until 2^27, i.e. until the queue is empty for these motions), the thesis's sizes.
// Event counts only; the times printed are not a fair comparison (the baseline rebuilds per batch).
// Checks while it runs: the kinetic hull against the exact static hull every K-th batch, the
// kept Delaunay triangulation against CGAL's inside every K-th gap between batches, and at the end
// the hull vertices of the triangulation against the kinetic hull's.
// Usage: fig23_bench [--n 22,49,...] [--seeds S] [--check-every K] [--until-log2 E] [--audit-json FILE]
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "audit/audit.hpp"
#include "hull/hull_at_time.hpp"
#include "hull/kinetic_hull.hpp"
#include "kinetic/trajectory.hpp"
#include "kinetic_delaunay.hpp"

namespace {

using kmr::exact::Dyadic;

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Row {
  int n = 0, runs = 0;
  long long hull_events = 0, hull_batches = 0, dt_events = 0, dt_flips = 0, dt_batches = 0, rebuilds = 0, retries = 0;
  long long hull_output_changes = 0, checks = 0, check_failures = 0, dt_certificates = 0, hull_certificates = 0;
  double hull_seconds = 0, dt_seconds = 0;
  double ratio() const { return double(dt_flips) / double(std::max<long long>(1, hull_events)); }
  double raw_ratio() const { return double(dt_events) / double(std::max<long long>(1, hull_events)); }
};

// The thesis's Fig. 2.3: n, CGAL Kinetic Delaunay events, our (the thesis's) kinetic hull events.
constexpr int kThesis[6][3] = {{22, 357, 71}, {49, 1501, 151}, {73, 2374, 218}, {109, 4662, 316}, {163, 7842, 380}, {244, 15309, 513}};

void run_one(Row& row, int n, std::uint64_t seed, long long check_every, const Dyadic& until) {
  std::mt19937_64 rng(seed);
  auto pts = kmr::kinetic::random_linear_trajectories<3>(static_cast<std::size_t>(n), rng, {20, 8});
  // The kinetic hull, judged every K-th batch by the exact static algorithm just before now.
  kmr::kinetic::MotionSimulator hs(10, until);
  auto t0 = std::chrono::steady_clock::now();
  kmr::hull::KineticHull kh(pts, hs);
  long long hb = 0;
  auto previous = kh.facets();
  kh.run_until(until, [&] {
    auto now_facets = kh.facets();
    if (now_facets != previous) ++row.hull_output_changes, previous = std::move(now_facets);
    if (std::getenv("FIG23_TIMES")) std::fprintf(stderr, "H %g %lld\n", hs.now().to_double(), hs.counters().events);
    if (check_every > 0 && ++hb % check_every == 0) {
      ++row.checks;
      if (kh.facets() != kmr::hull::static_hull_before(kh.points(), hs.now())) {
        ++row.check_failures;
        std::fprintf(stderr, "n = %d seed %llu: kinetic hull differs from the static hull at batch %lld\n", n,
                     static_cast<unsigned long long>(seed), hb);
      }
    }
  });
  row.hull_seconds += since(t0);
  row.hull_events += hs.counters().events;
  row.hull_batches += hs.counters().batches;
  row.hull_certificates += static_cast<long long>(kh.live_certificates());
  // The kinetic Delaunay on the same motions, its gaps between batches judged by CGAL.
  kmr::kinetic::MotionSimulator ds(10, until);
  const Dyadic delta = Dyadic::pow2(-10);
  auto t1 = std::chrono::steady_clock::now();
  kmr::bench::KineticDelaunay kd(pts, ds);
  row.dt_certificates += static_cast<long long>(kd.live_certificates());
  long long db = 0;
  auto judge = [&](const std::string& e) {
    ++row.checks;
    if (e.empty()) return;
    ++row.check_failures;
    std::fprintf(stderr, "n = %d seed %llu: kinetic Delaunay before batch %lld: %s\n", n, static_cast<unsigned long long>(seed), db,
                 e.c_str());
  };
  for (;;) {
    const Dyadic before = ds.now();
    auto b = ds.next_batch(until);
    if (!b) break;
    if (check_every > 0 && ++db % check_every == 0) judge(kd.check_gap(before, ds.now() - delta));
    kd.update(*b);
    if (std::getenv("FIG23_TIMES")) std::fprintf(stderr, "D %g %lld\n", ds.now().to_double(), kd.counters().flips);
  }
  if (check_every > 0) judge(kd.check_gap(ds.now(), until));
  row.dt_seconds += since(t1);
  const auto& c = kd.counters();
  row.dt_events += c.events, row.dt_flips += c.flips, row.dt_batches += c.batches;
  row.rebuilds += c.rebuilds, row.retries += c.retries;
  // Both structures end with the same hull.
  ++row.checks;
  if (kd.hull_vertices() != kh.vertices()) {
    ++row.check_failures;
    std::fprintf(stderr, "n = %d seed %llu: hull vertices of the Delaunay and of the kinetic hull differ at the end\n", n,
                 static_cast<unsigned long long>(seed));
  }
  ++row.runs;
}

void write_audit_json(const std::string& path, const std::vector<Row>& rows, const std::string& replay) {
  namespace au = kmr::audit;
  au::Result r;
  for (const Row& w : rows) r.seconds += w.hull_seconds + w.dt_seconds;
  r.claim = "F2.3-events-vs-kinetic-delaunay";
  r.title = "events: kinetic hull vs kinetic 3D Delaunay on the same motions (bench/hull/fig23_bench)";
  r.replay = replay;
  long long checks = 0, failures = 0;
  for (const Row& w : rows) checks += w.checks, failures += w.check_failures;
  r.verdict.pass = failures == 0 && !rows.empty();
  r.verdict.summary = "§2.4 motions (20/8 bits, δ = 2^-10, until 2^27), " + std::to_string(rows.empty() ? 0 : rows[0].runs) +
                      " run(s) per n; Delaunay events = flips (distinct point sets among a batch's failed certificates); " +
                      std::to_string(checks) + " checks (static hull, CGAL between batches, final hulls), " +
                      std::to_string(failures) + " failed";
  kmr::svg::Series hull{"kinetic hull events (kmr)", {}}, dt{"kinetic Delaunay flips (CGAL rebuild baseline)", {}},
      th_hull{"thesis: kinetic hull", {}}, th_dt{"thesis: CGAL Kinetic Delaunay", {}}, tenth{"target: Delaunay / 10", {}},
      changes{"kinetic hull output changes (batches that change the facets)", {}};
  for (const Row& w : rows) {
    const std::string n = "n=" + std::to_string(w.n);
    r.verdict.figure(n + " hull events", au::fmt(double(w.hull_events) / w.runs));
    r.verdict.figure(n + " Delaunay flips", au::fmt(double(w.dt_flips) / w.runs));
    r.verdict.figure(n + " Delaunay certificate failures", au::fmt(double(w.dt_events) / w.runs));
    r.verdict.figure(n + " flips / hull events", au::fmt(w.ratio()));
    r.verdict.figure(n + " hull output changes", au::fmt(double(w.hull_output_changes) / w.runs));
    r.verdict.figure(n + " flips / hull output changes", au::fmt(double(w.dt_flips) / double(std::max<long long>(1, w.hull_output_changes))));
    changes.points.push_back({double(w.n), double(w.hull_output_changes) / w.runs});
    hull.points.push_back({double(w.n), double(w.hull_events) / w.runs});
    dt.points.push_back({double(w.n), double(w.dt_flips) / w.runs});
    tenth.points.push_back({double(w.n), double(w.dt_flips) / w.runs / 10});
  }
  for (const auto& t : kThesis) th_hull.points.push_back({double(t[0]), double(t[2])}), th_dt.points.push_back({double(t[0]), double(t[1])});
  const Row* last = rows.empty() ? nullptr : &rows.back();
  r.verdict.set_target("kinetic Delaunay flips ÷ kinetic hull events ≥ 10 at the largest n run (issue 9; n = 244 by default)",
                       last && last->ratio() >= 10);
  r.verdict.thesis = "Fig. 2.3: CGAL 357 / 1501 / 2374 / 4662 / 7842 / 15309 events vs the kinetic hull's 71 / 151 / 218 / 316 / 380 / 513 "
                     "at n = 22 / 49 / 73 / 109 / 163 / 244 (5.0x ... 29.8x)";
  kmr::svg::Plot p;
  p.title = "F2.3: events until the queue is empty, kinetic hull vs kinetic Delaunay";
  p.x = kmr::svg::linear_axis("n", "points");
  p.y = kmr::svg::log_axis("events");
  p.series = {hull, changes, dt, th_hull, th_dt};
  p.bounds = {tenth};
  r.verdict.plot(std::move(p));
  std::ofstream out(path);
  au::write_json({r}, out);
  if (!out) {
    std::fprintf(stderr, "cannot write --audit-json file '%s'\n", path.c_str());
    std::exit(2);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes{22, 49, 73, 109, 163, 244};
  int seeds = 1, until_log2 = 27;
  long long check_every = 10;
  std::string audit_json;
  std::string replay = "build/bin/fig23_bench";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      replay += " " + a + " " + argv[i + 1];
      return argv[++i];
    };
    try {
      if (a == "--n") {
        sizes.clear();
        std::stringstream ss(value());
        for (std::string w; std::getline(ss, w, ',');) sizes.push_back(std::stoi(w));
      } else if (a == "--seeds") {
        seeds = std::stoi(value());
      } else if (a == "--check-every") {
        check_every = std::stoll(value());
      } else if (a == "--until-log2") {
        until_log2 = std::stoi(value());
      } else if (a == "--audit-json") {
        audit_json = value();
      } else {
        throw std::invalid_argument(a);
      }
    } catch (const std::exception&) {
      std::fprintf(stderr, "usage: fig23_bench [--n 22,49,73,109,163,244] [--seeds S] [--check-every K] [--until-log2 E] [--audit-json FILE]\n");
      return 2;
    }
  }
  for (int n : sizes)
    if (n < 5) {
      std::fprintf(stderr, "--n: every size must be at least 5 (got %d)\n", n);
      return 2;
    }
  if (seeds < 1 || check_every < 0 || until_log2 < 0 || until_log2 > 40) {
    std::fprintf(stderr, "--seeds >= 1, --check-every >= 0, 0 <= --until-log2 <= 40\n");
    return 2;
  }
  const Dyadic until = Dyadic::pow2(until_log2);
  std::vector<Row> rows;
  for (int n : sizes) {
    Row row;
    row.n = n;
    for (int s = 0; s < seeds; ++s) run_one(row, n, 2012 + 1000 * static_cast<std::uint64_t>(s) + static_cast<std::uint64_t>(n), check_every, until);
    std::printf(
        "{\"n\": %d, \"runs\": %d, \"hull_events\": %lld, \"hull_batches\": %lld, \"hull_output_changes\": %lld, \"delaunay_flips\": %lld, "
        "\"delaunay_certificate_failures\": %lld, \"delaunay_batches\": %lld, \"flips_per_hull_event\": %.3g, "
        "\"failures_per_hull_event\": %.3g, \"rebuilds\": %lld, \"retries\": %lld, \"initial_delaunay_certificates\": %lld, "
        "\"final_hull_certificates\": %lld, \"checks\": %lld, \"check_failures\": %lld, \"hull_seconds\": %.3g, \"delaunay_seconds\": %.3g}\n",
        n, row.runs, row.hull_events, row.hull_batches, row.hull_output_changes, row.dt_flips, row.dt_events, row.dt_batches, row.ratio(), row.raw_ratio(),
        row.rebuilds, row.retries, row.dt_certificates, row.hull_certificates, row.checks, row.check_failures, row.hull_seconds,
        row.dt_seconds);
    std::fflush(stdout);
    rows.push_back(row);
  }
  if (!audit_json.empty()) write_audit_json(audit_json, rows, replay + "  (then kmr audit --include FILE --report DIR)");
  for (const Row& w : rows)
    if (w.check_failures) return 1;
  return 0;
}
