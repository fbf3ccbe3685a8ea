#pragma once

// Stable LSD radix sort on 64-bit keys, shared by the hull algorithms that sort many points.

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink::detail {

// Unsigned bits whose order is the order of the doubles (-0 and +0 end up side by side).
inline std::uint64_t ordered_bits(Real value) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// Sorts `items` by bits [low_bit, high_bit) of key(item), kDigitBits bits a pass; a pass in
// which every item has the same digit is skipped. `buffer` is scratch storage.
template <int kDigitBits = 11, typename T, typename Key>
void radix_sort(std::vector<T>& items, std::vector<T>& buffer, Key key, int low_bit = 0,
                int high_bit = 64) {
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = items.size();
  buffer.resize(n);
  std::array<std::size_t, kBuckets> count;
  for (int shift = low_bit; shift < high_bit; shift += kDigitBits) {
    count.fill(0);
    for (const T& item : items) ++count[(key(item) >> shift) & (kBuckets - 1)];
    if (std::find(count.begin(), count.end(), n) != count.end()) continue;
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const T& item : items) buffer[count[(key(item) >> shift) & (kBuckets - 1)]++] = item;
    items.swap(buffer);
  }
}

}  // namespace mink::detail
