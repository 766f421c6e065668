#include "cli/args.hpp"

#include "exact/error.hpp"
#include "exact/integer.hpp"

namespace kmr::cli {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
           const std::set<std::string>& switches) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--") {
      positional_.insert(positional_.end(), argv.begin() + static_cast<long>(i) + 1, argv.end());
      return;
    }
    if (a.rfind("--", 0) == 0) {
      std::string name = a.substr(2);
      if (name == "help" || switches.count(name)) {
        flags_.insert(name);
      } else if (valued.count(name)) {
        if (i + 1 >= argv.size()) throw InputError("option --" + name + " needs a value");
        if (values_.count(name)) throw InputError("option --" + name + " is given twice");
        values_[name] = argv[++i];
      } else {
        throw InputError("unknown option '" + a + "' (see --help)");
      }
    } else if (a == "-h") {
      flags_.insert("help");
    } else {
      positional_.push_back(a);
    }
  }
}

std::optional<std::string> Args::value(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

long long Args::integer(const std::string& name, long long fallback, long long min, long long max) const {
  auto v = value(name);
  if (!v) return fallback;
  exact::Integer x = exact::parse_integer(*v);
  if (x < min || x > max)
    throw InputError("--" + name + " " + *v + " is out of range [" + std::to_string(min) + ", " +
                     std::to_string(max) + "]");
  return x.convert_to<long long>();
}

}  // namespace kmr::cli
