// Chapter 3 claims (dynamic well-spaced point sets) for `kmr audit`. Each check names its claim
// ID of spec/claims.md; asymptotic claims are reported as bounded ratios over growing inputs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "audit/audit.hpp"
#include "wellspaced/generators.hpp"
#include "wellspaced/measure.hpp"
#include "wellspaced/well_spaced_set.hpp"
#include "wsjudge/brute_force.hpp"

namespace kmr::audit {
namespace {

using namespace kmr::wellspaced;


template <std::size_t D>
bool same(const WellSpacedSet<D>& a, const WellSpacedSet<D>& b) {
  auto x = a.vertices(), y = b.vertices();
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i].exact == y[i].exact) || x[i].is_steiner != y[i].is_steiner) return false;
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

// The output judged by the exact brute force of src/wsjudge: through its doubles when every vertex
// is one (the audit's inputs; `measured` may swap them for the fail-verdict tests), else through its
// exact text (vertices finer than a double, issue 11 §1), read back by the judge's own reader.
template <std::size_t D>
bool judged_ok(const Options& o, const char* what, const std::vector<Point<D>>& in, const WellSpacedSet<D>& ws,
               std::size_t& size, int& fine) {
  std::vector<Point<D>> M;
  std::vector<kmr::wsjudge::ExactPoint<D>> X;
  bool all = true;
  for (auto& x : ws.vertices()) {
    M.push_back(x.x);
    kmr::wsjudge::ExactPoint<D> e;
    for (std::size_t i = 0; i < D; ++i) e[i] = kmr::wsjudge::read_hex_float(x.exact.text(i));
    X.push_back(e);
    if (!x.exact.is_double()) ++fine, all = false;
  }
  const double rho = ws.params().rho;
  if (!all) {
    size = X.size();
    return kmr::wsjudge::is_well_spaced<D>(X, rho) && kmr::wsjudge::is_size_conforming<D>(in, X, rho);
  }
  M = measured(o, what, M);
  size = M.size();
  return kmr::wsjudge::is_well_spaced<D>(M, rho) && kmr::wsjudge::is_size_conforming<D>(in, M, rho);
}

