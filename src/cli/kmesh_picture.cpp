#include "cli/kmesh_picture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/error.hpp"
#include "svg/svg.hpp"

namespace kmr::cli {

namespace {
using P = std::pair<double, double>;

// Sutherland–Hodgman: the part of polygon `poly` inside the square [x0, x1] × [y0, y1] (pixels).
std::vector<P> clip_to_square(std::vector<P> poly, double x0, double y0, double x1, double y1) {
  auto cut = [&](auto inside, auto cross) {
    std::vector<P> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const P &a = poly[i], &b = poly[(i + 1) % poly.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) out.push_back(cross(a, b));
    }
    poly = out;
  };
  auto at_x = [](double x) { return [x](const P& a, const P& b) { return P{x, a.second + (x - a.first) / (b.first - a.first) * (b.second - a.second)}; }; };
  auto at_y = [](double y) { return [y](const P& a, const P& b) { return P{a.first + (y - a.second) / (b.second - a.second) * (b.first - a.first), y}; }; };
  cut([&](const P& p) { return p.first >= x0; }, at_x(x0));
  cut([&](const P& p) { return p.first <= x1; }, at_x(x1));
  cut([&](const P& p) { return p.second >= y0; }, at_y(y0));
  cut([&](const P& p) { return p.second <= y1; }, at_y(y1));
  return poly;
}
}  // namespace

std::string kmesh_picture(const std::vector<KmeshVertex>& vs, const std::vector<std::array<int, 3>>& triangles,
                          const std::string& caption) {
  const double inf = std::numeric_limits<double>::infinity();
  double lo[2] = {inf, inf}, hi[2] = {-inf, -inf}, ilo[2] = {inf, inf}, ihi[2] = {-inf, -inf};
  std::size_t inputs = 0;
  for (const auto& v : vs) {
    lo[0] = std::min(lo[0], v.x), hi[0] = std::max(hi[0], v.x), lo[1] = std::min(lo[1], v.y), hi[1] = std::max(hi[1], v.y);
    if (v.steiner) continue;
    ++inputs;
    ilo[0] = std::min(ilo[0], v.x), ihi[0] = std::max(ihi[0], v.x), ilo[1] = std::min(ilo[1], v.y), ihi[1] = std::max(ihi[1], v.y);
  }
  double ext = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!std::isfinite(ext)) throw InputError("--svg: the coordinates are too large to be drawn");
  if (!(ext > 0)) ext = 1;  // a single vertex
  // Right panel: a zoom on the input vertices (the outer Steiner orbits reach far beyond them).
  double zext = std::max(ihi[0] - ilo[0], ihi[1] - ilo[1]) * 1.5;
  if (!(zext > 0) || !std::isfinite(zext)) zext = ext / 8;
  const double zlo[2] = {(ilo[0] + ihi[0] - zext) / 2, (ilo[1] + ihi[1] - zext) / 2};
  const double size = 600, margin = 20, legend = 44, inner = size - 2 * margin;
  svg::Document d(2 * size, size + legend);
  d.title(caption);
  svg::Style bg;
  bg.fill = "#ffffff";
  d.rect(0, 0, 2 * size, size + legend, bg);
  const double r = std::clamp(50 / std::sqrt(double(vs.size())), 1.0, 4.0);
  svg::Style edge, in, st, frame;
  edge.stroke = "#7a8fa6", edge.fill = "#eef3f8", edge.stroke_width = 0.6;
  in.fill = "#1b2a49", in.stroke = "#1b2a49";
  st.fill = "#ffffff", st.stroke = "#d62728", st.stroke_width = std::max(0.8, r / 2.5);
  frame.stroke = "#333";
  // Panel 0: the whole mesh (its markers carry the data); panel 1: the zoom, clipped to its frame.
  for (int panel = 0; panel < 2; ++panel) {
    const double s = panel ? inner / zext : inner / ext, left = panel * size;
    const double ox = panel ? left + margin : left + margin + (inner - s * (hi[0] - lo[0])) / 2;
    const double oy = panel ? margin : margin + (inner - s * (hi[1] - lo[1])) / 2;
    const double bx = panel ? zlo[0] : lo[0], by = panel ? zlo[1] : lo[1];
    auto X = [&](int i) { return ox + s * (vs[i].x - bx); };
    auto Y = [&](int i) { return size - oy - s * (vs[i].y - by); };  // y up
    auto inside = [&](int i) { return X(i) >= left + margin && X(i) <= left + size - margin && Y(i) >= margin && Y(i) <= size - margin; };
    const std::string prefix = panel ? "zoom-" : "";
    d.begin_group({{"class", prefix + "triangles"}});
    for (const auto& t : triangles) {
      std::vector<P> poly = {{X(t[0]), Y(t[0])}, {X(t[1]), Y(t[1])}, {X(t[2]), Y(t[2])}};
      if (panel) poly = clip_to_square(poly, left + margin, margin, left + size - margin, size - margin);
      if (poly.size() >= 3)
        d.polygon(poly, edge, {{"class", prefix + "triangle"}, {"data-vertices", std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2])}});
    }
    d.end_group();
    const double pr = panel ? 3.5 : r;
    for (int pass = 0; pass < 2; ++pass) {  // Steiner vertices first, inputs on top
      d.begin_group({{"class", prefix + (pass ? "inputs" : "steiner")}});
      for (std::size_t i = 0; i < vs.size(); ++i)
        if (vs[i].steiner == (pass == 0) && (!panel || inside(int(i))))
          d.circle(X(int(i)), Y(int(i)), pass ? std::max(2.5, pr * 1.15) : pr, pass ? in : st,
                   {{"class", prefix + (pass ? "input" : "steiner")}, {"data-index", std::to_string(i)},
                    {"data-x", svg::exact_number(vs[i].x)}, {"data-y", svg::exact_number(vs[i].y)}});
      d.end_group();
    }
    if (panel) d.rect(left + margin, margin, inner, inner, frame);
  }
  double ly = size + 14;
  svg::TextStyle t;
  t.size = 12;
  d.circle(margin + 6, ly - 4, 4, in);
  d.text(margin + 16, ly, std::to_string(inputs) + " input vertices", t);
  d.circle(margin + 186, ly - 4, 4, st);
  d.text(margin + 196, ly, std::to_string(vs.size() - inputs) + " Steiner vertices", t);
  d.text(margin + 366, ly, std::to_string(triangles.size()) + " triangles", t);
  d.text(size + margin, ly, "right: zoom on the input vertices (1.5 x their bounding box)", t);
  t.fill = "#555";
  t.size = 11;
  d.text(margin, ly + 20, caption, t);
  return d.str();
}

}  // namespace kmr::cli
