#pragma once

#include <cstddef>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

// Support mapping (paper section 5, eq. 4): the vertex of a hull farthest along a direction.
// Directions are in the hull's local frame unless a Pose is given. Ties go to the lowest index
// in the linear scan; the faster searches return a vertex with the same dot product.

// Hulls up to this many vertices are scanned; larger ones are searched in O(log n).
inline constexpr std::size_t kLinearSupportLimit = 16;

// Every vertex, first maximum wins: the obviously-correct twin of the searches below.
std::size_t support_index_linear(const PreparedHull& hull, const Vec2& direction) noexcept;

// Binary search of the direction's pseudo-angle among the sorted edge-normal angles, then a
// short climb to absorb rounding in the pseudo-angles. O(log n).
std::size_t support_index_binary(const PreparedHull& hull, const Vec2& direction) noexcept;

// Hill climbing from `start` (the previous answer): O(1) when the direction changed little,
// O(n) at worst.
std::size_t support_index_climb(const PreparedHull& hull, const Vec2& direction,
                                std::size_t start) noexcept;

// Linear scan for small hulls, binary search for large ones.
inline std::size_t support_index(const PreparedHull& hull, const Vec2& direction) noexcept {
  return hull.size() <= kLinearSupportLimit ? support_index_linear(hull, direction)
                                            : support_index_binary(hull, direction);
}

// The support vertex of the posed hull along a world direction, in world coordinates.
inline Vec2 support_point(const PreparedHull& hull, const Pose& pose, const Vec2& direction) {
  return pose.apply(hull.vertices()[support_index(hull, pose.rotation.apply_inverse(direction))]);
}

}  // namespace mink