Verdict t334(const Options& o) {
  Verdict v;
  int ok = 0, total = 0, fine = 0;
  std::size_t n2 = o.quick ? 25 : 80, size = 0;
  for (auto k : {gen::Kind::uniform, gen::Kind::clustered, gen::Kind::grid, gen::Kind::close_pair, gen::Kind::boundary}) {
    auto in = gen::points<2>(k, n2, o.seed);
    WellSpacedSet<2> ws(in);
    ++total;
    ok += judged_ok<2>(o, "T3.3.4 output 2D", in, ws, size, fine);
    v.figure(std::string("2D ") + gen::name(k) + " |M|/|N|", fmt(double(size) / in.size()));
  }
  {  // two points 1 ulp apart (issue 11 §1): some Steiner vertices are finer than doubles
    const std::vector<Point<2>> in = {{0.5, 0.5}, {std::nextafter(0.5, 1.0), 0.5}};
    Params p;
    p.rho = 4;  // keeps |M| (and the exact judge's time) small
    p.beta = 8;
    WellSpacedSet<2> ws(in, p);
    ++total;
    ok += judged_ok<2>(o, "T3.3.4 output 2D 1-ulp pair", in, ws, size, fine);
    v.figure("2D 1-ulp pair (rho = 4) |M|", std::to_string(size));
  }
  {
    auto in = gen::points<3>(gen::Kind::uniform, o.quick ? 8 : 20, o.seed);
    WellSpacedSet<3> ws(in);
    ++total;
    ok += judged_ok<3>(o, "T3.3.4 output 3D", in, ws, size, fine);
    v.figure("3D uniform |M|/|N|", fmt(double(size) / in.size()));
  }
  v.pass = ok == total;
  v.summary = std::to_string(ok) + "/" + std::to_string(total) +
              " outputs rho-well-spaced and size-conforming (exact brute force, rho = 1.5; the 1-ulp pair at rho = 4)";
  if (fine > 0) v.summary += "; " + std::to_string(fine) + " vertices finer than doubles, judged exactly";
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
  svg::Series mean_s{"mean squares per call", {}}, max_s{"max squares per call", {}}, fill_s{"max Steiner per fill", {}};
  for (std::size_t n : sizes) {
    WellSpacedSet<2> ws(gen::points<2>(gen::Kind::uniform, n, o.seed));
    const Stats& s = ws.stats();
    double mean = double(s.cv_squares_total) / s.cv_calls;
    if (n == sizes.front()) first = mean, firstf = double(s.steiner_per_fill_max);
    last = mean, lastf = double(s.steiner_per_fill_max);
    mean_s.points.push_back({double(n), mean});
    max_s.points.push_back({double(n), double(s.cv_squares_max)});
    fill_s.points.push_back({double(n), double(s.steiner_per_fill_max)});
    v.figure("n=" + std::to_string(n) + " squares/CV call mean,max; Steiner/fill max",
             fmt(mean) + ", " + std::to_string(s.cv_squares_max) + "; " + std::to_string(s.steiner_per_fill_max));
    // the two-tier filter (spec/wellspaced.md): share of calls the interval tier could not decide
    v.figure("n=" + std::to_string(n) + " exact fallbacks / (CV calls + fills)",
             fmt(double(s.exact_fallbacks) / double(s.cv_calls + s.fills)));
  }
  last = measured(o, "T3.3.8 squares per call at the largest n", last);  // the judged figures (audit.hpp's seam)
  lastf = measured(o, "T3.3.8 Steiner per fill at the largest n", lastf);
  v.pass = last <= 2 * first && lastf <= 2 * std::max(1.0, firstf);
  svg::Plot p;
  p.title = "T3.3.8: squares read per clipped-Voronoi call (2D uniform)";
  p.x = svg::linear_axis("n", "input points");
  p.y = svg::linear_axis("per call or fill", "squares, vertices");
  p.series = {mean_s, max_s, fill_s};
  p.bounds.push_back(svg::constant_bound("pass bound: 2 x mean at first n", 2 * first, double(sizes.front()), double(sizes.back())));
  v.plot(std::move(p));
  v.summary = std::string(v.pass ? "" : "squares per call or Steiner per fill more than doubled from the smallest to the largest n; ") +
              "2D uniform: squares read per clipped-Voronoi call and Steiner vertices per fill stay bounded as n grows (ratio last/first " +
              fmt(last / first) + ", Steiner per fill " + fmt(firstf) + " -> " + fmt(lastf) + ")";
  return v;
}

