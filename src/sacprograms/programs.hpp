#pragma once
// The CEAL / ΔML benchmark programs written against kmr::sac, each with a plain static twin (the
// same algorithm without tracing, like ΔML's automatically generated non-adaptive version).
// Guarantees (tested in proptests/sac against the twins, and in tests/sac against independent
// references: std::transform, std::accumulate, std::sort, a monotone-chain hull, recursive eval):
//  * map:       out[i] = map_fn(in[i]) = 3 in[i] + 1, wrapping modulo 2^64 (defined for every input).
//  * filter:    the elements with keep_fn(x), in order.
//  * sum:       Σ in (wrapping 64-bit), by randomized contraction.
//  * quicksort: in sorted ascending (stable for equal keys), first element as pivot.
//  * mergesort: in sorted ascending, lists split by coins of cell names (ΔML msort).
//  * quickhull: the strict convex-hull vertices of the points in (encoded by encode_point),
//               counterclockwise from the lexicographically smallest; [] if empty, [p] if all equal.
// After any edits and propagate(), the self-adjusting output equals the static twin's on the
// current input and the trace equals a from-scratch run's (sac::Runtime guarantees).
#include <functional>
#include <string>
#include <vector>

#include "sacprograms/list.hpp"

namespace kmr::sacprograms {

long long map_fn(long long x);
bool keep_fn(long long x);

// Points of quickhull: |x|, |y| < 2^29, packed into one long long (x high, y low 32 bits).
constexpr long long kCoordLimit = 1LL << 29;
long long encode_point(long long x, long long y);  // throws InputError out of range
long long point_x(long long p);
long long point_y(long long p);

// A list program: `build` runs it on the input root inside rt.run and returns a function that
// reads its current output (through Meta.deref); `twin` runs the static twin on a plain list and,
// if `seconds` is not null, stores the time of the algorithm proper (not of copying its output).
struct ListProgram {
  std::string name;
  std::function<std::function<std::vector<long long>()>(Runtime&, Root*)> build;
  std::function<std::vector<long long>(const SCell*, SArena&, double* seconds)> twin;
};

// map, filter, sum, quicksort, mergesort, quickhull — in that order.
const std::vector<ListProgram>& list_programs();
const ListProgram& list_program(const std::string& name);  // throws InputError if unknown

// Independent references (plain STL / textbook code, not the algorithms above).
std::vector<long long> reference_output(const std::string& name, const std::vector<long long>& in);

}  // namespace kmr::sacprograms
