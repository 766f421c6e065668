// Chapter 3 claims (dynamic well-spaced point sets) for `kmr audit`. Each check names its claim
// ID of spec/claims.md; asymptotic claims are reported as bounded ratios over growing inputs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "audit/audit.hpp"
#include "wellspaced/generators.hpp"
#include "wellspaced/measure.hpp"
#include "wellspaced/well_spaced_set.hpp"

namespace kmr::audit {
namespace {

using namespace kmr::wellspaced;


template <std::size_t D>
bool same(const WellSpacedSet<D>& a, const WellSpacedSet<D>& b) {
  auto x = a.vertices(), y = b.vertices();
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i].x != y[i].x || x[i].is_steiner != y[i].is_steiner) return false;
  return a.canonical_graph() == b.canonical_graph();
}

// A base input of n uniform points plus one point at distance 2^-k from base[0] (spread ≈ 2^k).
std::vector<Point<2>> base_input(std::size_t n, std::uint64_t seed) {
  return gen::points<2>(gen::Kind::uniform, n, seed);
}
Point<2> close_to(const Point<2>& p, int k) {
  Point<2> q = p;
  q[0] += (p[0] < 0.5 ? 1 : -1) * std::ldexp(1.0, -k);
  return q;
}

Verdict t334(const Options& o) {
  Verdict v;
  int ok = 0, total = 0;
  std::size_t n2 = o.quick ? 25 : 80;
  for (auto k : {gen::Kind::uniform, gen::Kind::clustered, gen::Kind::grid, gen::Kind::close_pair, gen::Kind::boundary}) {
    auto in = gen::points<2>(k, n2, o.seed);
    WellSpacedSet<2> ws(in);
    std::vector<Point<2>> M;
    for (auto& x : ws.vertices()) M.push_back(x.x);
    ++total;
    ok += is_well_spaced<2>(M, ws.params().rho) && is_size_conforming<2>(in, M, ws.params().rho);
    v.figure(std::string("2D ") + gen::name(k) + " |M|/|N|", fmt(double(M.size()) / in.size()));
  }
  {
    auto in = gen::points<3>(gen::Kind::uniform, o.quick ? 8 : 20, o.seed);
    WellSpacedSet<3> ws(in);
    std::vector<Point<3>> M;
    for (auto& x : ws.vertices()) M.push_back(x.x);
    ++total;
    ok += is_well_spaced<3>(M, ws.params().rho) && is_size_conforming<3>(in, M, ws.params().rho);
    v.figure("3D uniform |M|/|N|", fmt(double(M.size()) / in.size()));
  }
  v.pass = ok == total;
  v.summary = std::to_string(ok) + "/" + std::to_string(total) +
              " outputs rho-well-spaced and size-conforming (exact brute force, rho = 1.5)";
  return v;
}

Verdict l342(const Options& o) {
  Verdict v;
  int steps = 0, ok = 0;
  for (auto k : {gen::Kind::uniform, gen::Kind::grid, gen::Kind::close_pair}) {
    auto pool = gen::points<2>(k, o.quick ? 14 : 30, o.seed + 1);
    std::vector<Point<2>> cur(pool.begin(), pool.begin() + pool.size() / 2);
    WellSpacedSet<2> ws(cur);
    std::mt19937_64 rng(o.seed);
    for (int s = 0; s < (o.quick ? 6 : 20); ++s) {
      const auto& p = pool[rng() % pool.size()];
      auto it = std::find(cur.begin(), cur.end(), p);
      if (it != cur.end() && cur.size() <= 2) continue;
      if (it != cur.end()) {
        ws.erase(p);
        cur.erase(it);
      } else {
        ws.insert(p);
        cur.push_back(p);
      }
      WellSpacedSet<2> fresh(cur);
      ++steps;
      ok += same<2>(ws, fresh);
    }
  }
  v.pass = ok == steps && steps > 0;
  v.summary = std::to_string(ok) + "/" + std::to_string(steps) +
              " updates: output equal and computation graph identical (canonical form) to from-scratch";
  return v;
}