// Lemma 3.3.6: an operation at rank r on v has NN_∞(v) ∈ Θ(ρ^r). The exact upper bound
// NN_∞(v) < ρ^{r+1} of scheduled operations is asserted; the Θ sides are reported as min NN_∞/ρ^r
// and max NN_∞/ρ^r, both over all operations (scheduled ones stay below ρ by the exact bound, so the
// max is in practice an input dispatch's, whose rank comes from v's square, Lemma 3.1.5), and each may
// move by at most 2x from the smallest to the largest n.
template <std::size_t D>
bool l336_series(const Options& o, Verdict& v, gen::Kind kind, const std::vector<std::size_t>& sizes, std::size_t& above,
                 svg::Plot& plot) {
  std::string name = std::to_string(D) + "D " + gen::name(kind);
  std::vector<double> lo, hi;  // per n: min NN_inf/rho^r over all operations, max over all (input dispatches included)
  std::size_t series_above = 0;
  for (std::size_t n : sizes) {
    WellSpacedSet<D> ws(gen::points<D>(kind, n, o.seed));
    RankRatios R = rank_ratios<D>(ws);
    series_above += R.above;
    lo.push_back(std::min(R.lo, R.in_lo));
    hi.push_back(std::max(R.hi, R.in_hi));
    v.figure(name + " n=" + std::to_string(n) + " NN_inf/rho^r scheduled min,max; input dispatch min,max",
             fmt(R.lo) + ", " + fmt(R.hi) + "; " + fmt(R.in_lo) + ", " + fmt(R.in_hi));
  }
  // The judged figures (audit.hpp's seam).
  above += measured(o, "L3.3.6 operations with NN_inf >= rho^(r+1)", series_above);
  lo = measured(o, "L3.3.6 min NN_inf/rho^r per n", lo);
  hi = measured(o, "L3.3.6 max NN_inf/rho^r per n", hi);
  svg::Series lo_s{name + " min", {}}, hi_s{name + " max", {}};
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    lo_s.points.push_back({double(sizes[i]), lo[i]});
    hi_s.points.push_back({double(sizes[i]), hi[i]});
  }
  plot.series.push_back(lo_s);
  plot.series.push_back(hi_s);
  return 2 * lo.back() >= lo.front() && hi.back() <= 2 * hi.front();
}
Verdict l336(const Options& o) {
  Verdict v;
  std::size_t above = 0;
  svg::Plot plot;
  plot.title = "L3.3.6: min and max of NN_inf(v) / rho^r over all operations";
  plot.x = svg::log_axis("n", "input points");
  plot.y = svg::log_axis("NN_inf(v) / rho^r");
  std::vector<std::size_t> sizes2 = o.quick ? std::vector<std::size_t>{50, 100, 200} : std::vector<std::size_t>{100, 300, 1000};
  bool ok = l336_series<2>(o, v, gen::Kind::uniform, sizes2, above, plot);
  ok &= l336_series<2>(o, v, gen::Kind::clustered, sizes2, above, plot);
  ok &= l336_series<3>(o, v, gen::Kind::uniform, o.quick ? std::vector<std::size_t>{6, 12} : std::vector<std::size_t>{10, 20, 40}, above, plot);
  v.plot(std::move(plot));
  v.pass = ok && above == 0;
  v.summary = std::string(above != 0 ? "an operation's NN_inf(v) reached rho^(r+1); " : "") +
              (ok ? "" : "min or max of NN_inf/rho^r moved more than 2x from the smallest to the largest n; ") +
              std::to_string(above) +
              " scheduled operations with NN_inf(v) >= rho^(r+1) (exact); min and max of NN_inf/rho^r move <= 2x from smallest to largest n (2D uniform, clustered; 3D uniform)";
  return v;
}

// Lemma 3.3.15: affected vertices (operations whose canonical-graph lines differ before/after an
// update) lie within O(NN(v)) of v̂: max |v v̂|/NN(v) stays bounded as Δ grows (≤ 2x its value at the
// smallest Δ, for each n) and as n grows (the smallest-Δ values move ≤ 2x from the smallest n).
Verdict l3315(const Options& o) {
  Verdict v;
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{16, 64} : std::vector<std::size_t>{16, 64, 256};
  std::vector<int> ks = o.quick ? std::vector<int>{10, 30} : std::vector<int>{10, 20, 30, 40};
  double first = 0, worst = 0;
  bool ok = true;
  svg::Plot plot;
  plot.title = "L3.3.15: affected vertices' distance to the updated point, in NN(v)";
  plot.x = svg::linear_axis("log2 Delta", "bits of spread");
  plot.y = svg::linear_axis("max |v vhat| / NN(v) over affected v");
  for (std::size_t n : sizes) {
    auto base = base_input(n, o.seed + 4);
    double at_small_delta = 0;
    svg::Series series{"n=" + std::to_string(n), {}};
    for (int k : ks) {
      WellSpacedSet<2> ws(base);
      Point<2> q = close_to(base[0], k);
      auto G = ws.computation_graph();
      auto M = ws.vertices();
      ws.insert(q);
      auto G2 = ws.computation_graph();
      auto M2 = ws.vertices();
      ws.erase(q);
      AffectedRatio ins = affected_ratio<2>(G, M, G2, M2, q);
      AffectedRatio del = affected_ratio<2>(G2, M2, ws.computation_graph(), ws.vertices(), q);
      double r = measured(o, "L3.3.15 max |v vhat|/NN(v)", std::max(ins.max_ratio, del.max_ratio));  // audit.hpp's seam
      if (k == ks.front()) at_small_delta = r;
      if (first == 0) first = r;
      ok &= r > 0 && r <= 2 * at_small_delta;
      worst = std::max(worst, r);
      series.points.push_back({double(k), r});
      v.figure("n=" + std::to_string(n) + " Delta=2^" + std::to_string(k) + " max |v vhat|/NN(v) insert, delete; affected vertices",
               fmt(ins.max_ratio) + ", " + fmt(del.max_ratio) + "; " + std::to_string(ins.vertices) + ", " + std::to_string(del.vertices));
    }
    ok &= at_small_delta <= 2 * first;
    plot.bounds.push_back(svg::constant_bound("pass bound n=" + std::to_string(n) + ": 2 x smallest Delta", 2 * at_small_delta,
                                              double(ks.front()), double(ks.back())));
    plot.series.push_back(std::move(series));
  }
  v.plot(std::move(plot));
  v.pass = ok;
  v.summary = std::string(ok ? "" : "affected vertices farther than 2x the smallest Delta's (or smallest n's) ratio, or none; ") +
              "insert/delete a point 2^-k from an input vertex: max |v vhat|/NN(v) over affected vertices in [" + fmt(first) + ", " +
              fmt(worst) + "], within 2x of the smallest Delta for each n and of the smallest n";
  return v;
}

