#pragma once

#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "shape_core.hpp"

namespace mink::detail {

// Two disks: one point on the line of centres, closed form.
Manifold collide_circles(const Circle& a, const Pose& pose_a, const Circle& b, const Pose& pose_b,
                         Real speculative_distance);

// A disk (A) and a segment's or a hull's core (B, a capsule, segment or polygon): one point at
// the core's nearest feature to the centre, closed form (the nearest point of the segment, or
// the hull's face of greatest separation and its end vertices' regions), the general path's
// GJK and separating-axis test not needed for a point. The normal points from A to B.
Manifold collide_circle_core(const Circle& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                             Real speculative_distance);

}  // namespace mink::detail
