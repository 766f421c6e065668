#pragma once
// §2.2: every input point gets a random priority (seeded); points are inserted in decreasing
// priority order. Guarantees: a pure function of (n, seed); ties (equal 64-bit draws) broken by
// the lower index; the result is a permutation of 0..n−1.
#include <cstdint>
#include <vector>

namespace kmr::hull {

// Priorities drawn from std::mt19937_64(seed), one per index in input order.
std::vector<std::uint64_t> random_priorities(int n, std::uint64_t seed);

// Indices by decreasing priority (p_1, p_2, ..., p_n of §2.2).
std::vector<int> priority_order(const std::vector<std::uint64_t>& priorities);

}  // namespace kmr::hull
