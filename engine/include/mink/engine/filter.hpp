#pragma once

#include <cstdint>

namespace mink {

/// Which shapes may touch. Two shapes collide when they share a non-zero group (positive:
/// always, negative: never), or else when each one's category meets the other's mask.
struct Filter {
  std::uint64_t category = 1;              ///< the bits this shape is
  std::uint64_t mask = ~std::uint64_t{0};  ///< the bits this shape collides with
  std::int32_t group = 0;                  ///< 0: none; same positive: always; same negative: never

  bool operator==(const Filter&) const = default;
};

/// @brief The filter rule above, in one place for the step, queries and tests.
inline bool should_collide(const Filter& a, const Filter& b) noexcept {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

}  // namespace mink
