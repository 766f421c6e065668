#pragma once
// A plot is data, not a drawing: a check fills one (series of (x, y) points, axis labels with units,
// optionally bounds to draw) and the report draws it with render(). This is the one way a check of
// `kmr audit` adds a picture (src/audit/audit.hpp: Verdict::plots).
// Guarantees (tests/svg): render() is a well-formed SVG document; every finite point of every series
// appears as one <circle class="pt"> carrying data-series (the series name), data-x and data-y (the
// point's coordinates, %.17g, so they read back to the same doubles); bounds are dashed polylines
// with class "bound"; points that are not finite (or ≤ 0 on a log axis) are not drawn, and a note
// says how many.
#include <optional>
#include <string>
#include <vector>

namespace kmr::svg {

struct XY {
  double x = 0, y = 0;
};

struct Series {
  std::string name;
  std::vector<XY> points;  // drawn in this order, joined by a line
};

struct Axis {
  std::string label;                    // e.g. "log2 Δ"
  std::string unit;                     // e.g. "operations"; empty for a pure number
  bool log = false;                     // base-10 logarithmic scale
  std::vector<std::string> categories;  // x only: point x = i stands for categories[i] (e.g. program names)
  std::string text() const { return unit.empty() ? label : label + " (" + unit + ")"; }
};

Axis linear_axis(std::string label, std::string unit = "");
Axis log_axis(std::string label, std::string unit = "");
Axis category_axis(std::string label, std::vector<std::string> categories);

struct Plot {
  std::string title;
  Axis x, y;
  std::vector<Series> series;  // measured
  std::vector<Series> bounds;  // fitted or claimed bounds, drawn dashed without markers
};

// y = c·x through the origin over the x range of s, c the largest (upper) or smallest (lower) y/x of
// s's points with x > 0: the tightest bound of that form the data admit. nullopt if there is none.
std::optional<Series> proportional_bound(const std::string& name, const Series& s, bool upper);
// y = c over [x0, x1].
Series constant_bound(const std::string& name, double c, double x0, double x1);

// The plot as a standalone SVG document (width × height pixels).
std::string render(const Plot& plot, double width = 640, double height = 400);

}  // namespace kmr::svg
