#pragma once

#include <optional>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

struct RayHit {
  Real fraction = 0;  // of the translation, in [0, 1]
  Vec2 point{0, 0};
  Vec2 normal{0, 0};  // unit, outward from the hull at the hit
};

// First hit of the segment origin -> origin + translation against a posed hull, entering from
// outside. A ray starting inside the hull does not hit it (as in Box2D). Clips the segment
// against each edge's half plane.
std::optional<RayHit> ray_cast_hull(const ConvexHull& hull, const Pose& pose, const Vec2& origin,
                                    const Vec2& translation);

// True when `point` lies inside or on the posed hull.
bool hull_contains(const ConvexHull& hull, const Pose& pose, const Vec2& point);

}  // namespace mink
