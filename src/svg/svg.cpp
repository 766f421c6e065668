#include "svg/svg.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace kmr::svg {

std::string escape(std::string_view s) {
  std::string r;
  r.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': r += "&amp;"; break;
      case '<': r += "&lt;"; break;
      case '>': r += "&gt;"; break;
      case '"': r += "&quot;"; break;
      case '\'': r += "&apos;"; break;
      case '\t': case '\n': case '\r': r += c; break;
      default:  // XML 1.0 has no other control characters, not even escaped: U+FFFD instead
        if (static_cast<unsigned char>(c) < 0x20) r += "\xEF\xBF\xBD";
        else r += c;
    }
  }
  return r;
}

namespace {
std::string print(double x, const char* format) {
  if (!std::isfinite(x)) throw std::invalid_argument("svg: non-finite number");
  if (x == 0) x = 0;  // no "-0"
  char b[40];
  std::snprintf(b, sizeof b, format, x);
  return b;
}
std::string style(const Style& s) {
  std::string r = " stroke=\"" + escape(s.stroke) + "\" fill=\"" + escape(s.fill) + "\"";
  if (s.stroke != "none") r += " stroke-width=\"" + number(s.stroke_width) + "\"";
  if (!s.dash.empty()) r += " stroke-dasharray=\"" + escape(s.dash) + "\"";
  if (s.opacity != 1) r += " opacity=\"" + number(s.opacity) + "\"";
  return r;
}
std::string attributes(const Attributes& a) {
  std::string r;
  for (const auto& [k, v] : a) r += " " + k + "=\"" + escape(v) + "\"";
  return r;
}
std::string points(const std::vector<std::pair<double, double>>& p) {
  std::string r;
  for (std::size_t i = 0; i < p.size(); ++i) r += (i ? " " : "") + number(p[i].first) + "," + number(p[i].second);
  return r;
}
}  // namespace

std::string number(double x) { return print(x, "%.6g"); }
std::string exact_number(double x) { return print(x, "%.17g"); }

Document::Document(double width, double height) : width_(width), height_(height) {
  if (!(width > 0) || !(height > 0)) throw std::invalid_argument("svg: document size must be positive");
}

void Document::line(double x1, double y1, double x2, double y2, const Style& s, const Attributes& extra) {
  body_ += "<line x1=\"" + number(x1) + "\" y1=\"" + number(y1) + "\" x2=\"" + number(x2) + "\" y2=\"" + number(y2) +
           "\"" + style(s) + attributes(extra) + "/>\n";
}
void Document::rect(double x, double y, double w, double h, const Style& s, const Attributes& extra) {
  body_ += "<rect x=\"" + number(x) + "\" y=\"" + number(y) + "\" width=\"" + number(w) + "\" height=\"" + number(h) +
           "\"" + style(s) + attributes(extra) + "/>\n";
}
void Document::circle(double cx, double cy, double r, const Style& s, const Attributes& extra, const std::string& tooltip) {
  body_ += "<circle cx=\"" + number(cx) + "\" cy=\"" + number(cy) + "\" r=\"" + number(r) + "\"" + style(s) + attributes(extra);
  body_ += tooltip.empty() ? "/>\n" : "><title>" + escape(tooltip) + "</title></circle>\n";
}
void Document::polyline(const std::vector<std::pair<double, double>>& p, const Style& s, const Attributes& extra) {
  body_ += "<polyline points=\"" + points(p) + "\"" + style(s) + attributes(extra) + "/>\n";
}
void Document::polygon(const std::vector<std::pair<double, double>>& p, const Style& s, const Attributes& extra) {
  body_ += "<polygon points=\"" + points(p) + "\"" + style(s) + attributes(extra) + "/>\n";
}
void Document::text(double x, double y, const std::string& content, const TextStyle& t) {
  body_ += "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" font-size=\"" + number(t.size) +
           "\" font-family=\"sans-serif\" text-anchor=\"" + escape(t.anchor) + "\" fill=\"" + escape(t.fill) + "\"";
  if (t.bold) body_ += " font-weight=\"bold\"";
  if (t.rotate != 0) body_ += " transform=\"rotate(" + number(t.rotate) + " " + number(x) + " " + number(y) + ")\"";
  body_ += ">" + escape(content) + "</text>\n";
}
void Document::title(const std::string& content) { title_ = content; }
void Document::begin_group(const Attributes& attrs) {
  body_ += "<g" + attributes(attrs) + ">\n";
  ++open_groups_;
}
void Document::end_group() {
  if (open_groups_ == 0) throw std::logic_error("svg: end_group without begin_group");
  body_ += "</g>\n";
  --open_groups_;
}

std::string Document::inline_str() const {
  std::string r = "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + number(width_) + "\" height=\"" +
                  number(height_) + "\" viewBox=\"0 0 " + number(width_) + " " + number(height_) + "\">\n";
  if (!title_.empty()) r += "<title>" + escape(title_) + "</title>\n";
  r += body_;
  for (int i = 0; i < open_groups_; ++i) r += "</g>\n";
  r += "</svg>\n";
  return r;
}
std::string Document::str() const { return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + inline_str(); }

}  // namespace kmr::svg
