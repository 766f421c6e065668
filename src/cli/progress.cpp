#include "cli/progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace kmr::cli {

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

Progress::Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}
Progress::~Progress() { done(); }

void Progress::message(const std::string& what) {
  if (!enabled_) return;
  std::string line = what.substr(0, 100);
  std::fprintf(stderr, "\r%s%s", line.c_str(), std::string(width_ > line.size() ? width_ - line.size() : 0, ' ').c_str());
  std::fflush(stderr);
  width_ = line.size();
  last_ = now();
}

void Progress::step(std::size_t i, std::size_t n, const std::string& what) {
  if (!enabled_) return;
  if (i + 1 < n && last_ >= 0 && now() - last_ < 0.1) return;
  std::string line = "[";
  line += std::to_string(i + 1);
  line += '/';
  line += std::to_string(n);
  line += "] ";
  line += what;
  message(line);
}

bool Progress::due() const { return enabled_ && (last_ < 0 || now() - last_ >= 0.1); }

void Progress::done() {
  if (!enabled_ || width_ == 0) return;
  std::fprintf(stderr, "\r%s\r", std::string(width_, ' ').c_str());
  std::fflush(stderr);
  width_ = 0;
}

}  // namespace kmr::cli