// Theorem 3.3.11: StableWS runs in O(n log Δ): executed operations ÷ (n·log2 Δ) must not grow (last ≤
// 1.5 × first in each series); seconds ÷ (n·log2 Δ) are reported.
Verdict t3311(const Options& o) {
  Verdict v;
  bool ok = true;
  double worst = 0;
  svg::Series by_n{"ops / (n log2 Delta)", {}}, by_delta{"ops / (n log2 Delta)", {}};
  auto run = [&](const std::string& what, const std::vector<Point<2>>& in, double& ratio) {
    auto t0 = std::chrono::steady_clock::now();
    WellSpacedSet<2> ws(in);
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double nlog = double(in.size()) * log2_spread<2>(in);
    ratio = measured(o, "T3.3.11 ops/(n lg Δ)", double(ws.stats().dispatches + ws.stats().fills) / nlog);  // audit.hpp's seam
    worst = std::max(worst, ratio);
    v.figure(what + " log2 Delta; ops/(n log2 Delta); us/(n log2 Delta)", fmt(log2_spread<2>(in)) + "; " + fmt(ratio) + "; " + fmt(1e6 * sec / nlog));
  };
  double first = 0, r = 0;
  for (std::size_t n : o.quick ? std::vector<std::size_t>{50, 100, 200} : std::vector<std::size_t>{250, 500, 1000, 2000}) {
    run("uniform n=" + std::to_string(n), gen::points<2>(gen::Kind::uniform, n, o.seed + 5), r);
    if (first == 0) first = r;
    by_n.points.push_back({double(n), r});
  }
  ok &= r <= 1.5 * first;
  {
    svg::Plot p;
    p.title = "T3.3.11: StableWS operations per n log2 Delta, growing n (2D uniform)";
    p.x = svg::linear_axis("n", "input points");
    p.y = svg::linear_axis("executed operations / (n log2 Delta)");
    p.series = {by_n};
    p.bounds.push_back(svg::constant_bound("pass bound: 1.5 x first", 1.5 * first, by_n.points.front().x, by_n.points.back().x));
    v.plot(std::move(p));
  }
  first = 0;
  auto base = base_input(o.quick ? 50 : 200, o.seed + 5);
  for (int k : {10, 20, 30, 40}) {
    auto in = base;
    in.push_back(close_to(base[0], k));
    run("uniform n=" + std::to_string(base.size()) + " + pair at 2^-" + std::to_string(k), in, r);
    if (first == 0) first = r;
    by_delta.points.push_back({log2_spread<2>(in), r});
  }
  ok &= r <= 1.5 * first;
  {
    svg::Plot p;
    p.title = "T3.3.11: operations per n log2 Delta, growing Delta (n = " + std::to_string(base.size()) + " + a close pair)";
    p.x = svg::linear_axis("log2 Delta", "bits of spread");
    p.y = svg::linear_axis("executed operations / (n log2 Delta)");
    p.series = {by_delta};
    p.bounds.push_back(svg::constant_bound("pass bound: 1.5 x first", 1.5 * first, by_delta.points.front().x, by_delta.points.back().x));
    v.plot(std::move(p));
  }
  v.pass = ok;
  v.summary = std::string(ok ? "" : "operations / (n log2 Delta) grew by more than 1.5x within a series; ") +
              "2D: executed operations / (n log2 Delta) (max " + fmt(worst) + ") do not grow with n nor with Delta (last <= 1.5 x first per series)";
  return v;
}

