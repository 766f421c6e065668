#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <limits>

#include "audit/audit.hpp"
#include "exact/error.hpp"

#ifndef KMR_VERSION
#error "KMR_VERSION must be defined by the build (src/audit/CMakeLists.txt)"
#endif

namespace kmr::audit {

namespace {
std::string json_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    if (c == '\n') { r += "\\n"; continue; }
    if (static_cast<unsigned char>(c) < 0x20) {  // JSON forbids raw control characters in strings
      char u[8];
      std::snprintf(u, sizeof u, "\\u%04x", static_cast<unsigned>(c));
      r += u;
      continue;
    }
    r += c;
  }
  return r;
}
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
std::string json_string(const std::string& s) {
  std::string r = "\"";
  r += json_escape(s);
  r += '"';
  return r;
}

void write_series(std::ostream& json, const std::vector<svg::Series>& list) {
  json << "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    json << (i ? "," : "") << "{\"name\":" << json_string(list[i].name) << ",\"points\":[";
    for (std::size_t j = 0; j < list[i].points.size(); ++j)
      json << (j ? "," : "") << "[" << json_number(list[i].points[j].x) << "," << json_number(list[i].points[j].y) << "]";
    json << "]}";
  }
  json << "]";
}
void write_axis(std::ostream& json, const svg::Axis& a) {
  json << "{\"label\":" << json_string(a.label) << ",\"unit\":" << json_string(a.unit) << ",\"log\":" << (a.log ? "true" : "false")
       << ",\"categories\":[";
  for (std::size_t i = 0; i < a.categories.size(); ++i) json << (i ? "," : "") << json_string(a.categories[i]);
  json << "]}";
}
}  // namespace

const char* version() { return KMR_VERSION; }

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

bool selected(const std::string& claim, const std::string& only) {
  if (!only.empty() && only.back() == '$') return claim == only.substr(0, only.size() - 1);
  return claim.rfind(only, 0) == 0;
}

std::vector<Check> select_checks(const Options& options) {
  std::vector<Check> chosen;
  std::string known;
  for (Check& check : all_checks()) {
    if (!known.empty()) known += ", ";
    known += check.claim;
    if (selected(check.claim, options.only)) chosen.push_back(std::move(check));
  }
  if (chosen.empty())
    throw InputError("no claim matches --only '" + options.only +
                     "'; known claim IDs (any prefix works, e.g. 'T3.' or 'A2.1'; 'ID$' matches exactly ID): " + known);
  return chosen;
}

std::vector<Result> run_checks(const Options& options) {
  std::vector<Check> chosen = select_checks(options);
  std::vector<Result> results;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const Check& check = chosen[i];
    if (options.progress) options.progress(i, chosen.size(), check.claim);
    Result r;
    r.claim = check.claim, r.title = check.title;
    auto start = std::chrono::steady_clock::now();
    try {
      r.verdict = check.run(options);
    } catch (const std::exception& e) {
      r.verdict.pass = false;
      r.verdict.summary = std::string("threw: ") + e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    results.push_back(std::move(r));
  }
  if (options.progress) options.progress(chosen.size(), chosen.size(), "");
  return results;
}

const char* verdict_word(const Verdict& v) {
  if (!v.pass) return "FAIL";
  if (v.target_met.has_value() && !*v.target_met) return "MISSED";
  return "PASS";
}

void print_table(const std::vector<Result>& results, std::ostream& out) {
  int failed = 0, missed = 0;
  std::size_t w = 28;  // the claim column fits the longest ID
  for (const Result& r : results) w = std::max(w, r.claim.size() + 2);
  const std::string indent(w + 8, ' ');
  out << std::left << std::setw(int(w)) << "claim" << std::setw(6) << "verdict" << "  check\n";
  for (const Result& r : results) {
    const Verdict& v = r.verdict;
    if (!v.pass) ++failed;
    if (std::string(verdict_word(v)) == "MISSED") ++missed;
    out << std::left << std::setw(int(w)) << r.claim << std::setw(6) << verdict_word(v) << "  " << r.title << "\n";
    if (!v.summary.empty()) out << indent << v.summary << "\n";
    if (v.target_met) out << indent << "target: " << v.target << (*v.target_met ? " (met)" : " (MISSED)") << "\n";
    for (auto& [name, value] : v.figures) out << indent << name << " = " << value << "\n";
  }
  out << results.size() - failed << " passed, " << failed << " failed";
  if (missed) out << " (" << missed << " of the passed missed a stated target: MISSED)";
  out << "\n";
}

