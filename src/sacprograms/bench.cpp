#include "sacprograms/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <cstdio>
#include <random>

#include <sys/resource.h>

#include "sac/big_stack.hpp"
#include "sacprograms/exptree.hpp"
#include "sacprograms/session.hpp"

namespace kmr::sacprograms {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: KiB
}
}  // namespace

long long bench_value(const std::string& program, std::uint64_t r) {
  if (program == "quickhull") {
    long long x = static_cast<long long>(r & 0x1fffff) - (1 << 20);
    long long y = static_cast<long long>((r >> 21) & 0x1fffff) - (1 << 20);
    return encode_point(x, y);
  }
  return static_cast<long long>(r & 0x7fffffff);
}

std::vector<long long> bench_input(const std::string& program, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<long long> v(n);
  for (auto& x : v) x = bench_value(program, rng());
  return v;
}

BenchRow bench_list(const std::string& name, std::size_t n, std::size_t edits, std::uint64_t seed) {
  const ListProgram& p = list_program(name);
  BenchRow row;
  row.program = name;
  row.n = n;
  std::vector<long long> in = bench_input(name, n, seed);
  {
    SArena arena;
    SCell* l = to_slist(arena, in);
    p.twin(l, arena, &row.static_s);
  }
  std::vector<std::uint64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = i + 1;
  Runtime rt;
  ListInput input(rt, in, ids);
  auto t0 = Clock::now();
  auto reader = p.build(rt, input.root());
  row.initial_s = since(t0);
  auto st = rt.stats();
  row.trace_nodes = st.trace_nodes;
  row.bytes_per_node = st.trace_nodes ? static_cast<double>(st.bytes) / static_cast<double>(st.trace_nodes) : 0;
  row.bytes_per_element = n ? static_cast<double>(st.bytes) / static_cast<double>(n) : 0;

  // Edits: alternately delete a random element and insert a random one after a random element
  // (or at the front).
  std::mt19937_64 rng(seed ^ 0xed175);
  std::uint64_t next_id = n + 1;
  double total = 0;
  for (std::size_t e = 0; e < edits; ++e) {
    bool del = (e % 2 == 0) && input.size() > 0;
    std::uint64_t r = rng();
    List* cell = input.size() == 0 || r % (input.size() + 1) == 0 ? nullptr : input.random_cell(r);
    long long v = bench_value(name, rng());
    auto t1 = Clock::now();
    if (del) input.erase(cell ? cell : input.random_cell(r));
    else input.insert_after(cell, next_id++, v);
    input.propagate();
    total += since(t1);
  }
  row.edits = edits;
  row.edit_s = edits ? total / static_cast<double>(edits) : 0;
  row.overhead = row.static_s > 0 ? row.initial_s / row.static_s : 0;
  row.speedup = row.edit_s > 0 ? row.static_s / row.edit_s : 0;
  SArena arena;
  row.output_ok = reader() == p.twin(to_slist(arena, input.values()), arena, nullptr);
  row.peak_rss_mb = peak_rss_mb();
  return row;
}

BenchRow bench_exptree(std::size_t n, std::size_t edits, std::uint64_t seed) {
  BenchRow row;
  row.program = "exptree";
  row.n = n;
  PlainTree tree = PlainTree::random(std::max<std::size_t>(n, 1), seed);
  auto t0 = Clock::now();
  volatile long long sink = tree.eval();
  (void)sink;
  row.static_s = since(t0);
  Runtime rt;
  TreeInput input(rt, tree);
  t0 = Clock::now();
  Mod<long long>* out = sa_exptree(rt, input.root());
  row.initial_s = since(t0);
  auto st = rt.stats();
  row.trace_nodes = st.trace_nodes;
  row.bytes_per_node = st.trace_nodes ? static_cast<double>(st.bytes) / static_cast<double>(st.trace_nodes) : 0;
  row.bytes_per_element = n ? static_cast<double>(st.bytes) / static_cast<double>(n) : 0;
  // Edits: insert (split a random leaf into an operator over two leaves), then delete it (merge).
  std::mt19937_64 rng(seed ^ 0xed175);
  std::vector<int> leaves = input.tree().leaves();
  input.reserve(edits);  // keep vector growth of the harness out of the timings
  double total = 0;
  for (std::size_t e = 0; e < edits; e += 2) {
    int leaf = leaves[rng() % leaves.size()];
    auto t1 = Clock::now();
    input.split(leaf, static_cast<int>(rng() % 3), static_cast<long long>(rng() % 1000));
    input.propagate();
    input.merge(leaf);
    input.propagate();
    total += since(t1);
  }
  std::size_t done = (edits + 1) / 2 * 2;
  row.edits = done;
  row.edit_s = done ? total / static_cast<double>(done) : 0;
  row.overhead = row.static_s > 0 ? row.initial_s / row.static_s : 0;
  row.speedup = row.edit_s > 0 ? row.static_s / row.edit_s : 0;
  row.output_ok = rt.deref(out) == input.tree().eval();
  row.peak_rss_mb = peak_rss_mb();
  return row;
}

