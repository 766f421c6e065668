#include "hull/priorities.hpp"

#include <algorithm>
#include <numeric>
#include <random>

namespace kmr::hull {

std::vector<std::uint64_t> random_priorities(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint64_t> pr(static_cast<std::size_t>(n));
  for (auto& p : pr) p = rng();
  return pr;
}

std::vector<int> priority_order(const std::vector<std::uint64_t>& pr) {
  std::vector<int> order(pr.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pr[a] != pr[b] ? pr[a] > pr[b] : a < b; });
  return order;
}

}  // namespace kmr::hull
