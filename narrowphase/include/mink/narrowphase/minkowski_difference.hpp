#pragma once

#include <span>
#include <vector>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

/// The Minkowski difference A - B = {a - b} of two convex polygons given counter-clockwise:
/// a convex polygon, counter-clockwise from its lowest (then leftmost) vertex. Built in
/// O(n + m) by merging the edge sequences of A and -B by angle; parallel edges merge into one,
/// so every vertex is a difference a_i - b_j of input vertices. For pictures and tests: GJK
/// only ever samples it through support points.
/// @throws InvalidArgumentError when either polygon has fewer than 3 vertices
std::vector<Vec2> minkowski_difference(std::span<const Vec2> a, std::span<const Vec2> b);

/// @brief The same for posed hulls, in world coordinates.
std::vector<Vec2> minkowski_difference(const PreparedHull& a, const Pose& pose_a,
                                       const PreparedHull& b, const Pose& pose_b);

}  // namespace mink