std::uint64_t available_memory() {
  std::ifstream f("/proc/meminfo");
  std::string key, unit;
  std::uint64_t kb = 0;
  while (f >> key >> kb) {
    std::getline(f, unit);
    if (key == "MemAvailable:") return kb * 1024;
  }
  return 0;  // unknown
}

namespace {
// Bytes held after the initial run of `program` on n elements: the runtime's own count (trace,
// modifiables, order-maintenance groups, index) plus the harness's per-element side tables.
constexpr double kHarnessBytesPerElement = 160;  // ListInput maps and vectors, input and id vectors

double probe_bytes_here(const std::string& program, std::size_t n, std::uint64_t seed) {
  Runtime rt;
  if (program == "exptree") {
    TreeInput input(rt, PlainTree::random(n, seed));
    sa_exptree(rt, input.root());
    return static_cast<double>(rt.stats().bytes);
  }
  const ListProgram& p = list_program(program);
  std::vector<std::uint64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = i + 1;
  ListInput input(rt, bench_input(program, n, seed), ids);
  auto reader = p.build(rt, input.root());
  return static_cast<double>(rt.stats().bytes);
}
// On a large stack (list recursion nests per element; sanitizer builds use
// several times the frame size, hence 8× bench_all's 2 KiB per element).
double probe_bytes(const std::string& program, std::size_t n, std::uint64_t seed) {
  double bytes = 0;
  sac::with_stack(std::max<std::size_t>(std::size_t{64} << 20, n * 16384),
                  [&] { bytes = probe_bytes_here(program, n, seed); });
  return bytes;
}
}  // namespace

double estimate_bench_bytes(const std::string& program, std::size_t n, std::uint64_t seed) {
  constexpr std::size_t n0 = 2048, n1 = 16384;  // log2 ratio 3
  double b0 = probe_bytes(program, n0, seed) / n0, b1 = probe_bytes(program, n1, seed) / n1;
  double beta = std::max(0.0, (b1 - b0) / 3);  // Θ(n log n) programs: bytes per element grow with log n
  double alpha = b1 - beta * std::log2(static_cast<double>(n1));
  double per = alpha + beta * std::log2(static_cast<double>(std::max<std::size_t>(n, 2)));
  return static_cast<double>(n) * (std::max(per, b1) + kHarnessBytesPerElement);
}

void check_bench_memory(const std::string& program, std::size_t n, std::uint64_t seed) {
  if (n <= kBenchProbeBelow) return;
  double need = estimate_bench_bytes(program, n, seed);
  double avail = static_cast<double>(available_memory());
  if (avail > 0 && need > avail) {
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "kmr bench sac: %s at n=%zu needs an estimated %.2f GB of trace (measured at n=2048 and n=16384, "
                  "extrapolated), more than the %.2f GB available (MemAvailable); choose a smaller --n",
                  program.c_str(), n, need / 1e9, avail / 1e9);
    throw InputError(buf);
  }
}

std::vector<BenchRow> bench_all(std::size_t n, std::size_t edits, std::uint64_t seed, const std::vector<std::string>& only,
                                const std::function<void(std::size_t, std::size_t, const std::string&)>& before) {
  std::vector<std::string> names;
  auto wanted = [&](const std::string& s) { return only.empty() || std::find(only.begin(), only.end(), s) != only.end(); };
  for (const auto& p : list_programs())
    if (wanted(p.name)) names.push_back(p.name);
  if (wanted("exptree")) names.push_back("exptree");
  // Refuse before running anything if a wanted program's trace would not fit in memory.
  for (const auto& name : names) check_bench_memory(name, n, seed);
  // List recursion nests one frame group per element: give the run a stack sized for n.
  std::vector<BenchRow> rows;
  std::size_t stack = std::max<std::size_t>(std::size_t{64} << 20, n * 2048);
  sac::with_stack(stack, [&] {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (before) before(i, names.size(), names[i]);
      rows.push_back(names[i] == "exptree" ? bench_exptree(n, edits, seed) : bench_list(names[i], n, edits, seed));
    }
  });
  return rows;
}

std::string bench_json(const std::vector<BenchRow>& rows) {
  std::string out = "[\n";
  char buf[512];
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& r = rows[i];
    std::snprintf(buf, sizeof buf,
                  "  {\"program\": \"%s\", \"n\": %zu, \"static_s\": %.6g, \"initial_s\": %.6g, \"overhead\": %.4g, "
                  "\"edit_s\": %.6g, \"speedup\": %.6g, \"trace_nodes\": %llu, \"bytes_per_node\": %.4g, "
                  "\"bytes_per_element\": %.4g, \"peak_rss_mb\": %.1f, \"edits\": %zu, \"output_ok\": %s}%s\n",
                  r.program.c_str(), r.n, r.static_s, r.initial_s, r.overhead, r.edit_s, r.speedup,
                  static_cast<unsigned long long>(r.trace_nodes), r.bytes_per_node, r.bytes_per_element,
                  r.peak_rss_mb, r.edits,
                  r.output_ok ? "true" : "false", i + 1 < rows.size() ? "," : "");
    out += buf;
  }
  return out + "]\n";
}

}  // namespace kmr::sacprograms
