#pragma once

#include <array>
#include <cstdint>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

/// @brief One contact point of a Manifold.
struct ManifoldPoint {
  Vec2 point{0, 0};      ///< world, midway between the two surfaces
  Real separation = 0;   ///< negative when penetrating
  std::uint32_t id = 0;  ///< stable across steps while the same features touch (warm starting)
};

/// @brief The contact between two hulls: a shared normal and up to two points.
struct Manifold {
  Vec2 normal{0, 0};                      ///< unit, world, from A towards B
  std::array<ManifoldPoint, 2> points{};  ///< the first point_count are valid
  int point_count = 0;                    ///< 0, 1 or 2
};

/// Contact manifold of two posed hulls: up to two points, each with its separation. Pairs
/// farther apart than `speculative_distance` give point_count == 0.
/// @param a, b the hulls, in their local frames
/// @param pose_a, pose_b where the hulls are in the world
/// @param speculative_distance largest separation that still yields points (world units)
Manifold collide_hulls(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                       const Pose& pose_b, Real speculative_distance);

}  // namespace mink
