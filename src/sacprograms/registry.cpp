#include <algorithm>
#include <numeric>

#include "sacprograms/internal.hpp"

namespace kmr::sacprograms {

namespace {
std::function<std::vector<long long>()> list_reader(Runtime& rt, Root* out) {
  return [&rt, out] { return to_vector(rt, out); };
}
}  // namespace

const std::vector<ListProgram>& list_programs() {
  static const std::vector<ListProgram> programs = {
      {"map", [](Runtime& rt, Root* in) { return list_reader(rt, sa_map(rt, in)); },
       [](const SCell* l, SArena& a) { return to_vector(static_map(l, a)); }},
      {"filter", [](Runtime& rt, Root* in) { return list_reader(rt, sa_filter(rt, in)); },
       [](const SCell* l, SArena& a) { return to_vector(static_filter(l, a)); }},
      {"sum",
       [](Runtime& rt, Root* in) -> std::function<std::vector<long long>()> {
         Mod<long long>* out = sa_sum(rt, in);
         return [&rt, out] { return std::vector<long long>{rt.deref(out)}; };
       },
       [](const SCell* l, SArena&) { return std::vector<long long>{static_sum(l)}; }},
      {"quicksort", [](Runtime& rt, Root* in) { return list_reader(rt, sa_quicksort(rt, in)); },
       [](const SCell* l, SArena& a) { return to_vector(static_quicksort(l, a)); }},
      {"mergesort", [](Runtime& rt, Root* in) { return list_reader(rt, sa_mergesort(rt, in)); },
       [](const SCell* l, SArena& a) { return to_vector(static_mergesort(l, a)); }},
      {"quickhull", [](Runtime& rt, Root* in) { return list_reader(rt, sa_quickhull(rt, in)); },
       [](const SCell* l, SArena&) { return static_quickhull(l); }},
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
