// Chapter 4 claims (kinetic mesh refinement in 2D; static construction of Fig. 4.2 only) for
// `kmr audit`. Asymptotic claims are reported as ratios over growing inputs with the claim beside
// them; the kinetic/dynamic claims (T4.3.7, L4.4.*) have no check because §4.3 is not implemented.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "audit/audit.hpp"
#include "kmesh/construction.hpp"
#include "kmesh/invariants.hpp"

namespace kmr::audit {
namespace {

using namespace kmr::kmesh;

std::vector<InputPoint> uniform(std::size_t n, std::uint64_t seed, int range) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> d(0, range);
  std::vector<InputPoint> in;
  while (in.size() < n) {
    InputPoint p{exact::Integer(d(rng)), exact::Integer(d(rng))};
    if (std::find(in.begin(), in.end(), p) == in.end()) in.push_back(p);
  }
  return in;
}

double log2_spread(const std::vector<InputPoint>& in) {
  double dmax = 0, dmin = INFINITY;
  for (std::size_t i = 0; i < in.size(); ++i)
    for (std::size_t j = i + 1; j < in.size(); ++j) {
      double dx = (in[i].x - in[j].x).convert_to<double>(), dy = (in[i].y - in[j].y).convert_to<double>();
      double d = std::hypot(dx, dy);
      dmax = std::max(dmax, d), dmin = std::min(dmin, d);
    }
  return std::log2(dmax / dmin);
}

struct Run {
  std::size_t n, m;
  double logd, ops_ratio, centers_ratio, ws;
  bool ok;
};

Run run(const std::vector<InputPoint>& in) {
  Mesh m = construct(in);
  bool ok = true;
  for (auto& c : {check_ball_empty(m), check_independent_set(m), check_voronoi_candidates(m), check_delaunay(m)})
    ok = ok && c.ok();
  auto ws = check_well_spaced(m);
  ok = ok && ws.ok();
  double logd = log2_spread(in);
  double ops = double(m.ops_spanner + m.ops_convert + m.ops_delaunay);
  std::size_t maxc = 0;
  for (auto& r : m.ranks) {
    std::size_t c = 0;
    for (std::size_t v = 0; v < m.size(); ++v)
      if (m.spanner.top(int(v)) >= r.rank && m.spanner.min_rank(int(v)) <= r.rank) ++c;
    maxc = std::max(maxc, c);
  }
  return {in.size(), m.size(), logd, ops / (in.size() * logd), double(maxc) / in.size(), ws.measured, ok};
}

Verdict t4212(const Options& o) {
  Verdict v;
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{4, 8} : std::vector<std::size_t>{6, 12, 24};
  double lo = INFINITY, hi = 0, clo = INFINITY, chi = 0, ws = 0;
  bool ok = true;
  for (auto n : sizes) {
    Run r = run(uniform(n, o.seed + n, 1000));
    ok = ok && r.ok;
    lo = std::min(lo, r.ops_ratio), hi = std::max(hi, r.ops_ratio);
    clo = std::min(clo, r.centers_ratio), chi = std::max(chi, r.centers_ratio);
    ws = std::max(ws, r.ws);
    v.figure("n=" + std::to_string(n) + " ops/(n lg Δ)", fmt(r.ops_ratio));
    v.figure("n=" + std::to_string(n) + " |M|/n", fmt(double(r.m) / n));
  }
  // A cluster of 3 points with spread 2^20 (log Δ grows, n does not).
  {
    std::vector<InputPoint> in{{exact::Integer(0), exact::Integer(0)}, {exact::Integer(1), exact::Integer(0)},
                               {exact::Integer(1) << (o.quick ? 10 : 20), exact::Integer(5)}};
    Run r = run(in);
    ok = ok && r.ok;
    lo = std::min(lo, r.ops_ratio), hi = std::max(hi, r.ops_ratio);
    ws = std::max(ws, r.ws);
    v.figure("spread 2^" + fmt(r.logd) + " ops/(n lg Δ)", fmt(r.ops_ratio));
  }
  v.figure("max/min ops/(n lg Δ)", fmt(hi / lo));
  v.figure("max |vc|/NN(v) (claim ≤ 4.5)", fmt(ws));
  v.pass = ok && hi / lo < 8;
  v.summary = "Fig. 4.2 on uniform and clustered inputs: lemma checks L4.2.4/5/9, Delaunay, 9/2-well-spaced all hold; "
              "operations ÷ (n log Δ) stay within a factor 8 (claim: O(n log Δ))";
  return v;
}

Verdict l4211(const Options& o) {
  Verdict v;
  std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{4, 8} : std::vector<std::size_t>{6, 12, 24};
  double hi = 0, lo = INFINITY;
  for (auto n : sizes) {
    Run r = run(uniform(n, o.seed + 7 * n, 1000));
    hi = std::max(hi, r.centers_ratio), lo = std::min(lo, r.centers_ratio);
    v.figure("n=" + std::to_string(n) + " max_l |S_l|/n", fmt(r.centers_ratio));
  }
  v.pass = hi / lo < 4;
  v.summary = "ℓ-centers (stored ranks λ_v ≤ ℓ ≤ Λ_v) per rank ÷ n, max over ranks, bounded over n (claim: O(n) per rank)";
  return v;
}

}  // namespace

std::vector<Check> kmesh_checks() {
  return {{"T4.2.12", "Ch.4 construction: quality mesh in O(n log Δ) operations", t4212},
          {"L4.2.11", "Ch.4: O(n) ℓ-centers per rank", l4211}};
}

}  // namespace kmr::audit
