#include "audit/audit.hpp"

namespace kmr::audit {

std::vector<Check> all_checks() {
  std::vector<Check> checks;
  for (auto list : {roots_checks, kinetic_checks, sac_checks, wellspaced_checks, kmesh_checks})
    for (auto& c : list()) checks.push_back(std::move(c));
  for (auto& c : hull_checks()) checks.push_back(std::move(c));
  return checks;
}

}  // namespace kmr::audit
