#pragma once

#include <span>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Jarvis march (paper 4.1.2): from the lowest-x point, repeatedly wrap to the point with every
/// other point on its left, the farthest among collinear ones. O(n h).
ConvexHull jarvis_hull(std::span<const Vec2> points);

}  // namespace mink
