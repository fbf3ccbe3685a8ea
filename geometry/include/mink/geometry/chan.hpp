#pragma once

#include <cstddef>
#include <span>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Chan's algorithm (paper 4.1): for t = 1, 2, ...: m = min(2^(2^t), n); Graham hulls of groups
/// of m points; at most m Jarvis steps, each finding the tangent of every group hull by binary
/// search; restart with the next t when the wrap does not close. O(n log h).
///
/// Choices the paper leaves open: points are grouped by angular sector about an interior point
/// (one counting-sort pass), so a wrap step skips groups whose box lies wholly inside the edge
/// found so far; rounds with m below a certified count of hull vertices (extremes in 24
/// directions) are skipped, as they cannot close; the last round's single group is hulled by
/// Graham's scan over the previous round's rings, whose arcs are merged into polar order
/// instead of sorted again.
ConvexHull chan_hull(std::span<const Vec2> points);

namespace detail {
/// Round t's group size, m = min(2^(2^t), limit), without overflowing.
std::size_t chan_group_size(unsigned t, std::size_t limit) noexcept;
}  // namespace detail

}  // namespace mink
