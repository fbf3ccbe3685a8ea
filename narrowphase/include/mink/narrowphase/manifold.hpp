#pragma once

#include <array>
#include <cstdint>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

struct ManifoldPoint {
  Vec2 point{0, 0};      // world, midway between the two surfaces
  Real separation = 0;   // negative when penetrating
  std::uint32_t id = 0;  // stable across steps while the same features touch (warm starting)
};

struct Manifold {
  Vec2 normal{0, 0};  // unit, world, from A towards B
  std::array<ManifoldPoint, 2> points{};
  int point_count = 0;
};

// Contact manifold of two posed hulls: up to two points, each with its separation. Pairs
// farther apart than `speculative_distance` give point_count == 0.
Manifold collide_hulls(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                       const Pose& pose_b, Real speculative_distance);

}  // namespace mink
