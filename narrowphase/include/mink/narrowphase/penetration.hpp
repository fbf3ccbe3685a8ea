#pragma once

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/simplex.hpp"

namespace mink {

/// @brief How deep two overlapping hulls overlap, in world coordinates.
struct PenetrationResult {
  Real depth = 0;      ///< >= 0: how far B must move along `normal` to stop overlapping
  Vec2 normal{0, 0};   ///< unit, world, from A towards B
  Vec2 point_a{0, 0};  ///< deepest point of A inside B (world)
  Vec2 point_b{0, 0};  ///< deepest point of B inside A (world): point_b = point_a - depth * normal
  int iterations = 0;  ///< EPA expansions
  bool used_face_test = false;  ///< the start was degenerate or the cap was hit: see below
};

/// Penetration depth and normal of overlapping hulls by EPA on the 2D Minkowski difference,
/// started from the final simplex of gjk_distance (a triangle around the origin). When that
/// simplex is not a proper triangle (the origin on its boundary: touching or nearly) or the
/// expansion reaches its cap, the answer comes from the face-normal test instead, which is
/// exact in 2D because A - B has exactly the edge normals of A and B. Call only for
/// overlapping pairs; for separated ones the result has depth 0.
/// @param a, b the hulls, in their local frames
/// @param pose_a, pose_b where the hulls are in the world
/// @param start the final simplex of gjk_distance for the same hulls and poses
PenetrationResult penetration(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                              const Pose& pose_b, const SimplexCache& start);

/// The face-normal (separating-axis) answer alone: the minimum over all edge normals of A
/// and B of the overlap along it. O(n + m).
PenetrationResult penetration_by_faces(const PreparedHull& a, const Pose& pose_a,
                                       const PreparedHull& b, const Pose& pose_b);

}  // namespace mink
