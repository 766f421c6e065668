#pragma once
// Measurements of the benchmark programs (kmr bench sac, kmr audit): one row per program with the
// static twin's time, the initial self-adjusting run's time, their ratio (overhead), the mean time of
// one random single-element insertion or deletion plus propagation, static ÷ edit (speedup), live
// trace nodes and bytes per node. Guarantees: inputs and edits come from the seed only; every
// edit's output is checked against the static twin at the end of the run (a row with
// output_ok = false reports a wrong answer, it is never hidden).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace kmr::sacprograms {

struct BenchRow {
  std::string program;
  std::size_t n = 0;
  double static_s = 0, initial_s = 0, overhead = 0, edit_s = 0, speedup = 0;
  std::uint64_t trace_nodes = 0;
  double bytes_per_node = 0;
  double bytes_per_element = 0;  // the runtime's bytes after the initial run ÷ n (trace + modifiables)
  double peak_rss_mb = 0;        // the process's peak RSS after this row (per program: run --program)
  std::size_t edits = 0;
  bool output_ok = false;
};

std::vector<long long> bench_input(const std::string& program, std::size_t n, std::uint64_t seed);
long long bench_value(const std::string& program, std::uint64_t r);  // a random element

BenchRow bench_list(const std::string& program, std::size_t n, std::size_t edits, std::uint64_t seed);
BenchRow bench_exptree(std::size_t n, std::size_t edits, std::uint64_t seed);
// All seven programs (map, filter, sum, quicksort, mergesort, quickhull, exptree), on a big stack,
// after check_bench_memory for each wanted program. `before` (when set, e.g. progress) is called
// before each program's run with (index from 0, number of programs, name).
std::vector<BenchRow> bench_all(std::size_t n, std::size_t edits, std::uint64_t seed,
                                const std::vector<std::string>& only = {},
                                const std::function<void(std::size_t, std::size_t, const std::string&)>& before = {});

// Memory guard (bench_all runs it first): the bytes the initial run of `program` on n elements
// holds, measured at n = 2048 and 16384 and extrapolated as n·(α + β·log2 n) plus the harness's
// side tables; check_bench_memory throws InputError naming program, n, estimate and MemAvailable
// when the estimate exceeds it (no check for n ≤ kBenchProbeBelow).
constexpr std::size_t kBenchProbeBelow = 65536;
std::uint64_t available_memory();  // /proc/meminfo MemAvailable in bytes, 0 if unknown
double estimate_bench_bytes(const std::string& program, std::size_t n, std::uint64_t seed);
void check_bench_memory(const std::string& program, std::size_t n, std::uint64_t seed);

std::string bench_json(const std::vector<BenchRow>& rows);

}  // namespace kmr::sacprograms
