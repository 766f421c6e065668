#pragma once
// `kmr wellspaced --svg FILE`: a picture of a 2D well-spaced set — the Voronoi cells of the output
// vertices clipped to [0,1]², input vertices (filled, dark) drawn apart from Steiner vertices (open,
// red). Which vertices are Voronoi neighbours is decided exactly by the library
// (clipped_voronoi_neighbors, β ≥ ρ: for a ρ-well-spaced set every neighbour whose shared edge meets
// [0,1]² is a β-clipped neighbour); the cell polygons are then cut from the unit square by those
// neighbours' bisectors in double arithmetic, which only places pixels and decides nothing.
// Guarantees (tests/cli): a well-formed SVG with one <polygon class="cell"> and one <circle> per
// output vertex (class "input" or "steiner", data-x/data-y its exact coordinates).
#include <string>

#include "wellspaced/well_spaced_set.hpp"

namespace kmr::cli {

std::string wellspaced_picture(const wellspaced::WellSpacedSet<2>& ws, const std::string& caption);

}  // namespace kmr::cli
