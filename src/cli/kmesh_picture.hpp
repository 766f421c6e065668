#pragma once
// `kmr kmesh --svg FILE`: a picture of the Chapter 4 mesh at time T — the Delaunay triangles of all
// output vertices (edges), input vertices filled dark, Steiner vertices open red; drawn from the
// same vertex list and triangles the command prints (coordinates in input units). Left: the whole
// mesh; right: a zoom on the input vertices (1.5 × their bounding box; triangles clipped to it),
// since the outer Steiner orbits reach far beyond the input. Only the left panel carries data.
// Guarantees (tests/cli/kmesh_picture_test.sh): a well-formed SVG with one <polygon
// class="triangle"> per triangle (data-vertices: its three vertex indices, as printed) and one
// <circle> per vertex in the left panel (class "input" or "steiner", data-index its position in the
// output, data-x/data-y its printed coordinates, exactly); the right panel's classes are "zoom-…".
#include <array>
#include <string>
#include <vector>

namespace kmr::cli {

struct KmeshVertex {
  double x, y;
  bool steiner;
};

std::string kmesh_picture(const std::vector<KmeshVertex>& vertices, const std::vector<std::array<int, 3>>& triangles,
                          const std::string& caption);

}  // namespace kmr::cli
