#pragma once
// Input generators for the Chapter 3 oracle tests and benches (CGAL-free, deterministic).
// Guarantees: every point lies in [0,1]^D, coordinates are doubles (exact dyadics), no duplicates,
// and the result depends only on (kind, n, seed). Degenerate families on purpose (design.md,
// doctrine 4): grids (cocircular/cospherical), collinear, near-duplicate pairs (2^-30 apart),
// domain boundary and corners, clusters. ClosePairs: max(1, n/40) pairs 2^-30 apart + uniform.
#include <cstdint>
#include <string>
#include <vector>

#include "ws_oracle.hpp"

namespace kmr::oracle::ws::gen {

enum class Kind { Uniform, Clustered, Line, Grid, ClosePairs, Boundary };
std::string name(Kind k);
inline const Kind kAllKinds[] = {Kind::Uniform, Kind::Clustered, Kind::Line,
                                 Kind::Grid,    Kind::ClosePairs, Kind::Boundary};

// About n points (Grid rounds n to a full grid) of the given kind.
template <std::size_t D>
std::vector<DPoint<D>> make(Kind kind, std::size_t n, std::uint64_t seed);

}  // namespace kmr::oracle::ws::gen