// Theorem 3.4.5: the tiled gadgets of §3.4.2 (gen::gadget_tiling): n dynamic insertions, one per
// gadget, insert Ω(n log Δ) Steiner vertices. Reports inserted ÷ (n·log2 Δ), Δ the spread of the final
// input. Passes when the ratio stays ≥ c0 = 1/(2 log2(2ρ)) (half the density along one segment in
// Lemma 3.4.4's proof), does not fall as Δ grows (for each n; O(n) changes would fall like 1/log Δ),
// and at the common largest Δ falls ≤ 2x from n = 1 to the largest n.
Verdict t345(const Options& o) {
  Verdict v;
  // (tiles_log2, delta_log2): n = 4^tiles_log2 gadgets; the 64-gadget tiling only up to 2^-14 (time)
  std::vector<std::pair<int, std::vector<int>>> runs =
      o.quick ? std::vector<std::pair<int, std::vector<int>>>{{0, {10, 15}}, {1, {10, 15}}, {2, {10, 15}}}
              : std::vector<std::pair<int, std::vector<int>>>{{0, {10, 14, 22}}, {1, {10, 14, 22}}, {2, {10, 14, 22}}, {3, {10, 14}}};
  const int common = o.quick ? 15 : 14;
  double lo = std::numeric_limits<double>::infinity(), hi = 0, c0 = 0, single = 0, largest = 0;
  bool ok = true;
  svg::Plot plot;
  plot.title = "T3.4.5: Steiner vertices inserted per n log2 Delta, n gadget insertions";
  plot.x = svg::linear_axis("log2 Delta", "bits of spread");
  plot.y = svg::linear_axis("Steiner inserted / (n log2 Delta)");
  double lg_lo = std::numeric_limits<double>::infinity(), lg_hi = 0;
  for (const auto& [j, ks] : runs) {
    double at_small = 0, ratio = 0;
    svg::Series series{"n=" + std::to_string(1 << (2 * j)) + " gadgets", {}};
    for (int k : ks) {
      auto G = gen::gadget_tiling<2>(j, k);
      WellSpacedSet<2> ws(G.input);
      c0 = 1 / (2 * std::log2(2 * ws.params().rho));
      std::uint64_t inserted = 0, deleted = 0;
      for (const auto& x : G.dynamic) {
        UpdateStats u = ws.insert(x);
        inserted += u.steiner_inserted;
        deleted += u.steiner_deleted;
      }
      std::vector<Point<2>> all = G.input;
      all.insert(all.end(), G.dynamic.begin(), G.dynamic.end());
      double n = double(G.dynamic.size()), lg = log2_spread<2>(all);
      ratio = measured(o, "T3.4.5 inserted/(n lg Δ)", double(inserted) / (n * lg));  // audit.hpp's seam
      if (k == ks.front()) at_small = ratio;
      if (k == common) (j == 0 ? single : largest) = ratio;
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
      series.points.push_back({lg, ratio});
      lg_lo = std::min(lg_lo, lg), lg_hi = std::max(lg_hi, lg);
      v.figure("n=" + std::to_string(G.dynamic.size()) + " gadgets (" + std::to_string(G.input.size()) + " input) delta=2^-" + std::to_string(k) +
                   " log2 Delta; Steiner inserted, deleted; inserted/(n log2 Delta)",
               fmt(lg) + "; " + std::to_string(inserted) + ", " + std::to_string(deleted) + "; " + fmt(ratio));
    }
    ok &= ratio >= at_small;
    plot.series.push_back(std::move(series));
  }
  plot.bounds.push_back(svg::constant_bound("c0 = 1/(2 log2 2rho) (pass: all above)", c0, lg_lo, lg_hi));
  v.plot(std::move(plot));
  v.pass = ok && lo >= c0 && 2 * largest >= single;
  if (!ok) v.summary = "inserted / (n log2 Delta) fell as Delta grew; ";
  if (!(lo >= c0)) v.summary += "inserted / (n log2 Delta) below c0; ";
  if (!(2 * largest >= single)) v.summary += "the largest n's ratio is below half of n = 1's; ";
  v.summary += "tiled gadgets, one dynamic insertion per gadget: Steiner vertices inserted / (n log2 Delta) in [" + fmt(lo) + ", " + fmt(hi) +
              "] >= c0 = 1/(2 log2(2 rho)) = " + fmt(c0) + "; not falling as Delta grows; at Delta = 2^" + std::to_string(common) + " n = 1: " +
              fmt(single) + ", largest n: " + fmt(largest);
  return v;
}

