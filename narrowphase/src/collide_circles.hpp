#pragma once

#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

namespace mink::detail {

// Two disks: one point on the line of centres, closed form.
Manifold collide_circles(const Circle& a, const Pose& pose_a, const Circle& b, const Pose& pose_b,
                         Real speculative_distance);

}  // namespace mink::detail
