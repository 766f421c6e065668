#include "hull/priorities.hpp"

#include <array>
#include <random>

namespace kmr::hull {

std::vector<std::uint64_t> random_priorities(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint64_t> pr(static_cast<std::size_t>(n));
  for (auto& p : pr) p = rng();
  return pr;
}

// A stable LSD radix sort (8 passes of 8 bits) on the key ~priority: decreasing priority, equal
// priorities in increasing index order — the order of std::sort with that comparison, in O(n).
std::vector<int> priority_order(const std::vector<std::uint64_t>& pr) {
  const std::size_t n = pr.size();
  std::vector<std::uint64_t> key(n), key2(n);
  std::vector<int> order(n), order2(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = ~pr[i], order[i] = static_cast<int>(i);
  for (int shift = 0; shift < 64; shift += 8) {
    std::array<std::size_t, 257> count{};
    for (std::size_t i = 0; i < n; ++i) ++count[((key[i] >> shift) & 0xff) + 1];
    for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t at = count[(key[i] >> shift) & 0xff]++;
      key2[at] = key[i], order2[at] = order[i];
    }
    key.swap(key2), order.swap(order2);
  }
  return order;
}

}  // namespace kmr::hull
