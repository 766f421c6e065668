// Audit checks for §1.3 (self-adjusting computation): change propagation yields the from-scratch
// trace and output; edits of stable programs cost little work (cognates reused); overhead and
// speedup of the benchmark programs, measured.
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>

#include "audit/audit.hpp"
#include "sacprograms/bench.hpp"
#include "sac/big_stack.hpp"
#include "sac/runtime.hpp"
#include "sacprograms/exptree.hpp"
#include "sacprograms/generality.hpp"
#include "sacprograms/session.hpp"

namespace kmr::audit {

namespace {
using namespace kmr::sacprograms;


// Random single edits and batches; after each propagation compare with a from-scratch run.
Verdict propagation_equals_from_scratch(const Options& o) {
  Verdict v;
  std::size_t n = o.quick ? 100 : 1000, rounds = o.quick ? 20 : 60;
  std::size_t checked = 0, bad = 0;
  std::string first_bad;
  for (const auto& p : list_programs()) {
    std::mt19937_64 rng(o.seed ^ std::hash<std::string>{}(p.name));
    auto value = [&] { return bench_value(p.name, rng()) % (p.name == "quickhull" ? (1LL << 62) : 64); };
    std::vector<long long> in = bench_input(p.name, n, o.seed);
    if (p.name != "quickhull")
      for (auto& x : in) x %= 64;  // duplicates on purpose
    ListSession s(p, in);
    for (std::size_t r = 0; r < rounds; ++r) {
      std::size_t edits = r % 3 == 2 ? 4 : 1;  // every third round a batch before one propagation
      for (std::size_t e = 0; e < edits; ++e) s.random_edit(rng, value);
      s.propagate();
      Snapshot a = measured(o, "S1.3.1-change-propagation snapshot", s.snapshot()), b = from_scratch(p, s.values(), s.ids());
      ++checked;
      bool ok = a.output == b.output && a.output == s.static_output() && a.signature == b.signature &&
                a.trace_nodes == b.trace_nodes && a.live_mods == b.live_mods;
      if (!ok && bad++ == 0) first_bad = p.name + " round " + std::to_string(r);
    }
  }
  // Expression trees: split, merge and set edits.
  {
    std::mt19937_64 rng(o.seed);
    Runtime rt;
    TreeInput in(rt, PlainTree::random(n, o.seed));
    auto* out = sa_exptree(rt, in.root());
    for (std::size_t r = 0; r < rounds; ++r) {
      auto leaves = in.tree().leaves();
      auto merge = in.tree().mergeable();
      int kind = static_cast<int>(rng() % 3);
      if (kind == 0) in.set(leaves[rng() % leaves.size()], static_cast<long long>(rng() % 100));
      else if (kind == 1 || merge.empty()) in.split(leaves[rng() % leaves.size()], static_cast<int>(rng() % 3), 7);
      else in.merge(merge[rng() % merge.size()]);
      in.propagate();
      Runtime fresh;
      TreeInput in2(fresh, in.tree());
      sa_exptree(fresh, in2.root());
      ++checked;
      bool ok = rt.deref(out) == in.tree().eval() && rt.signature() == fresh.signature() &&
                rt.stats().trace_nodes == fresh.stats().trace_nodes && rt.stats().live_mods == fresh.stats().live_mods;
      if (!ok && bad++ == 0) first_bad = "exptree round " + std::to_string(r);
    }
  }
  // The Appendix A.2 shapes (issue 8 §1): certificates created in the run and flipped by their
  // owner, destination memo with repeated keys, a write that moves earlier.
  {
    std::size_t m = o.quick ? 60 : 200;
    for (int prog = 0; prog < 3; ++prog) {
      std::mt19937_64 rng(o.seed + 77 + static_cast<std::uint64_t>(prog));
      std::vector<long long> vals(m);
      std::vector<std::uint64_t> ids(m);
      for (std::size_t i = 0; i < m; ++i) {
        vals[i] = prog == 2 ? -static_cast<long long>(rng() % 10) : static_cast<long long>(rng() % 13) - 6;
        ids[i] = i + 1;
      }
      std::uint64_t next_id = m + 1;
      std::map<std::uint64_t, bool> flips;
      auto build = [&](Runtime& rt, ListInput& in, CertificateOwner& owner) -> std::function<std::vector<long long>()> {
        if (prog == 0) {
          Root* r = sa_certified_filter(rt, in.root(), &owner);
          return [&rt, r] { return to_vector(rt, r); };
        }
        if (prog == 1) {
          Root* r = sa_next_greater(rt, in.root());
          return [&rt, r] { return to_vector(rt, r); };
        }
        Mod<long long>* r = sa_first_positive(rt, in.root());
        return [&rt, r] { return std::vector<long long>{rt.deref(r)}; };
      };
      Runtime rt;
      CertificateOwner owner(rt);
      ListInput in(rt, vals, ids);
      auto out = build(rt, in, owner);
      for (std::size_t r = 0; r < rounds; ++r) {
        std::size_t size = vals.size();
        int kind = size == 0 ? 0 : static_cast<int>(rng() % (prog == 0 ? 4 : 3));
        std::size_t pos = static_cast<std::size_t>(rng() % (kind == 0 ? size + 1 : size));
        long long x = static_cast<long long>(rng() % 13) - (prog == 2 ? 11 : 6);
        if (kind == 0) {
          in.insert(pos, next_id, x);
          vals.insert(vals.begin() + static_cast<std::ptrdiff_t>(pos), x);
          ids.insert(ids.begin() + static_cast<std::ptrdiff_t>(pos), next_id++);
        } else if (kind == 1) {
          in.erase(pos);
          vals.erase(vals.begin() + static_cast<std::ptrdiff_t>(pos));
          ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(pos));
        } else if (kind == 2) {
          in.set(pos, x);
          vals[pos] = x;
        } else {
          std::uint64_t name = input_cell_name(ids[pos]);
          flips[name] = !certificate_truth(flips, name);
          owner.flip(name);
        }
        in.propagate();
        Runtime frt;
        CertificateOwner fowner(frt);
        fowner.set_flips(flips);
        ListInput fin(frt, vals, ids);
        build(frt, fin, fowner);
        std::vector<long long> want = prog == 0   ? static_certified_filter(vals, ids, flips)
                                      : prog == 1 ? static_next_greater(vals)
                                                  : std::vector<long long>{static_first_positive(vals)};
        ++checked;
        bool ok = out() == want && rt.signature() == frt.signature() &&
                  rt.stats().trace_nodes == frt.stats().trace_nodes && rt.stats().live_mods == frt.stats().live_mods &&
                  (prog != 0 || owner.live().size() == ids.size());
        if (!ok && bad++ == 0) first_bad = std::string(prog == 0 ? "certified_filter" : prog == 1 ? "next_greater" : "first_positive") +
                                           " round " + std::to_string(r);
      }
    }
  }
  v.pass = bad == 0;
  v.summary = "7 programs, n=" + std::to_string(n) + ", and 3 App. A shapes (certificates, destination memo, " +
              "moved write): after each propagation output = static twin, trace signature and live counts = " +
              "from-scratch run" + (bad ? "; first failure: " + first_bad : "");
  v.figure("propagations_checked", std::to_string(checked));
  v.figure("mismatches", std::to_string(bad));
  return v;
}

// Work per edit (memo misses + reads re-executed) at n and 8n: stable programs grow polylogarithmically.
Verdict edit_work_is_small(const Options& o) {
  Verdict v;
  std::size_t n = o.quick ? 500 : 4000, edits = o.quick ? 40 : 100;
  bool pass = true;
  std::vector<std::string> names;
  svg::Series at_n{"n=" + std::to_string(n), {}}, at_8n{"8n=" + std::to_string(8 * n), {}};
  for (const auto& p : list_programs()) {
    double work[2];
    for (int k = 0; k < 2; ++k) {
      std::size_t size = n << (3 * k);
      std::vector<std::uint64_t> ids(size);
      for (std::size_t i = 0; i < size; ++i) ids[i] = i + 1;
      Runtime rt;
      ListInput in(rt, bench_input(p.name, size, o.seed), ids);
      p.build(rt, in.root());
      std::mt19937_64 rng(o.seed + 1);
      auto s0 = rt.stats();
      for (std::size_t e = 0; e < edits; ++e) {
        if (e % 2 == 0) in.erase(in.random_cell(rng()));
        else in.insert_after(in.random_cell(rng()), size + 1 + e, bench_value(p.name, rng()));
        in.propagate();
      }
      auto s1 = rt.stats();
      work[k] = static_cast<double>((s1.memo_misses - s0.memo_misses) + (s1.reads_reexecuted - s0.reads_reexecuted)) /
                static_cast<double>(edits);
    }
    double growth = measured(o, "S1.3.2 growth " + p.name, work[1] / std::max(work[0], 1.0));  // audit.hpp's seam
    at_n.points.push_back({double(names.size()), work[0]});
    at_8n.points.push_back({double(names.size()), work[1]});
    names.push_back(p.name);
    v.figure(p.name + "_work_per_edit", fmt(work[0]) + " -> " + fmt(work[1]) + " (x" + fmt(growth) + " for 8x n)");
    pass = pass && growth < 4.0;  // linear work would grow 8x
  }
  svg::Plot plot;
  plot.title = "S1.3.2: work per random edit at n and 8n (pass: growth < 4x)";
  plot.x = svg::category_axis("program", names);
  plot.y = svg::log_axis("memo misses + reads re-executed per edit", "operations");
  plot.series = {at_n, at_8n};
  v.plot(std::move(plot));
  v.pass = pass;
  v.summary = std::string(pass ? "" : "work per edit grew by 4x or more for 8x n; ") +
              "memo misses + reads re-executed per random insertion/deletion at n=" + std::to_string(n) +
              " and 8n; pass if each grows < 4x (linear would be 8x)";
  return v;
}

Verdict overhead_and_speedup(const Options& o) {
  Verdict v;
  std::size_t n = o.quick ? 5000 : 100000, edits = o.quick ? 40 : 200;
  auto rows = measured(o, "S1.3.4 rows", bench_all(n, edits, o.seed));  // audit.hpp's seam
  bool ok = true;
  std::vector<std::string> names;
  svg::Series overhead{"overhead at n=" + std::to_string(n), {}}, speedup{"speedup at n=" + std::to_string(n), {}};
  svg::Series overhead_anchor{"anchor (CEAL/DeltaML, n=1e6)", {}}, speedup_anchor{"anchor (CEAL/DeltaML, n=1e6)", {}};
  for (const auto& r : rows) {
    ok = ok && r.output_ok;
    bool simple = r.program == "map" || r.program == "filter" || r.program == "sum";
    double x = double(names.size());
    overhead.points.push_back({x, r.overhead});
    speedup.points.push_back({x, r.speedup});
    if (r.program != "exptree") {  // the anchors name map/filter/sum and the sorts/quickhull
      overhead_anchor.points.push_back({x, simple ? 10.0 : 20.0});
      speedup_anchor.points.push_back({x, simple ? 1e3 : 1e2});
    }
    names.push_back(r.program);
    v.figure(r.program, "overhead " + fmt(r.overhead) + ", speedup " + fmt(r.speedup) + ", " +
                            std::to_string(r.trace_nodes) + " trace nodes, " + fmt(r.bytes_per_node) + " B/node, " +
                            fmt(r.bytes_per_element) + " B/element" +
                            (r.output_ok ? "" : ", WRONG OUTPUT"));
  }
  for (int k = 0; k < 2; ++k) {
    svg::Plot plot;
    plot.title = k == 0 ? "S1.3.4: overhead of the initial self-adjusting run (anchor: at most)"
                        : "S1.3.4: speedup of one edit with change propagation (anchor: at least)";
    plot.x = svg::category_axis("program", names);
    plot.y = k == 0 ? svg::log_axis("initial run / static run", "time ratio") : svg::log_axis("static run / one edit", "time ratio");
    plot.series = k == 0 ? std::vector<svg::Series>{overhead, overhead_anchor} : std::vector<svg::Series>{speedup, speedup_anchor};
    v.plot(std::move(plot));
  }
  v.thesis = "CEAL (PLDI'09) / DeltaML anchors cited in §1.3: overhead <= 10x (map, filter, sum), <= 20x (sorts, quickhull); "
             "speedup >= 10^3 resp. >= 10^2 at n = 10^6";
  bool lean = true;  // issue 8 §2's size-independent targets (its speedup targets are at n = 10^6)
  for (const auto& r : rows) {
    bool simple = r.program == "map" || r.program == "filter" || r.program == "sum" || r.program == "exptree";
    lean = lean && r.overhead <= (simple ? 10.0 : 20.0);
    if (r.program == "map") lean = lean && r.bytes_per_element <= 150;
  }
  v.set_target("overhead ≤ 10× (map, filter, sum, exptree), ≤ 20× (quicksort, mergesort, quickhull); map trace ≤ 150 "
               "B/element (issue 8 §2; the speedup targets are at n = 10^6, spec/sac.md)", lean);
  v.pass = ok;
  v.summary = "kmr bench sac at n=" + std::to_string(n) + " (" + std::to_string(edits) +
              " edits): figures reported; pass = outputs equal the static twins (targets at 1e6: see spec/sac.md)";
  return v;
}
}  // namespace

// The list programs recurse once per element: run every check on a large stack
// (reserved, not committed: only the pages touched cost memory).
std::function<Verdict(const Options&)> on_large_stack(Verdict (*check)(const Options&)) {
  return [check](const Options& o) {
    Verdict v;
    sac::with_stack(std::size_t{1} << 30, [&] { v = check(o); });
    return v;
  };
}

std::vector<Check> sac_checks() {
  return {
      {"S1.3.1-change-propagation", "change propagation yields the from-scratch trace and output",
       on_large_stack(propagation_equals_from_scratch)},
      {"S1.3.2-monotone-reuse", "stable programs: edits reuse cognates, work per edit grows slowly",
       on_large_stack(edit_work_is_small)},
      {"S1.3.4-overhead-speedup", "overhead of initial runs and speedup of edits (measured)",
       on_large_stack(overhead_and_speedup)},
  };
}

}  // namespace kmr::audit
