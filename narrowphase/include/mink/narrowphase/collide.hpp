#pragma once

#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

namespace mink {

/// Contact manifold of any two posed shapes through one dispatch table indexed by their kinds
/// (either order: the result's normal always points from A towards B). Separations are surface
/// to surface, radii included; each point lies midway between the two surfaces; feature ids are
/// stable while the same features touch. Pairs farther apart than `speculative_distance` give
/// point_count == 0. Two chain segments never collide (point_count == 0). A chain segment only
/// collides with a shape on its right side, and uses its ghost vertices so that a shape crossing
/// from one segment to the next sees one smooth surface.
/// @param a, b the shapes, in their local frames
/// @param pose_a, pose_b where they are in the world
/// @param speculative_distance largest separation that still yields points (world units)
Manifold collide_shapes(const ShapeGeometry& a, const Pose& pose_a, const ShapeGeometry& b,
                        const Pose& pose_b, Real speculative_distance);

}  // namespace mink
