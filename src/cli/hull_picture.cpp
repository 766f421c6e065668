#include "cli/hull_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "exact/error.hpp"
#include "svg/svg.hpp"

namespace kmr::cli {

namespace {
using V = std::array<double, 3>;
V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(const V& a, const V& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V unit(const V& a) {
  double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
}  // namespace

std::string hull_picture(const std::vector<hull::Point3d>& points, const hull::Hull& h, const std::string& caption) {
  // Screen basis: right = z × view, up = view × right (z stays up on the page).
  const V view = unit(kHullView), right = unit(cross({0, 0, 1}, view)), up = cross(view, right);
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  std::vector<std::array<double, 2>> q;
  for (const V& p : points) {
    q.push_back({dot(p, right), dot(p, up)});
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], q.back()[k]), hi[k] = std::max(hi[k], q.back()[k]);
  }
  const double ext = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!std::isfinite(ext) || !(ext > 0)) throw InputError("--svg: the coordinates are too large to be drawn");
  const double size = 600, margin = 24, legend = 44, s = (size - 2 * margin) / ext;
  const double ox = margin + (size - 2 * margin - s * (hi[0] - lo[0])) / 2, oy = margin + (size - 2 * margin - s * (hi[1] - lo[1])) / 2;
  auto X = [&](int i) { return ox + s * (q[i][0] - lo[0]); };
  auto Y = [&](int i) { return size - oy - s * (q[i][1] - lo[1]); };  // y up

  std::vector<char> is_vertex(points.size(), 0), on_front(points.size(), 0);
  for (int v : h.vertices) is_vertex[v] = 1;
  svg::Document d(size, size + legend);
  d.title(caption);
  svg::Style bg;
  bg.fill = "#ffffff";
  d.rect(0, 0, size, size + legend, bg);
  char view_text[96];
  std::snprintf(view_text, sizeof view_text, "%.17g %.17g %.17g", kHullView[0], kHullView[1], kHullView[2]);
  d.begin_group({{"class", "hull"}, {"data-view", view_text}});
  auto tri = [&](const std::array<int, 3>& f) {
    return std::vector<std::pair<double, double>>{{X(f[0]), Y(f[0])}, {X(f[1]), Y(f[1])}, {X(f[2]), Y(f[2])}};
  };
  auto facet_attr = [&](const std::array<int, 3>& f, const char* cls) {
    return svg::Attributes{{"class", cls}, {"data-facet", std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2])}};
  };
  // Back faces first (dashed, light), then the interior points, then the front faces over them.
  svg::Style back;
  back.stroke = "#9aa7b5", back.stroke_width = 0.7, back.dash = "4 3";
  std::vector<std::pair<std::array<int, 3>, double>> front;
  for (const auto& f : h.facets) {
    V n = cross(sub(points[f[1]], points[f[0]]), sub(points[f[2]], points[f[0]]));
    double c = dot(unit(n), view);
    if (c > 0) {
      front.push_back({f, c});
      for (int v : f) on_front[v] = 1;
    } else {
      d.polygon(tri(f), back, facet_attr(f, "back"));
    }
  }
  svg::Style grey;
  grey.fill = "#7f7f7f";
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_vertex[i])
      d.circle(X(int(i)), Y(int(i)), 1.8, grey,
               {{"class", "point"}, {"data-index", std::to_string(i)}, {"data-x", svg::exact_number(points[i][0])},
                {"data-y", svg::exact_number(points[i][1])}, {"data-z", svg::exact_number(points[i][2])}});
  for (const auto& [f, c] : front) {
    svg::Style fs;
    char rgb[16];
    int g = int(150 + 95 * c);  // lighter the more the face looks at the viewer
    std::snprintf(rgb, sizeof rgb, "#%02x%02x%02x", g * 80 / 100, g * 92 / 100, g);
    fs.fill = rgb, fs.stroke = "#2c3e57", fs.stroke_width = 0.8, fs.opacity = 0.82;
    d.polygon(tri(f), fs, facet_attr(f, "front"));
  }
  svg::Style vf, vb;
  vf.fill = "#1b2a49", vb.fill = "#ffffff", vb.stroke = "#8a97a8";
  for (int v : h.vertices)
    d.circle(X(v), Y(v), on_front[v] ? 3.2 : 2.6, on_front[v] ? vf : vb,
             {{"class", "vertex"}, {"data-index", std::to_string(v)}, {"data-x", svg::exact_number(points[v][0])},
              {"data-y", svg::exact_number(points[v][1])}, {"data-z", svg::exact_number(points[v][2])}});
  d.end_group();
  double ly = size + 14;
  svg::TextStyle t;
  t.size = 12;
  d.circle(margin + 6, ly - 4, 3.2, vf);
  d.text(margin + 16, ly, std::to_string(h.vertices.size()) + " hull vertices, " + std::to_string(h.facets.size()) +
                              " facets (" + std::to_string(front.size()) + " facing the viewer, the rest dashed)", t);
  d.circle(margin + 426, ly - 4, 1.6, grey);
  d.text(margin + 434, ly, std::to_string(points.size() - h.vertices.size()) + " other points", t);
  t.fill = "#555";
  t.size = 11;
  d.text(margin, ly + 20, caption, t);
  return d.str();
}

}  // namespace kmr::cli