// Theorem 3.4.3 (and the single gadget of Lemma 3.4.4): insert a point at distance 2^-k next to an input vertex.
Verdict t343(const Options& o, bool lower_bound) {
  Verdict v;
  std::vector<int> ks = o.quick ? std::vector<int>{10, 20, 30} : std::vector<int>{10, 20, 30, 40};
  auto base = base_input(o.quick ? 16 : 40, o.seed + 2);
  std::vector<double> per_log, steiner;
  svg::Series series{lower_bound ? "Steiner changes on insert" : "operations touched per update (mean of insert, erase)", {}};
  for (int k : ks) {
    WellSpacedSet<2> ws(base);
    Point<2> q = close_to(base[0], k);
    auto a = ws.insert(q);
    auto b = ws.erase(q);
    double touched = 0.5 * double(a.touched() + b.touched());
    double changes = double(a.steiner_inserted + a.steiner_deleted);
    per_log.push_back(touched / k);
    steiner.push_back(changes);
    series.points.push_back({double(k), lower_bound ? changes : touched});
    v.figure("Delta=2^" + std::to_string(k) + (lower_bound ? " Steiner changes on insert, /log2" : " ops per update, /log2"),
             lower_bound ? fmt(changes) + ", " + fmt(changes / k) : fmt(touched) + ", " + fmt(touched / k));
  }
  if (lower_bound) steiner = measured(o, "L3.4.4 Steiner changes", steiner);  // the judged figures (audit.hpp's seam)
  else per_log = measured(o, "T3.4.3 ops per update ÷ lg Δ", per_log);
  svg::Plot p;
  p.title = lower_bound ? "L3.4.4: Steiner changes for one insertion next to a vertex" : "T3.4.3: operations per dynamic update";
  p.x = svg::linear_axis("log2 Delta", "bits of spread");
  p.y = svg::linear_axis(lower_bound ? "Steiner vertices inserted + deleted" : "operations touched per update");
  p.series = {series};
  if (auto b = svg::proportional_bound(lower_bound ? "c log2 Delta, c = min (lower bound)" : "c log2 Delta, c = max (upper bound)",
                                       series, !lower_bound))
    p.bounds.push_back(*b);
  if (!lower_bound)
    if (auto b = svg::proportional_bound("c log2 Delta, c = min", series, false)) p.bounds.push_back(*b);
  v.plot(std::move(p));
  if (lower_bound) {
    v.pass = steiner.back() >= 1.5 * steiner.front();
    v.summary = std::string(v.pass ? "" : "Steiner changes grew by less than 1.5x from the smallest to the largest Delta; ") +
                "insert next to an input vertex (one gadget): Steiner changes grow with log2 Delta (Omega(log Delta))";
  } else {
    double mx = *std::max_element(per_log.begin(), per_log.end()), mn = *std::min_element(per_log.begin(), per_log.end());
    v.pass = mx <= 3 * mn;
    v.summary = std::string(v.pass ? "" : "operations touched per update / log2 Delta vary by more than 3x; ") +
                "operations touched per update / log2 Delta bounded for Delta = 2^" + std::to_string(ks.front()) + "..2^" +
                std::to_string(ks.back()) + " (max/min " + fmt(mx / mn) + ")";
  }
  return v;
}

