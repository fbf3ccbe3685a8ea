#pragma once

// Union-find over indices 0..n-1, each set named by its smallest member: the sleep islands
// (island.cpp) and the bodies a diverged solve stops with it (divergence.cpp).

#include <algorithm>
#include <cstdint>
#include <vector>

namespace mink::detail {

// The set `i` is in, halving the path on the way.
inline std::uint32_t find_set(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Puts the sets of `a` and `b` together, under the smaller root.
inline void join_sets(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
  a = find_set(parent, a);
  b = find_set(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace mink::detail
