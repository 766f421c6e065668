#pragma once
// Test helpers shared by the kmesh update and KDS tests: the brute-force check failures as one
// string, and stability measured against a from-scratch construction (the thesis claims no
// equality, §4.3, so it is a figure, not a check).
#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kmesh/invariants.hpp"

namespace kmr::kmesh::test {

// "" when every check passed, else "claim: first violation; ..." for each failed one.
inline std::string failures(const std::vector<CheckResult>& rs) {
  std::string s;
  for (auto& r : rs)
    if (!r.ok()) s += r.claim + ": " + r.violations[0] + "; ";
  return s;
}

// The exact positions of the Steiner vertices (satellites) of a mesh.
inline std::set<std::pair<Dyadic, Dyadic>> steiner_positions(const Mesh& m) {
  std::set<std::pair<Dyadic, Dyadic>> s;
  for (std::size_t v = 0; v < m.size(); ++v)
    if (m.info[v].steiner) s.insert({m.spanner.position(int(v))[0], m.spanner.position(int(v))[1]});
  return s;
}

// The fraction of Steiner vertices two meshes share, ÷ the larger count (1 when both have none).
inline double shared_steiner_fraction(const Mesh& a, const Mesh& b) {
  auto sa = steiner_positions(a), sb = steiner_positions(b);
  std::size_t shared = 0;
  for (auto& p : sa) shared += sb.count(p);
  return double(shared) / double(std::max<std::size_t>({sa.size(), sb.size(), 1}));
}

}  // namespace kmr::kmesh::test
