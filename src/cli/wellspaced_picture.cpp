#include "cli/wellspaced_picture.hpp"

#include <algorithm>
#include <cmath>

#include "svg/svg.hpp"

namespace kmr::cli {

namespace {
using P = std::array<double, 2>;

// Sutherland–Hodgman: the part of polygon `poly` closer to v than to u (bisector half-plane).
std::vector<P> clip(const std::vector<P>& poly, const P& v, const P& u) {
  const double nx = u[0] - v[0], ny = u[1] - v[1], c = (nx * (u[0] + v[0]) + ny * (u[1] + v[1])) / 2;
  auto side = [&](const P& p) { return nx * p[0] + ny * p[1] - c; };  // ≤ 0: v's side
  std::vector<P> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P &a = poly[i], &b = poly[(i + 1) % poly.size()];
    double sa = side(a), sb = side(b);
    if (sa <= 0) out.push_back(a);
    if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) {
      double t = sa / (sa - sb);
      out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return out;
}
}  // namespace

std::string wellspaced_picture(const wellspaced::WellSpacedSet<2>& ws, const std::string& caption) {
  const double size = 600, margin = 20, legend = 44;
  auto X = [&](double x) { return margin + x * (size - 2 * margin); };
  auto Y = [&](double y) { return size - margin - y * (size - 2 * margin); };  // y up
  auto vs = ws.vertices();
  svg::Document d(size, size + legend);
  d.title(caption);
  svg::Style bg;
  bg.fill = "#ffffff";
  d.rect(0, 0, size, size + legend, bg);
  svg::Style cell;
  cell.stroke = "#7a8fa6", cell.fill = "#eef3f8", cell.stroke_width = 0.6;
  d.begin_group({{"class", "cells"}});
  std::size_t inputs = 0;
  for (const auto& v : vs) {
    inputs += !v.is_steiner;
    std::vector<P> poly = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& u : ws.clipped_voronoi_neighbors(v.exact)) poly = clip(poly, v.x, u.below());  // a picture: doubles
    std::vector<std::pair<double, double>> px;
    for (const P& p : poly) px.emplace_back(X(p[0]), Y(p[1]));
    d.polygon(px, cell, {{"class", "cell"}});
  }
  d.end_group();
  const double r = std::clamp(50 / std::sqrt(double(vs.size())), 1.0, 4.0);
  svg::Style in, st;
  in.fill = "#1b2a49", in.stroke = "#1b2a49";
  st.fill = "#ffffff", st.stroke = "#d62728", st.stroke_width = std::max(0.8, r / 2.5);
  for (int pass = 0; pass < 2; ++pass) {  // Steiner vertices first, inputs on top
    d.begin_group({{"class", pass ? "inputs" : "steiner"}});
    for (const auto& v : vs)
      if (v.is_steiner == (pass == 0))
        d.circle(X(v.x[0]), Y(v.x[1]), pass ? r * 1.15 : r, pass ? in : st,
                 {{"class", pass ? "input" : "steiner"}, {"data-x", svg::exact_number(v.x[0])}, {"data-y", svg::exact_number(v.x[1])}});
    d.end_group();
  }
  svg::Style frame;
  frame.stroke = "#333";
  d.rect(X(0), Y(1), X(1) - X(0), Y(0) - Y(1), frame);
  double ly = size + 14;
  d.circle(margin + 6, ly - 4, 4, in);
  svg::TextStyle t;
  t.size = 12;
  d.text(margin + 16, ly, std::to_string(inputs) + " input vertices", t);
  d.circle(margin + 186, ly - 4, 4, st);
  d.text(margin + 196, ly, std::to_string(vs.size() - inputs) + " Steiner vertices", t);
  t.fill = "#555";
  t.size = 11;
  d.text(margin, ly + 20, caption, t);
  return d.str();
}

}  // namespace kmr::cli
