// The kinetic hull end to end (§2.4): n moving points with §2.4's motions (Bℓ = 20, Bv = 8 bits,
// δ = 2^-10), the initial run, then batches until E events, judged at sampled batches (the exact
// static algorithm just before now and the hull certificate; optionally a from-scratch
// self-adjusting run). Prints one JSON line per size with the times, and the Fig. 2.4 and 2.6
// ratios against the best of three warm static runs (initial_over_static, static_over_event; and
// static_over_event_with_next_batch, where an event also pays its share of the simulator's
// next_batch: the queue and the lazily isolated failure intervals, next_batch_seconds).
// Usage: kinetic_hull_bench [--n 1000,10000] [--events E] [--check-every K] [--scratch]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "hull/hull.hpp"
#include "hull/hull_at_time.hpp"
#include "hull/kinetic_hull.hpp"
#include "kinetic/trajectory.hpp"

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  using namespace kmr;
  std::vector<int> sizes{10000};
  long long max_events = 200, check_every = 50;
  bool scratch = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--n" && i + 1 < argc) {
      sizes.clear();
      std::stringstream ss(argv[++i]);
      for (std::string w; std::getline(ss, w, ',');) sizes.push_back(std::stoi(w));
    } else if (a == "--events" && i + 1 < argc) {
      max_events = std::stoll(argv[++i]);
    } else if (a == "--check-every" && i + 1 < argc) {
      check_every = std::stoll(argv[++i]);
    } else if (a == "--scratch") {
      scratch = true;
    } else {
      std::cerr << "usage: kinetic_hull_bench [--n 1000,10000] [--events E] [--check-every K] [--scratch]\n";
      return 2;
    }
  }
  for (int n : sizes) {
    std::mt19937_64 rng(2012 + n);
    auto pts = kinetic::random_linear_trajectories<3>(static_cast<std::size_t>(n), rng, {20, 8});
    std::vector<hull::Point3d> start;
    for (const auto& q : pts)
      start.push_back({q[0].is_zero() ? 0.0 : q[0][0].convert_to<double>(), q[1].is_zero() ? 0.0 : q[1][0].convert_to<double>(),
                       q[2].is_zero() ? 0.0 : q[2][0].convert_to<double>()});
    auto s0 = std::chrono::steady_clock::now();
    hull::convex_hull(start);
    const double static_seconds = since(s0);
    double static_best = static_seconds;  // warm runs, best of 3 (the Fig. 2.4 / 2.6 denominators)
    for (int r = 0; r < 3; ++r) {
      auto s1 = std::chrono::steady_clock::now();
      hull::convex_hull(start);
      static_best = std::min(static_best, since(s1));
    }
    const exact::Dyadic until = exact::Dyadic::pow2(27);
    kinetic::MotionSimulator sim(10, until);
    auto t0 = std::chrono::steady_clock::now();
    hull::KineticHull kh(pts, sim);
    const double initial = since(t0);
    double propagation = 0, next_batch = 0, checking = 0;
    long long batches = 0, checks = 0, failures = 0;
    while (sim.counters().events < max_events) {
      auto t3 = std::chrono::steady_clock::now();
      auto b = sim.next_batch(until);
      next_batch += since(t3);
      if (!b) break;
      auto t1 = std::chrono::steady_clock::now();
      kh.update(*b);
      propagation += since(t1);
      if (++batches % check_every == 0) {
        auto t2 = std::chrono::steady_clock::now();
        auto f = kh.facets();
        bool ok = f == hull::static_hull_before(kh.points(), sim.now()) &&
                  hull::hull_certificate_failure(kh.points(), sim.now(), f).empty();
        if (scratch) ok = ok && hull::KineticHull(kh.points(), sim.now()).signature() == kh.signature();
        failures += !ok;
        ++checks;
        checking += since(t2);
      }
    }
    const auto& c = sim.counters();
    const double per_event = propagation / double(std::max<long long>(1, c.events));
    const double per_event_with_next = (propagation + next_batch) / double(std::max<long long>(1, c.events));
    std::cout << "{\"n\": " << n << ", \"static_seconds\": " << static_seconds << ", \"static_best_seconds\": " << static_best
              << ", \"initial_seconds\": " << initial << ", \"initial_over_static\": " << initial / static_best
              << ", \"static_over_event\": " << static_best / per_event
              << ", \"static_over_event_with_next_batch\": " << static_best / per_event_with_next
              << ", \"events\": " << c.events << ", \"batches\": " << batches << ", \"max_batch\": " << c.max_batch
              << ", \"propagation_seconds\": " << propagation << ", \"next_batch_seconds\": " << next_batch << ", \"seconds_per_event\": " << propagation / std::max<long long>(1, c.events)
              << ", \"checks\": " << checks << ", \"check_failures\": " << failures << ", \"check_seconds\": " << checking
              << ", \"now\": " << sim.now().to_decimal() << ", \"filter_searches\": " << c.poly_filter_decided
              << ", \"filter_fallbacks\": " << c.poly_filter_fallbacks << ", \"lazy_no_root\": " << c.lazy_no_root
              << ", \"lazy_deferred\": " << c.lazy_deferred << ", \"lazy_checkpoints_reached\": " << c.lazy_checkpoints_reached
              << ", \"live_certificates\": " << kh.live_certificates() << ", \"certificates_created\": " << kh.counters().certificates_created
              << "}" << std::endl;
    if (failures) return 1;
  }
  return 0;
}
