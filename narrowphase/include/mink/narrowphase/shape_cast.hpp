#pragma once

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "mink/narrowphase/time_of_impact.hpp"

namespace mink {

/// @brief A shape moved along a straight line without turning, against a shape at rest. The
/// shapes are borrowed: they must outlive the call.
struct ShapeCastInput {
  const ShapeGeometry* shape = nullptr;     ///< the moving shape, in its own frame
  Pose pose;                                ///< where it starts
  Vec2 translation{0, 0};                   ///< world: how far its pose moves at fraction 1
  const ShapeGeometry* obstacle = nullptr;  ///< the shape in the way, in its own frame
  Pose obstacle_pose;                       ///< where the obstacle lies
  Real max_fraction = 1;                    ///< the cast covers [0, max_fraction], in [0, 1]
  Real target = 0.005;       ///< surface separation to stop at (see TimeOfImpactInput)
  Real tolerance = 0.00125;  ///< > 0
  int max_iterations = 500;  ///< distance evaluations allowed, >= 1
};

/// @brief Where a cast stopped, world coordinates. For `separated` only `fraction`
/// (max_fraction) and `iterations` are set.
struct ShapeCastOutput {
  ToiState state = ToiState::separated;  ///< as for time_of_impact
  Real fraction = 0;                     ///< of the translation
  Real separation = 0;                   ///< surface separation at `fraction`
  Vec2 point{0, 0};                      ///< the obstacle's surface point nearest the moving shape
  /// Unit, from the obstacle towards the moving shape; zero when the cores overlap (as for
  /// time_of_impact).
  Vec2 normal{0, 0};
  int iterations = 0;  ///< distance evaluations made
};

/// The first fraction at which the moving shape comes within `target` of the obstacle: the time
/// of impact of a sweep with no rotation, with the same guarantees (see TimeOfImpactOutput). With
/// no spin the advancement bound is exact along the normal, so the search converges in a few
/// steps (Newton's method on the distance, a convex function of the fraction).
/// @throws InvalidArgumentError naming the input: a null shape or obstacle, a non-finite pose or
/// translation, or a bad max_fraction, target, tolerance or max_iterations (as time_of_impact)
ShapeCastOutput shape_cast(const ShapeCastInput& input);

}  // namespace mink
