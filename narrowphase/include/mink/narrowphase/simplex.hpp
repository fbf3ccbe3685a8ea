#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

/// @brief One vertex of a GJK simplex: a support point of the Minkowski difference A - B and the
/// two hull vertices it came from.
struct SimplexVertex {
  Vec2 point{0, 0};           ///< a - b
  Vec2 a{0, 0};               ///< vertex of A (world, in query results)
  Vec2 b{0, 0};               ///< vertex of B (world, in query results)
  std::uint32_t index_a = 0;  ///< index of `a` among A's vertices
  std::uint32_t index_b = 0;  ///< index of `b` among B's vertices
};

/// @brief A simplex (a point, a segment or a triangle) in world coordinates, oldest vertex first:
/// what pictures draw inside the Minkowski difference.
struct Simplex {
  std::array<SimplexVertex, 3> vertices{};  ///< the first `count` are valid
  int count = 0;                            ///< 0 to 3
};

/// A simplex as the vertex pairs (index into A, index into B) it came from, oldest first.
/// Query results hold their final simplex this way (cheap to fill); world_simplex turns it into
/// points. Passed back into gjk_distance, the next query on the same pair starts from it and
/// converges in one or two iterations when the poses changed little. count == 0 means cold.
struct SimplexCache {
  int count = 0;                           ///< 0 (cold) to 3
  std::array<std::uint32_t, 3> index_a{};  ///< vertex indices into A, oldest first
  std::array<std::uint32_t, 3> index_b{};  ///< vertex indices into B, oldest first

  /// The lowest (A, B) vertex pair of the simplex: names the nearest features independently of
  /// the order GJK found them in (feature ids for warm starting). Needs count >= 1.
  std::array<std::uint32_t, 2> lowest_pair() const noexcept {
    std::array<std::uint32_t, 2> best{index_a[0], index_b[0]};
    for (std::size_t k = 1; k < static_cast<std::size_t>(count); ++k) {
      if (index_a[k] < best[0] || (index_a[k] == best[0] && index_b[k] < best[1])) {
        best = {index_a[k], index_b[k]};
      }
    }
    return best;
  }
};

/// @brief The points of an index-pair simplex for the posed hulls.
Simplex world_simplex(const SimplexCache& indices, const PreparedHull& a, const Pose& pose_a,
                      const PreparedHull& b, const Pose& pose_b);

}  // namespace mink
