#pragma once

#include <array>
#include <cstdint>

#include "mink/geometry/types.hpp"

namespace mink {

// One vertex of a GJK simplex: a support point of the Minkowski difference A - B and the two
// hull vertices it came from.
struct SimplexVertex {
  Vec2 point{0, 0};  // a - b
  Vec2 a{0, 0};      // vertex of A (world, in query results)
  Vec2 b{0, 0};      // vertex of B (world, in query results)
  std::uint32_t index_a = 0;
  std::uint32_t index_b = 0;
};

// The simplex a GJK query ended with (a point, a segment or a triangle), in world coordinates,
// oldest vertex first. Exposed so pictures can draw it inside the Minkowski difference.
struct Simplex {
  std::array<SimplexVertex, 3> vertices{};
  int count = 0;
};

// The vertex pairs of a previous distance query's final simplex: passed back in, the next query
// on the same pair starts from them and converges in one or two iterations when the poses
// changed little. count == 0 means cold.
struct SimplexCache {
  int count = 0;
  std::array<std::uint32_t, 3> index_a{};
  std::array<std::uint32_t, 3> index_b{};
};

}  // namespace mink
