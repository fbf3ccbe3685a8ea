#pragma once

#include <span>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Chan's algorithm (paper 4.1): for t = 1, 2, ...: m = min(2^(2^t), n); Graham hulls of groups
/// of m points; at most m Jarvis steps, each finding the tangent of every group hull by binary
/// search; restart with the next t when the wrap does not close. O(n log h).
ConvexHull chan_hull(std::span<const Vec2> points);

}  // namespace mink