// Issue 4 target: one update ≥ 10^3× faster than a from-scratch run at n = 10^5 in 2D (full mode);
// quick mode (ctest) only checks that an update beats a from-scratch run.
Verdict speed(const Options& o) {
  Verdict v;
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{200} : std::vector<std::size_t>{10000, 100000};
  const double target = o.quick ? 1 : 1000;
  int pairs = o.quick ? 5 : 20;
  v.pass = true;
  svg::Series ratio_s{"from-scratch / update time", {}};
  for (std::size_t n : sizes) {
    auto pts = gen::points<2>(gen::Kind::uniform, n + pairs, o.seed + 3);
    std::vector<Point<2>> in(pts.begin(), pts.begin() + n);
    auto t0 = std::chrono::steady_clock::now();
    WellSpacedSet<2> ws(in);
    double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    auto u = sample_updates<2>(ws, std::vector<Point<2>>(pts.begin() + n, pts.end()));
    double upd = measured(o, "T3.4.3-speed mean update seconds", u.mean_seconds);  // audit.hpp's seam
    std::string at = "n=" + std::to_string(n) + " ";
    v.figure(at + "from-scratch seconds", fmt(build));
    v.figure(at + "mean update seconds", fmt(upd));
    v.figure(at + "speed ratio (scratch/update)", fmt(build / upd));
    ratio_s.points.push_back({double(n), build / upd});
    v.figure(at + "mean operations touched per update", fmt(u.mean_touched));
    v.pass = v.pass && build / upd > 1;
    if (n == sizes.back()) v.pass = v.pass && build / upd >= target;
  }
  {
    svg::Plot p;
    p.title = "T3.4.3-speed: one update vs StableWS from scratch (2D uniform)";
    p.x = svg::log_axis("n", "input points");
    p.y = svg::log_axis("time ratio", "from-scratch / update");
    p.series = {ratio_s};
    p.bounds.push_back(svg::constant_bound(o.quick ? "pass bound (quick): 1" : "target: 1000", target, double(sizes.front()) / 2,
                                           double(sizes.back()) * 2));
    v.plot(std::move(p));
  }
  if (!v.pass) v.summary = "an update was not faster than the target ratio; ";
  v.summary += o.quick ? "2D uniform: one insertion/deletion with PropagateWS vs StableWS from scratch (update must be faster)"
                      : "2D uniform: one insertion/deletion with PropagateWS vs StableWS from scratch; target >= 1000x at n = 1e5";
  return v;
}

}  // namespace

std::vector<Check> wellspaced_checks() {
  return {
      {"T3.3.4", "StableWS output is rho-well-spaced and size-conforming (2D, 3D)", t334},
      {"L3.4.2", "PropagateWS output and computation graph equal from-scratch after random updates", l342},
      {"L3.3.6", "an operation at rank r on v has NN_inf(v) in Theta(rho^r)", l336},
      {"T3.3.8", "O(1) squares per clipped-Voronoi call and Steiner vertices per fill (Lemma 3.3.9)", t338},
      {"T3.3.11", "StableWS in O(n log Delta): operations / (n log2 Delta) bounded", t3311},
      {"L3.3.15", "affected vertices within O(NN(v)) of the updated point", l3315},
      {"T3.4.3", "O(log Delta) operations per dynamic update", [](const Options& o) { return t343(o, false); }},
      {"L3.4.4", "Omega(log Delta) Steiner changes for an insertion next to a vertex (one gadget)", [](const Options& o) { return t343(o, true); }},
      {"T3.4.5", "Omega(n log Delta) Steiner insertions for n gadget insertions (tiled gadgets)", t345},
      {"T3.4.3-speed", "update vs from-scratch time ratio", speed},
  };
}

}  // namespace kmr::audit
