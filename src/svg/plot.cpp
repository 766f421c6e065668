#include "svg/plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "svg/svg.hpp"

namespace kmr::svg {

std::optional<Series> proportional_bound(const std::string& name, const Series& s, bool upper) {
  std::optional<double> c;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
  for (const XY& p : s.points) {
    if (!(p.x > 0) || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    double r = p.y / p.x;
    c = !c ? r : upper ? std::max(*c, r) : std::min(*c, r);
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
  }
  if (!c) return std::nullopt;
  return Series{name, {{x0, *c * x0}, {x1, *c * x1}}};
}

Axis linear_axis(std::string label, std::string unit) {
  Axis a;
  a.label = std::move(label), a.unit = std::move(unit);
  return a;
}
Axis log_axis(std::string label, std::string unit) {
  Axis a = linear_axis(std::move(label), std::move(unit));
  a.log = true;
  return a;
}
Axis category_axis(std::string label, std::vector<std::string> categories) {
  Axis a = linear_axis(std::move(label));
  a.categories = std::move(categories);
  return a;
}

Series constant_bound(const std::string& name, double c, double x0, double x1) { return Series{name, {{x0, c}, {x1, c}}}; }

namespace {

Style style(std::string stroke, std::string fill, double width = 1, std::string dash = "") {
  Style s;
  s.stroke = std::move(stroke), s.fill = std::move(fill), s.stroke_width = width, s.dash = std::move(dash);
  return s;
}
TextStyle text_style(double size, std::string anchor = "start", double rotate = 0, std::string fill = "#222", bool bold = false) {
  TextStyle t;
  t.size = size, t.anchor = std::move(anchor), t.rotate = rotate, t.fill = std::move(fill), t.bold = bold;
  return t;
}

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

// An axis's range and ticks in data units (log axes: in log10 units).
struct Scale {
  double lo = 0, hi = 1;
  bool log = false;
  std::vector<double> ticks;
  double map(double v, double from, double to) const {
    double t = ((log ? std::log10(v) : v) - lo) / (hi - lo);
    return from + t * (to - from);
  }
};

double nice_step(double span, int target) {
  double raw = span / target, mag = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) return m * mag;
  return 10 * mag;
}

Scale make_scale(std::vector<double> v, const Axis& a, bool is_x) {
  Scale s;
  s.log = a.log;
  if (is_x && !a.categories.empty()) {
    s.lo = -0.5, s.hi = double(a.categories.size()) - 0.5;
    for (std::size_t i = 0; i < a.categories.size(); ++i) s.ticks.push_back(double(i));
    return s;
  }
  if (s.log)
    for (double& x : v) x = std::log10(x);
  double lo = v.empty() ? 0 : *std::min_element(v.begin(), v.end());
  double hi = v.empty() ? 1 : *std::max_element(v.begin(), v.end());
  if (s.log) {
    s.lo = std::floor(lo - 0.05), s.hi = std::ceil(hi + 0.05);  // nothing drawn on the frame
    if (s.hi == s.lo) s.hi += 1;
    for (double t = s.lo; t <= s.hi + 1e-9; t += 1) s.ticks.push_back(t);
    return s;
  }
  if (!is_x && lo > 0 && lo < 0.6 * hi) lo = 0;  // a y axis from 0 when the data are not far from it
  if (hi == lo) lo -= std::max(1.0, std::fabs(lo) * 0.1), hi += std::max(1.0, std::fabs(hi) * 0.1);
  if (is_x) lo -= 0.02 * (hi - lo), hi += 0.02 * (hi - lo);  // markers off the axes
  double step = nice_step(hi - lo, 5);
  s.lo = std::floor(lo / step) * step, s.hi = std::ceil(hi / step) * step;
  for (double t = s.lo; t <= s.hi + step * 1e-9; t += step) s.ticks.push_back(std::fabs(t) < step * 1e-9 ? 0 : t);
  return s;
}

bool drawable(const XY& p, const Plot& plot) {
  return std::isfinite(p.x) && std::isfinite(p.y) && (!plot.x.log || p.x > 0) && (!plot.y.log || p.y > 0);
}

std::string tick_text(double t, const Scale& s) {
  if (s.log) return "1e" + number(t);
  return number(t);
}

}  // namespace

std::string render(const Plot& plot, double width, double height) {
  // the legend goes below the axes, one line per series and bound (long names never clip)
  const std::size_t entries = plot.series.size() + plot.bounds.size();
  const double left = 72, right = 24, top = 34, bottom = 54, legend_height = 18.0 * double(entries) + 8;
  const double x0 = left, x1 = width - right, y0 = height - bottom, y1 = top;
  std::vector<double> xs, ys;
  std::size_t hidden = 0;
  for (const auto* list : {&plot.series, &plot.bounds})
    for (const Series& s : *list)
      for (const XY& p : s.points) {
        if (!drawable(p, plot)) {
          if (list == &plot.series) ++hidden;
          continue;
        }
        xs.push_back(p.x), ys.push_back(p.y);
      }
  Scale sx = make_scale(xs, plot.x, true), sy = make_scale(ys, plot.y, false);
  auto X = [&](double v) { return sx.map(v, x0, x1); };
  auto Y = [&](double v) { return sy.map(v, y0, y1); };

  Document d(width, height + legend_height);
  d.title(plot.title);
  d.rect(0, 0, width, height + legend_height, style("none", "#ffffff"));
  d.text(width / 2, 20, plot.title, text_style(14, "middle", 0, "#222", true));
  // grid and ticks
  Style grid = style("#e4e4e4", "none", 1);
  Style axis = style("#444", "none", 1.2);
  for (double t : sy.ticks) {
    d.line(x0, Y(sy.log ? std::pow(10, t) : t), x1, Y(sy.log ? std::pow(10, t) : t), grid);
    d.text(x0 - 6, Y(sy.log ? std::pow(10, t) : t) + 4, tick_text(t, sy), text_style(11, "end"));
  }
  for (double t : sx.ticks) {
    double v = sx.log ? std::pow(10, t) : t;
    d.line(X(v), y0, X(v), y1, grid);
    std::string label = !plot.x.categories.empty() ? plot.x.categories[std::size_t(t)] : tick_text(t, sx);
    d.text(X(v), y0 + 16, label, text_style(11, "middle"));
  }
  d.line(x0, y0, x1, y0, axis);
  d.line(x0, y0, x0, y1, axis);
  d.text((x0 + x1) / 2, height - 14, plot.x.text(), text_style(12, "middle"));
  d.text(18, (y0 + y1) / 2, plot.y.text(), text_style(12, "middle", -90));

  // series, then bounds; legend below
  double ly = height + 4;
  auto legend = [&](const std::string& name, const Style& s, bool marker) {
    d.line(x0, ly, x0 + 24, ly, s);
    if (marker) d.circle(x0 + 12, ly, 3.5, style(s.stroke, s.stroke));
    d.text(x0 + 32, ly + 4, name, text_style(11));
    ly += 18;
  };
  std::size_t colour = 0;
  for (const Series& s : plot.series) {
    std::string c = kColours[colour++ % (sizeof kColours / sizeof *kColours)];
    std::vector<std::pair<double, double>> line;
    for (const XY& p : s.points)
      if (drawable(p, plot)) line.emplace_back(X(p.x), Y(p.y));
    d.begin_group({{"class", "series"}, {"data-series", s.name}});
    if (line.size() > 1 && plot.x.categories.empty()) d.polyline(line, style(c, "none", 1.5));
    for (const XY& p : s.points)
      if (drawable(p, plot))
        d.circle(X(p.x), Y(p.y), 3.5, style(c, c),
                 {{"class", "pt"}, {"data-series", s.name}, {"data-x", exact_number(p.x)}, {"data-y", exact_number(p.y)}},
                 s.name + ": (" + number(p.x) + ", " + number(p.y) + ")");
    d.end_group();
    legend(s.name, style(c, "none", 1.5), true);
  }
  const char* const dashes[] = {"6 4", "2 3", "10 3 2 3", "12 6"};
  std::size_t bound_no = 0;
  for (const Series& s : plot.bounds) {
    std::vector<std::pair<double, double>> line;
    for (const XY& p : s.points)
      if (drawable(p, plot)) line.emplace_back(X(p.x), Y(p.y));
    Style st = style("#555", "none", 1.5, dashes[bound_no++ % 4]);
    if (line.size() > 1) d.polyline(line, st, {{"class", "bound"}, {"data-series", s.name}});
    legend(s.name, st, false);
  }
  if (hidden) d.text(x1, top - 6, std::to_string(hidden) + " point(s) not drawable", text_style(11, "end", 0, "#a00"));
  return d.str();
}

}  // namespace kmr::svg
