#pragma once

#include <optional>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

/// @brief Where a ray first meets a hull, in world coordinates.
struct RayHit {
  Real fraction = 0;  ///< of the translation, in [0, 1]
  Vec2 point{0, 0};   ///< origin + fraction * translation
  Vec2 normal{0, 0};  ///< unit, outward from the hull at the hit
};

/// First hit of the segment origin -> origin + translation against a posed hull, entering
/// from outside. A ray starting inside the hull does not hit it (as in Box2D). Clips the segment
/// against each edge's half plane.
/// @param hull the hull in local coordinates
/// @param pose places the hull in the world
/// @param origin, translation the segment, world coordinates
/// @return the hit, or nothing when the segment misses or starts inside
std::optional<RayHit> ray_cast_hull(const ConvexHull& hull, const Pose& pose, const Vec2& origin,
                                    const Vec2& translation);

/// @brief True when `point` (world) lies inside or on the posed hull.
bool hull_contains(const ConvexHull& hull, const Pose& pose, const Vec2& point);

}  // namespace mink
