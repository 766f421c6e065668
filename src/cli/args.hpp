#pragma once
// Minimal argument parsing shared by every `kmr` command: `--name value` options, `--flag`
// switches, positionals, and `--` after which everything is positional (so negative numbers pass).
// Guarantees: an unknown option, a repeated option, a missing value or a malformed number throws
// InputError naming it.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace kmr::cli {

class Args {
 public:
  // `valued` lists the options that take a value, `switches` those that do not.
  Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
       const std::set<std::string>& switches);
  bool has(const std::string& name) const { return values_.count(name) || flags_.count(name); }
  std::optional<std::string> value(const std::string& name) const;
  long long integer(const std::string& name, long long fallback, long long min, long long max) const;
  const std::vector<std::string>& positional() const { return positional_; }
  bool help() const { return flags_.count("help") > 0; }

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_;
  std::vector<std::string> positional_;
};

}  // namespace kmr::cli
