#pragma once

#include <span>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Andrew's monotone chain: sort by (x, y), then lower and upper chains. O(n log n); the plain
/// baseline every other algorithm is tested against.
ConvexHull monotone_chain_hull(std::span<const Vec2> points);

}  // namespace mink
