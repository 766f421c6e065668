#include "cli/kmesh_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/error.hpp"
#include "svg/svg.hpp"

namespace kmr::cli {

std::string kmesh_picture(const std::vector<KmeshVertex>& vs, const std::vector<std::array<int, 3>>& triangles,
                          const std::string& caption) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& v : vs)
    lo[0] = std::min(lo[0], v.x), hi[0] = std::max(hi[0], v.x), lo[1] = std::min(lo[1], v.y), hi[1] = std::max(hi[1], v.y);
  double ext = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!std::isfinite(ext)) throw InputError("--svg: the coordinates are too large to be drawn");
  if (!(ext > 0)) ext = 1;  // a single vertex
  const double size = 600, margin = 20, legend = 44, s = (size - 2 * margin) / ext;
  const double ox = margin + (size - 2 * margin - s * (hi[0] - lo[0])) / 2, oy = margin + (size - 2 * margin - s * (hi[1] - lo[1])) / 2;
  auto X = [&](int i) { return ox + s * (vs[i].x - lo[0]); };
  auto Y = [&](int i) { return size - oy - s * (vs[i].y - lo[1]); };  // y up
  svg::Document d(size, size + legend);
  d.title(caption);
  svg::Style bg;
  bg.fill = "#ffffff";
  d.rect(0, 0, size, size + legend, bg);
  svg::Style edge;
  edge.stroke = "#7a8fa6", edge.fill = "#eef3f8", edge.stroke_width = 0.6;
  d.begin_group({{"class", "triangles"}});
  for (const auto& t : triangles)
    d.polygon({{X(t[0]), Y(t[0])}, {X(t[1]), Y(t[1])}, {X(t[2]), Y(t[2])}}, edge,
              {{"class", "triangle"}, {"data-vertices", std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2])}});
  d.end_group();
  std::size_t inputs = 0;
  for (const auto& v : vs) inputs += !v.steiner;
  const double r = std::clamp(50 / std::sqrt(double(vs.size())), 1.0, 4.0);
  svg::Style in, st;
  in.fill = "#1b2a49", in.stroke = "#1b2a49";
  st.fill = "#ffffff", st.stroke = "#d62728", st.stroke_width = std::max(0.8, r / 2.5);
  for (int pass = 0; pass < 2; ++pass) {  // Steiner vertices first, inputs on top
    d.begin_group({{"class", pass ? "inputs" : "steiner"}});
    for (std::size_t i = 0; i < vs.size(); ++i)
      if (vs[i].steiner == (pass == 0))
        d.circle(X(int(i)), Y(int(i)), pass ? std::max(2.5, r * 1.15) : r, pass ? in : st,
                 {{"class", pass ? "input" : "steiner"}, {"data-index", std::to_string(i)},
                  {"data-x", svg::exact_number(vs[i].x)}, {"data-y", svg::exact_number(vs[i].y)}});
    d.end_group();
  }
  double ly = size + 14;
  svg::TextStyle t;
  t.size = 12;
  d.circle(margin + 6, ly - 4, 4, in);
  d.text(margin + 16, ly, std::to_string(inputs) + " input vertices", t);
  d.circle(margin + 186, ly - 4, 4, st);
  d.text(margin + 196, ly, std::to_string(vs.size() - inputs) + " Steiner vertices", t);
  d.text(margin + 366, ly, std::to_string(triangles.size()) + " triangles", t);
  t.fill = "#555";
  t.size = 11;
  d.text(margin, ly + 20, caption, t);
  return d.str();
}

}  // namespace kmr::cli
