// The SVG writer and plots (src/svg): documents parse as XML (xmllint), text is escaped, and a
// plot's markers carry exactly the points it was given (read back with an XML parser that shares
// no code with the writer: Boost.PropertyTree).
#include <gtest/gtest.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include "svg/plot.hpp"
#include "svg/svg.hpp"

namespace {

using namespace kmr::svg;
namespace pt = boost::property_tree;

bool xmllint_accepts(const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / ("kmr_svg_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                                       std::to_string(std::rand()) + ".svg");
  std::ofstream(path) << text;
  int rc = std::system(("xmllint --noout '" + path.string() + "' 2>/dev/null").c_str());
  std::filesystem::remove(path);
  return rc == 0;
}

struct Marker {
  std::string series;
  double x, y;
};
void collect(const pt::ptree& node, std::vector<Marker>& out, int& bounds) {
  for (const auto& [name, child] : node) {
    if (name == "circle" && child.get("<xmlattr>.class", "") == "pt")
      out.push_back({child.get<std::string>("<xmlattr>.data-series"), std::stod(child.get<std::string>("<xmlattr>.data-x")),
                     std::stod(child.get<std::string>("<xmlattr>.data-y"))});
    if (name == "polyline" && child.get("<xmlattr>.class", "") == "bound") ++bounds;
    collect(child, out, bounds);
  }
}
std::vector<Marker> markers(const std::string& svg, int* bounds = nullptr) {
  std::istringstream in(svg);
  pt::ptree tree;
  pt::read_xml(in, tree);
  std::vector<Marker> out;
  int b = 0;
  collect(tree, out, b);
  if (bounds) *bounds = b;
  return out;
}

TEST(Svg, EscapesMarkupInTextAndAttributes) {
  EXPECT_EQ(escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  EXPECT_EQ(escape("a\x01" "b\tc"), "a\xEF\xBF\xBD" "b\tc");
  Document ctl(10, 10);
  ctl.text(1, 1, "bell\x07 and escape\x1b[0m");
  EXPECT_TRUE(xmllint_accepts(ctl.str())) << ctl.str();
  Document d(100, 50);
  d.title("<title> & co");
  d.text(1, 2, "x < y && \"z\"");
  d.circle(5, 5, 1, Style{}, {{"data-name", "a\"b<c"}}, "tip <>");
  std::string s = d.str();
  EXPECT_TRUE(xmllint_accepts(s)) << s;
  EXPECT_EQ(s.find("x < y"), std::string::npos);
  EXPECT_NE(s.find("viewBox=\"0 0 100 50\""), std::string::npos);
  EXPECT_NE(s.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
}

TEST(Svg, NumbersAreFiniteAndRoundTrip) {
  EXPECT_THROW(number(std::nan("")), std::invalid_argument);
  EXPECT_THROW(exact_number(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_EQ(number(-0.0), "0");
  for (double x : {0.1, 1.0 / 3, 1e-300, 123456789.125, -2.5e17}) EXPECT_EQ(std::stod(exact_number(x)), x);
  Document d(10, 10);
  EXPECT_THROW(d.line(0, 0, std::nan(""), 1, Style{}), std::invalid_argument);
  EXPECT_THROW(Document(0, 1), std::invalid_argument);
}

TEST(Svg, OpenGroupsAreClosedAndUnbalancedEndThrows) {
  Document d(10, 10);
  d.begin_group({{"class", "a"}});
  d.begin_group({});
  EXPECT_TRUE(xmllint_accepts(d.str()));
  d.end_group();
  d.end_group();
  EXPECT_THROW(d.end_group(), std::logic_error);
}

TEST(Plot, MarkersCarryExactlyTheGivenPoints) {
  Plot p;
  p.title = "ops <per> update & more";
  p.x = linear_axis("log2 Δ", "bits");
  p.y = linear_axis("operations");
  p.series = {{"a", {{10, 1.0 / 3}, {20, 2.75}, {30, 1e5}}}, {"b \"quoted\"", {{10, -4}, {15, 0.1}}}};
  auto b = proportional_bound("c x", p.series[0], true);
  ASSERT_TRUE(b);
  p.bounds.push_back(*b);
  p.bounds.push_back(constant_bound("one", 1, 10, 30));
  std::string s = render(p);
  ASSERT_TRUE(xmllint_accepts(s)) << s;
  int bounds = 0;
  auto m = markers(s, &bounds);
  ASSERT_EQ(m.size(), 5u);
  std::size_t k = 0;
  for (const auto& series : p.series)
    for (const auto& pt : series.points) {
      EXPECT_EQ(m[k].series, series.name);
      EXPECT_EQ(m[k].x, pt.x);
      EXPECT_EQ(m[k].y, pt.y);
      ++k;
    }
  EXPECT_EQ(bounds, 2);
}

// Where a marker is drawn, not only what it says: the pixel position is a strictly increasing
// affine function of x (of log10 x on a log axis), a strictly decreasing one of y (SVG y points
// down), and inside the document. Read back from cx/cy with Boost.PropertyTree.
void expect_affine(const std::vector<std::pair<double, double>>& data_px, bool increasing) {
  ASSERT_GE(data_px.size(), 3u);
  auto [d0, p0] = data_px.front();
  auto [d1, p1] = data_px.back();
  double slope = (p1 - p0) / (d1 - d0);
  EXPECT_TRUE(increasing ? slope > 0 : slope < 0) << slope;
  for (auto [d, px] : data_px) EXPECT_NEAR(px, p0 + slope * (d - d0), 0.01) << d;  // 6 significant digits
}
void check_positions(const Plot& p) {
  std::istringstream in(render(p));
  pt::ptree tree;
  pt::read_xml(in, tree);
  double w = tree.get<double>("svg.<xmlattr>.width"), h = tree.get<double>("svg.<xmlattr>.height");
  std::vector<std::pair<double, double>> xs, ys;
  std::function<void(const pt::ptree&)> walk = [&](const pt::ptree& n) {
    for (const auto& [name, c] : n) {
      if (name == "circle" && c.get("<xmlattr>.class", "") == "pt") {
        double x = std::stod(c.get<std::string>("<xmlattr>.data-x")), y = std::stod(c.get<std::string>("<xmlattr>.data-y"));
        double cx = c.get<double>("<xmlattr>.cx"), cy = c.get<double>("<xmlattr>.cy");
        EXPECT_TRUE(cx > 0 && cx < w && cy > 0 && cy < h) << cx << "," << cy;
        xs.emplace_back(p.x.log ? std::log10(x) : x, cx);
        ys.emplace_back(p.y.log ? std::log10(y) : y, cy);
      }
      walk(c);
    }
  };
  walk(tree);
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  expect_affine(xs, true);
  expect_affine(ys, false);
}
TEST(Plot, MarkersAreDrawnWhereTheirDataSays) {
  Plot p;
  p.x = linear_axis("n");
  p.y = linear_axis("ops");
  p.series = {{"a", {{10, 3}, {20, 2.75}, {35, 100}, {80, -4}}}};
  check_positions(p);
  p.x = log_axis("n");
  p.y = log_axis("time", "s");
  p.series = {{"a", {{10, 3e-6}, {1e3, 2.75}, {2e5, 100}}}, {"b", {{50, 1e-3}}}};
  p.bounds = {constant_bound("limit", 0.5, 10, 2e5)};
  check_positions(p);
}

TEST(Plot, ProportionalBoundIsTheTightestThroughTheOrigin) {
  Series s{"s", {{10, 40}, {20, 100}, {40, 120}, {0, 7}}};  // y/x = 4, 5, 3; x = 0 ignored
  auto up = proportional_bound("u", s, true), lo = proportional_bound("l", s, false);
  ASSERT_TRUE(up && lo);
  EXPECT_EQ(up->points.front().x, 10);
  EXPECT_EQ(up->points.back().x, 40);
  EXPECT_EQ(up->points.back().y, 200);  // 5 · 40
  EXPECT_EQ(lo->points.front().y, 30);  // 3 · 10
  EXPECT_FALSE(proportional_bound("none", Series{"e", {{0, 1}}}, true));
}

TEST(Plot, UndrawablePointsAreLeftOutAndCounted) {
  Plot p;
  p.title = "log";
  p.x = category_axis("program", {"map", "sum"});
  p.y = log_axis("speedup");
  p.series = {{"s", {{0, 100}, {1, 0}}}, {"t", {{0, std::numeric_limits<double>::quiet_NaN()}, {1, 1e4}}}};
  std::string s = render(p);
  ASSERT_TRUE(xmllint_accepts(s)) << s;
  auto m = markers(s);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].y, 100);
  EXPECT_EQ(m[1].y, 1e4);
  EXPECT_NE(s.find("2 point(s) not drawable"), std::string::npos);
  EXPECT_NE(s.find(">map<"), std::string::npos);
  // an empty plot is still a valid document
  Plot empty;
  EXPECT_TRUE(xmllint_accepts(render(empty)));
}


// Issue 13 §2 (found by coverage/run.sh): the degenerate plots the audit can produce.
TEST(Plot, ProportionalBoundSkipsPointsItCannotScale) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  Series s{"m", {{0, 5}, {-1, 3}, {2, 4}, {4, 4}, {nan, 1}, {1, inf}, {inf, 1}}};
  // only (2, 4) and (4, 4) count: ratios 2 and 1, drawn over x in [2, 4]
  auto up = proportional_bound("c·x", s, true), down = proportional_bound("c·x", s, false);
  ASSERT_TRUE(up && down);
  ASSERT_EQ(up->points.size(), 2u);
  EXPECT_EQ(up->points[0].x, 2);
  EXPECT_EQ(up->points[0].y, 4);
  EXPECT_EQ(up->points[1].x, 4);
  EXPECT_EQ(up->points[1].y, 8);
  EXPECT_EQ(down->points[0].y, 2);
  EXPECT_EQ(down->points[1].y, 4);
  EXPECT_FALSE(proportional_bound("none", Series{"m", {{0, 1}, {-2, 3}, {nan, 1}}}, true));
  Series c = constant_bound("k", 3, 1, 5);
  EXPECT_EQ(c.points.size(), 2u);
  EXPECT_EQ(c.points[1].y, 3);
}

TEST(Plot, DegeneratePlotsDrawExactlyTheDrawablePoints) {
  // One point (zero span on both axes), linear and log; a log axis with non-positive values (not
  // drawable: counted in a note, never a marker or a NaN coordinate).
  for (bool log : {false, true}) {
    Plot p;
    p.title = log ? "log" : "linear";
    p.x = log ? log_axis("n") : linear_axis("n", "points");
    p.y = log ? log_axis("t", "s") : linear_axis("t");
    p.series = {{"one", {{10, 10}}}, {"bad", {{0, 1}, {5, -1}, {std::nan(""), 2}}}};
    p.bounds = {constant_bound("k", 10, 10, 10)};
    std::string s = render(p);
    ASSERT_TRUE(xmllint_accepts(s)) << s;
    EXPECT_EQ(s.find("nan"), std::string::npos) << s;
    auto m = markers(s);
    std::size_t want = log ? 1 : 3;  // linear: (0, 1) and (5, -1) are drawable, NaN never
    ASSERT_EQ(m.size(), want) << p.title;
    EXPECT_EQ(m[0].series, "one");
    EXPECT_EQ(m[0].x, 10);
    std::string note = log ? "3 point(s) not drawable" : "1 point(s) not drawable";  // log: x, y > 0 too
    EXPECT_NE(s.find(note), std::string::npos) << p.title;
  }
  EXPECT_THROW(Document(0, 10), std::invalid_argument);
  EXPECT_THROW(Document(10, -1), std::invalid_argument);
  EXPECT_THROW(Document(std::nan(""), 10), std::invalid_argument);
}

}  // namespace
