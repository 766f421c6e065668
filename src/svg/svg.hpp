#pragma once
// A small SVG 1.1 writer of the project's own: the plots of `kmr audit --report` and the pictures of
// `kmr wellspaced --svg` (and later `kmr hull`, `kmr kmesh`) are drawn with it. It is the lowest
// layer (no kmr dependency), so the audit and the CLI can both use it.
// Guarantees (tests/svg): str() is a complete, well-formed XML document (xmllint parses it) with
// the SVG namespace and a viewBox; every text and attribute value is XML-escaped; numbers are
// written in the C locale, never as nan/inf (a non-finite coordinate throws std::invalid_argument).
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kmr::svg {

// XML escaping of & < > " ' (text and attribute values); control characters other than tab and
// line breaks, which XML 1.0 cannot hold, become U+FFFD.
std::string escape(std::string_view s);
// A coordinate or length: up to 6 significant digits, C locale; throws on nan/inf.
std::string number(double x);
// A data value written so that it reads back to the same double (%.17g); throws on nan/inf.
std::string exact_number(double x);

struct Style {
  std::string stroke = "none";
  std::string fill = "none";
  double stroke_width = 1;
  std::string dash;      // stroke-dasharray, e.g. "6 3"; empty for a solid line
  double opacity = 1;    // fill and stroke opacity
};

struct TextStyle {
  double size = 12;
  std::string anchor = "start";  // start | middle | end
  double rotate = 0;             // degrees, about (x, y)
  std::string fill = "#222";
  bool bold = false;
};

using Attributes = std::vector<std::pair<std::string, std::string>>;  // extra attributes, escaped on output

// One SVG document, y pointing down, user units = pixels of width × height.
class Document {
 public:
  Document(double width, double height);
  double width() const { return width_; }
  double height() const { return height_; }

  void line(double x1, double y1, double x2, double y2, const Style& s, const Attributes& extra = {});
  void rect(double x, double y, double w, double h, const Style& s, const Attributes& extra = {});
  void circle(double cx, double cy, double r, const Style& s, const Attributes& extra = {},
              const std::string& tooltip = "");
  void polyline(const std::vector<std::pair<double, double>>& points, const Style& s, const Attributes& extra = {});
  void polygon(const std::vector<std::pair<double, double>>& points, const Style& s, const Attributes& extra = {});
  void text(double x, double y, const std::string& content, const TextStyle& t = {});
  void title(const std::string& content);  // the document's <title> (accessible name)
  void begin_group(const Attributes& attrs);
  void end_group();

  // The complete document (XML declaration, <svg> root with xmlns, width, height, viewBox).
  std::string str() const;
  // The same without the XML declaration, for inlining into HTML.
  std::string inline_str() const;

 private:
  double width_, height_;
  std::string title_;
  std::string body_;
  int open_groups_ = 0;
};

}  // namespace kmr::svg
