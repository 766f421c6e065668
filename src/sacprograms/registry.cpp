#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>

#include "sacprograms/internal.hpp"

namespace kmr::sacprograms {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
template <class F>
auto timed(double* seconds, F&& f) {
  auto t0 = std::chrono::steady_clock::now();
  auto r = f();
  if (seconds) *seconds = since(t0);
  return r;
}
std::function<std::vector<long long>()> list_reader(Runtime& rt, Root* out) {
  return [&rt, out] { return to_vector(rt, out); };
}

// Andrew's monotone chain, the reference for quickhull's tests. Its arithmetic is its own (the
// encoding read again, an __int128 cross product): it shares no predicate with the self-adjusting
// program (geometry::orientation_value) nor with its static twin (twin::cross).
std::vector<long long> monotone_chain_hull(std::vector<long long> pts) {
  auto x = [](long long p) { return static_cast<__int128>(p >> 32); };
  auto y = [](long long p) { return static_cast<__int128>(static_cast<std::int32_t>(p & 0xffffffffLL)); };
  auto lex = [&](long long p, long long q) { return x(p) < x(q) || (x(p) == x(q) && y(p) < y(q)); };
  auto left_turn = [&](long long a, long long b, long long c) {
    return (x(b) - x(a)) * (y(c) - y(a)) > (y(b) - y(a)) * (x(c) - x(a));
  };
  std::sort(pts.begin(), pts.end(), lex);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() <= 1) return pts;
  std::vector<long long> h;
  for (int pass = 0; pass < 2; ++pass) {  // lower chain left to right, then upper right to left
    std::size_t start = h.size();
    for (long long p : pts) {
      while (h.size() >= start + 2 && !left_turn(h[h.size() - 2], h.back(), p)) h.pop_back();
      h.push_back(p);
    }
    h.pop_back();
    std::reverse(pts.begin(), pts.end());
  }
  return h;
}
}  // namespace

const std::vector<ListProgram>& list_programs() {
  static const std::vector<ListProgram> programs = {
      {"map", [](Runtime& rt, Root* in) { return list_reader(rt, sa_map(rt, in)); },
       [](const SCell* l, SArena& a, double* t) { return to_vector(timed(t, [&] { return static_map(l, a); })); }},
      {"filter", [](Runtime& rt, Root* in) { return list_reader(rt, sa_filter(rt, in)); },
       [](const SCell* l, SArena& a, double* t) { return to_vector(timed(t, [&] { return static_filter(l, a); })); }},
      {"sum",
       [](Runtime& rt, Root* in) -> std::function<std::vector<long long>()> {
         Mod<long long>* out = sa_sum(rt, in);
         return [&rt, out] { return std::vector<long long>{rt.deref(out)}; };
       },
       [](const SCell* l, SArena&, double* t) { return std::vector<long long>{timed(t, [&] { return static_sum(l); })}; }},
      {"quicksort", [](Runtime& rt, Root* in) { return list_reader(rt, sa_quicksort(rt, in)); },
       [](const SCell* l, SArena& a, double* t) { return to_vector(timed(t, [&] { return static_quicksort(l, a); })); }},
      {"mergesort", [](Runtime& rt, Root* in) { return list_reader(rt, sa_mergesort(rt, in)); },
       [](const SCell* l, SArena& a, double* t) { return to_vector(timed(t, [&] { return static_mergesort(l, a); })); }},
      {"quickhull", [](Runtime& rt, Root* in) { return list_reader(rt, sa_quickhull(rt, in)); },
       [](const SCell* l, SArena&, double* t) { return timed(t, [&] { return static_quickhull(l); }); }},
  };
  return programs;
}

const ListProgram& list_program(const std::string& name) {
  for (const auto& p : list_programs())
    if (p.name == name) return p;
  throw InputError("unknown list program '" + name + "'");
}

std::vector<long long> reference_output(const std::string& name, const std::vector<long long>& in) {
  std::vector<long long> out;
  if (name == "map") {
    std::transform(in.begin(), in.end(), std::back_inserter(out), map_fn);
  } else if (name == "filter") {
    std::copy_if(in.begin(), in.end(), std::back_inserter(out), keep_fn);
  } else if (name == "sum") {
    unsigned long long s = 0;
    for (long long x : in) s += static_cast<unsigned long long>(x);
    out.push_back(static_cast<long long>(s));
  } else if (name == "quicksort" || name == "mergesort") {
    out = in;
    std::sort(out.begin(), out.end());
  } else if (name == "quickhull") {
    out = monotone_chain_hull(in);
  } else {
    throw InputError("unknown list program '" + name + "'");
  }
  return out;
}

}  // namespace kmr::sacprograms
