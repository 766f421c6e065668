#pragma once
// Progress of long runs on stderr — only when stderr is a terminal and --quiet was not given; never
// on stdout. One line, rewritten in place with \r, cleared when done, so logs and pipes stay clean.
#include <string>

namespace kmr::cli {

class Progress {
 public:
  // enabled = !quiet && isatty(stderr)
  explicit Progress(bool quiet);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  bool enabled() const { return enabled_; }
  // "[i/n] what" (i counted from 1); at most ~10 redraws a second.
  void step(std::size_t i, std::size_t n, const std::string& what);
  void message(const std::string& what);
  // Whether a redraw is due (enabled, and none in the last ~0.1 s): for callers that build their
  // line only when it will be shown.
  bool due() const;
  void done();

 private:
  bool enabled_;
  std::size_t width_ = 0;
  double last_ = -1;
};

}  // namespace kmr::cli
