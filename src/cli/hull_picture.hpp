#pragma once
// `kmr hull --svg FILE`: an orthographic picture of a 3D hull, seen from the fixed direction
// kHullView (the viewer sits far away along it; z points up on the page). Facets whose outward
// normal points toward the viewer are front faces, drawn filled (shaded by the angle to the view);
// the others are back faces, their edges dashed and light. Hull vertices are marked (dark on the
// front, light behind); input points that are not vertices are small grey dots. Front/back and the
// projection are double arithmetic: they only place pixels and decide nothing.
// Guarantees (tests/cli/hull_picture_test.sh): a well-formed SVG with one <polygon class="front"> or
// <polygon class="back"> per facet (data-facet: its three input indices), one <circle
// class="vertex"> per hull vertex and one <circle class="point"> per other input point (data-index
// the input index, data-x/data-y/data-z its exact coordinates).
#include <array>
#include <string>
#include <vector>

#include "hull/hull.hpp"

namespace kmr::cli {

inline constexpr std::array<double, 3> kHullView = {1.0, -1.6, 0.9};  // toward the viewer

std::string hull_picture(const std::vector<hull::Point3d>& points, const hull::Hull& h, const std::string& caption);

}  // namespace kmr::cli