void write_json(const std::vector<Result>& results, std::ostream& json) {
  json << "[";
  for (std::size_t k = 0; k < results.size(); ++k) {
    const Result& r = results[k];
    const Verdict& v = r.verdict;
    json << (k ? "," : "") << "\n {\"claim\":" << json_string(r.claim) << ",\"title\":" << json_string(r.title)
         << ",\"pass\":" << (v.pass ? "true" : "false") << ",\"summary\":" << json_string(v.summary)
         << ",\"seconds\":" << json_number(r.seconds) << ",\"kmr_version\":" << json_string(version())
         << ",\"thesis\":" << json_string(v.thesis) << ",\"replay\":" << json_string(r.replay)
         << ",\"verdict\":" << json_string(verdict_word(v)) << ",\"target\":" << json_string(v.target)
         << ",\"target_met\":" << (v.target_met ? (*v.target_met ? "true" : "false") : "null") << ",\"figures\":{";
    for (std::size_t i = 0; i < v.figures.size(); ++i)
      json << (i ? "," : "") << json_string(v.figures[i].first) << ":" << json_string(v.figures[i].second);
    json << "},\"plots\":[";
    for (std::size_t i = 0; i < v.plots.size(); ++i) {
      const svg::Plot& p = v.plots[i];
      json << (i ? "," : "") << "{\"title\":" << json_string(p.title) << ",\"x\":";
      write_axis(json, p.x);
      json << ",\"y\":";
      write_axis(json, p.y);
      json << ",\"series\":";
      write_series(json, p.series);
      json << ",\"bounds\":";
      write_series(json, p.bounds);
      json << "}";
    }
    json << "]}";
  }
  json << "\n]\n";
}

namespace {
double read_number(const std::string& s) {
  if (s == "null") return std::numeric_limits<double>::quiet_NaN();
  std::size_t used = 0;
  double x = std::stod(s, &used);
  if (used != s.size()) throw std::invalid_argument("not a number: '" + s + "'");
  return x;
}
svg::Axis read_axis(const boost::property_tree::ptree& a) {
  svg::Axis r = svg::linear_axis(a.get<std::string>("label"), a.get<std::string>("unit"));
  r.log = a.get<bool>("log");
  for (const auto& [k, c] : a.get_child("categories")) r.categories.push_back(c.data());
  return r;
}
std::vector<svg::Series> read_series(const boost::property_tree::ptree& list) {
  std::vector<svg::Series> out;
  for (const auto& [k, s] : list) {
    svg::Series series{s.get<std::string>("name"), {}};
    for (const auto& [k2, p] : s.get_child("points")) {
      if (p.size() != 2) throw std::invalid_argument("a point needs 2 numbers");
      auto it = p.begin();
      double x = read_number(it->second.data());
      double y = read_number((++it)->second.data());
      series.points.push_back({x, y});
    }
    out.push_back(std::move(series));
  }
  return out;
}
}  // namespace

std::vector<Result> read_json(const std::string& path) {
  static const boost::property_tree::ptree kNoPlots;  // results written before plots existed
  namespace pt = boost::property_tree;
  std::vector<Result> results;
  try {
    pt::ptree root;
    pt::read_json(path, root);
    for (const auto& [key, c] : root) {
      Result r;
      r.claim = c.get<std::string>("claim");
      r.title = c.get<std::string>("title");
      r.verdict.pass = c.get<bool>("pass");
      r.verdict.summary = c.get<std::string>("summary");
      r.verdict.thesis = c.get<std::string>("thesis", "");
      r.replay = c.get<std::string>("replay", "");
      r.verdict.target = c.get<std::string>("target", "");
      std::string met = c.get<std::string>("target_met", "null");  // results written before targets existed: none
      if (met == "true" || met == "false") r.verdict.target_met = met == "true";
      else if (met != "null") throw std::invalid_argument("target_met must be true, false or null, not '" + met + "'");
      r.seconds = read_number(c.get<std::string>("seconds"));
      for (const auto& [name, value] : c.get_child("figures")) r.verdict.figure(name, value.data());
      for (const auto& [k, p] : c.get_child("plots", kNoPlots)) {
        svg::Plot plot;
        plot.title = p.get<std::string>("title");
        plot.x = read_axis(p.get_child("x"));
        plot.y = read_axis(p.get_child("y"));
        plot.series = read_series(p.get_child("series"));
        plot.bounds = read_series(p.get_child("bounds"));
        r.verdict.plot(std::move(plot));
      }
      if (r.claim.empty()) throw std::invalid_argument("a result without a claim ID");
      results.push_back(std::move(r));
    }
  } catch (const std::exception& e) {
    throw InputError("cannot read audit results from '" + path + "': " + e.what());
  }
  if (results.empty()) throw InputError("no audit results in '" + path + "'");
  return results;
}

int status(const std::vector<Result>& results) {
  for (const Result& r : results)
    if (!r.verdict.pass) return 1;
  return results.empty() ? 1 : 0;
}

int run_audit(const Options& options, std::ostream& out, std::ostream* json) {
  auto results = run_checks(options);
  print_table(results, out);
  if (json) write_json(results, *json);
  return status(results);
}

}  // namespace kmr::audit
