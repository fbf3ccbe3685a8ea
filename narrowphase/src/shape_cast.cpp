#include "mink/narrowphase/shape_cast.hpp"

#include <cmath>
#include <string>

#include "mink/error.hpp"

namespace mink {

namespace {

bool finite(const Pose& p) {
  return std::isfinite(p.position.x()) && std::isfinite(p.position.y()) &&
         std::isfinite(p.rotation.cos) && std::isfinite(p.rotation.sin);
}

// What time_of_impact would blame on its sweeps, named as the caller knows it.
void check(const ShapeCastInput& in) {
  if (in.shape == nullptr) throw InvalidArgumentError("shape_cast: shape is null");
  if (in.obstacle == nullptr) throw InvalidArgumentError("shape_cast: obstacle is null");
  if (!finite(in.pose)) throw InvalidArgumentError("shape_cast: pose is not finite");
  if (!finite(in.obstacle_pose))
    throw InvalidArgumentError("shape_cast: obstacle_pose is not finite");
  if (!std::isfinite(in.translation.x()) || !std::isfinite(in.translation.y())) {
    throw InvalidArgumentError("shape_cast: translation is not finite");
  }
}

}  // namespace

ShapeCastOutput shape_cast(const ShapeCastInput& input) {
  check(input);
  TimeOfImpactInput toi;
  // The obstacle is A, so the normal (A towards B) already points at the moving shape.
  toi.shape_a = input.obstacle;
  toi.sweep_a.center0 = input.obstacle_pose.position;
  toi.sweep_a.center1 = input.obstacle_pose.position;
  toi.sweep_a.angle0 = toi.sweep_a.angle1 = input.obstacle_pose.rotation.angle();
  toi.shape_b = input.shape;
  toi.sweep_b.center0 = input.pose.position;
  toi.sweep_b.center1 = input.pose.position + input.translation;
  toi.sweep_b.angle0 = toi.sweep_b.angle1 = input.pose.rotation.angle();
  toi.max_fraction = input.max_fraction;
  toi.target = input.target;
  toi.tolerance = input.tolerance;
  toi.max_iterations = input.max_iterations;
  const TimeOfImpactOutput found = time_of_impact(toi);
  ShapeCastOutput out;
  out.state = found.state;
  out.fraction = found.fraction;
  out.separation = found.separation;
  out.point = found.point_a;
  out.normal = found.normal;
  out.iterations = found.iterations;
  return out;
}

}  // namespace mink