Verdict t338(const Options& o) {
  Verdict v;
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{25, 50, 100} : std::vector<std::size_t>{100, 200, 400, 800};
  double first = 0, last = 0, firstf = 0, lastf = 0;
  for (std::size_t n : sizes) {
    WellSpacedSet<2> ws(gen::points<2>(gen::Kind::uniform, n, o.seed));
    const Stats& s = ws.stats();
    double mean = double(s.cv_squares_total) / s.cv_calls;
    if (n == sizes.front()) first = mean, firstf = double(s.steiner_per_fill_max);
    last = mean, lastf = double(s.steiner_per_fill_max);
    v.figure("n=" + std::to_string(n) + " squares/CV call mean,max; Steiner/fill max",
             fmt(mean) + ", " + std::to_string(s.cv_squares_max) + "; " + std::to_string(s.steiner_per_fill_max));
  }
  v.pass = last <= 2 * first && lastf <= 2 * std::max(1.0, firstf);
  v.summary = "2D uniform: squares read per clipped-Voronoi call and Steiner vertices per fill stay bounded as n grows (ratio last/first " +
              fmt(last / first) + ")";
  return v;
}

// Theorem 3.4.3 and 3.4.5: insert a point at distance 2^-k next to an input vertex.
Verdict t343(const Options& o, bool lower_bound) {
  Verdict v;
  std::vector<int> ks = o.quick ? std::vector<int>{10, 20, 30} : std::vector<int>{10, 20, 30, 40};
  auto base = base_input(o.quick ? 16 : 40, o.seed + 2);
  std::vector<double> per_log, steiner;
  for (int k : ks) {
    WellSpacedSet<2> ws(base);
    Point<2> q = close_to(base[0], k);
    auto a = ws.insert(q);
    auto b = ws.erase(q);
    double touched = 0.5 * double(a.touched() + b.touched());
    double changes = double(a.steiner_inserted + a.steiner_deleted);
    per_log.push_back(touched / k);
    steiner.push_back(changes);
    v.figure("Delta=2^" + std::to_string(k) + (lower_bound ? " Steiner changes on insert, /log2" : " ops per update, /log2"),
             lower_bound ? fmt(changes) + ", " + fmt(changes / k) : fmt(touched) + ", " + fmt(touched / k));
  }
  if (lower_bound) {
    v.pass = steiner.back() >= 1.5 * steiner.front();
    v.summary = "insert next to an input vertex (one gadget): Steiner changes grow with log2 Delta (Omega(log Delta))";
  } else {
    double mx = *std::max_element(per_log.begin(), per_log.end()), mn = *std::min_element(per_log.begin(), per_log.end());
    v.pass = mx <= 3 * mn;
    v.summary = "operations touched per update / log2 Delta bounded for Delta = 2^" + std::to_string(ks.front()) + "..2^" +
                std::to_string(ks.back()) + " (max/min " + fmt(mx / mn) + ")";
  }
  return v;
}

Verdict speed(const Options& o) {
  Verdict v;
  std::size_t n = o.quick ? 200 : 10000;
  int pairs = o.quick ? 5 : 20;
  auto pts = gen::points<2>(gen::Kind::uniform, n + pairs, o.seed + 3);
  std::vector<Point<2>> in(pts.begin(), pts.begin() + n);
  auto t0 = std::chrono::steady_clock::now();
  WellSpacedSet<2> ws(in);
  double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto u = sample_updates<2>(ws, std::vector<Point<2>>(pts.begin() + n, pts.end()));
  double upd = u.mean_seconds;
  v.figure("n", std::to_string(n));
  v.figure("from-scratch seconds", fmt(build));
  v.figure("mean update seconds", fmt(upd));
  v.figure("speed ratio (scratch/update)", fmt(build / upd));
  v.figure("mean operations touched per update", fmt(u.mean_touched));
  v.pass = build / upd > 1;
  v.summary = "2D uniform: one insertion/deletion with PropagateWS vs StableWS from scratch (target >= 1000x at n = 1e5)";
  return v;
}

}  // namespace

std::vector<Check> wellspaced_checks() {
  return {
      {"T3.3.4", "StableWS output is rho-well-spaced and size-conforming (2D, 3D)", t334},
      {"L3.4.2", "PropagateWS output and computation graph equal from-scratch after random updates", l342},
      {"T3.3.8", "O(1) squares per clipped-Voronoi call and Steiner vertices per fill (Lemma 3.3.9)", t338},
      {"T3.4.3", "O(log Delta) operations per dynamic update", [](const Options& o) { return t343(o, false); }},
      {"T3.4.5", "Omega(log Delta) Steiner changes for an insertion next to a vertex", [](const Options& o) { return t343(o, true); }},
      {"T3.4.3-speed", "update vs from-scratch time ratio", speed},
  };
}

}  // namespace kmr::audit
