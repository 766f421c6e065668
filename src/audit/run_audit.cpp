#include <chrono>
#include <cstdio>
#include <exception>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "audit/audit.hpp"

namespace kmr::audit {

namespace {
std::string json_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    if (c == '\n') { r += "\\n"; continue; }
    r += c;
  }
  return r;
}
}  // namespace

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

int run_audit(const Options& options, std::ostream& out, std::ostream* json) {
  int failed = 0, run = 0;
  if (json) *json << "[";
  out << std::left << std::setw(28) << "claim" << std::setw(6) << "verdict" << "  check\n";
  for (const Check& check : all_checks()) {
    if (check.claim.rfind(options.only, 0) != 0) continue;
    Verdict v;
    auto start = std::chrono::steady_clock::now();
    try {
      v = check.run(options);
    } catch (const std::exception& e) {
      v.pass = false;
      v.summary = std::string("threw: ") + e.what();
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++run;
    if (!v.pass) ++failed;
    out << std::left << std::setw(28) << check.claim << std::setw(6) << (v.pass ? "PASS" : "FAIL") << "  "
        << check.title << "\n";
    if (!v.summary.empty()) out << std::string(36, ' ') << v.summary << "\n";
    for (auto& [name, value] : v.figures) out << std::string(36, ' ') << name << " = " << value << "\n";
    if (json) {
      *json << (run > 1 ? "," : "") << "\n {\"claim\":\"" << json_escape(check.claim) << "\",\"title\":\""
            << json_escape(check.title) << "\",\"pass\":" << (v.pass ? "true" : "false") << ",\"summary\":\""
            << json_escape(v.summary) << "\",\"seconds\":" << seconds << ",\"figures\":{";
      for (std::size_t i = 0; i < v.figures.size(); ++i)
        *json << (i ? "," : "") << "\"" << json_escape(v.figures[i].first) << "\":\""
              << json_escape(v.figures[i].second) << "\"";
      *json << "}}";
    }
  }
  if (json) *json << "\n]\n";
  out << run - failed << " passed, " << failed << " failed\n";
  return failed == 0 && run > 0 ? 0 : 1;
}

}  // namespace kmr::audit
