#pragma once

#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

/// Melkman's deque hull (paper 4.2.1) of a simple polyline; here the polyline is a point
/// sequence sorted by (x, y), which is x-monotone and so simple. Linear time. Returns the CCW,
/// strictly convex ring starting at the first point: 1 or 2 vertices when the points are
/// degenerate.
/// @throws InvalidArgumentError if the points are not sorted.
std::vector<Vec2> melkman_sorted_chain_hull(std::span<const Vec2> sorted_points);

namespace detail {
/// Same, without the sortedness check (callers sorted the points themselves).
std::vector<Vec2> melkman_sorted_unchecked(std::span<const Vec2> sorted_points);
}  // namespace detail

}  // namespace mink
