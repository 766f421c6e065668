#pragma once
// An output file named by an option (--svg FILE): opened before the run, so that a bad path fails
// fast, and removed again unless the command commits it, so that a run that fails (an error, a
// failed --check) leaves no empty or half-written picture behind. Only a regular file is ever
// removed: `--svg /dev/null`, `/dev/stdout` (a symbolic link) or a FIFO stay (as root, removing them
// would unlink the device node or the link itself).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <string>

#include "exact/error.hpp"

namespace kmr::cli {

class OutputFile {
 public:
  OutputFile() = default;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() {
    if (!out_.is_open()) return;
    out_.close();
    discard();
  }
  // Opens PATH for writing; `what` names the option in the error ("--svg").
  void open(const std::string& path, const std::string& what) {
    path_ = path;
    what_ = what;
    out_.open(path);
    if (!out_) throw InputError("cannot write " + what + " file '" + path + "'");
  }
  bool is_open() const { return out_.is_open(); }
  std::ostream& stream() { return out_; }
  // Flushes and closes the file and keeps it; throws InputError if writing failed.
  void commit() {
    out_.flush();
    bool good = static_cast<bool>(out_);
    out_.close();
    if (!good) {
      discard();
      throw InputError("cannot write " + what_ + " file '" + path_ + "'");
    }
  }

 private:
  void discard() const {
    std::error_code ec;
    if (std::filesystem::symlink_status(path_, ec).type() == std::filesystem::file_type::regular)
      std::remove(path_.c_str());
  }
  std::string path_, what_;
  std::ofstream out_;
};

}  // namespace kmr::cli
