// Motor joint: drives B towards a pose relative to A with bounded force and torque. Each part
// is a motor (joint_rows.hpp) whose target speed removes correction_factor of the error every
// substep (speed correction_factor * error / h, as Box2D v3.0's motor joint), but never faster
// than half the bounded force could stop in the distance left. Without that cap a force-bound
// drive arrives too fast, overshoots and swings about the target for seconds (a bang-bang
// controller); with it the body brakes in time and settles. Half, as other forces (gravity,
// contacts) may take up part of the budget. A softness (hertz, damping) was the alternative,
// but once the force saturates it can overshoot just the same. The target speeds apply in both
// passes: they are what the joint drives, not an error the relax pass should take back.

#include "motor_joint.hpp"

#include <algorithm>
#include <cmath>

#include "joint_rows.hpp"

namespace mink::detail {

namespace {

// The speed to close `distance` at: `rate` * distance, at most what a deceleration of
// `braking` stops in that distance.
Real approach_speed(Real distance, Real rate, Real braking) {
  return std::min(rate * distance, std::sqrt(2 * braking * distance));
}

}  // namespace

void prepare(MotorJoint& joint, JointFrame& frame) {
  const MotorJointDef& def = joint.def;
  // A's anchor is the target point; B's is its origin.
  set_anchors(frame, def.linear_offset, Vec2(0, 0));
  const Real k = frame.bodies[0].inv_inertia + frame.bodies[1].inv_inertia;
  joint.axial_mass = k > 0 ? 1 / k : 0;
  joint.angle_error = wrap_angle(
      relative_angle(frame.starts[0].rotation, frame.starts[1].rotation) - def.angular_offset);
}

void warm_start(const MotorJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  warm_start_point(bodies, frame, joint.linear_impulse, joint.angular_impulse);
}

void solve(MotorJoint& joint, const JointFrame& frame, SolverBody* bodies, bool) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const MotorJointDef& def = joint.def;
  const Real rate = def.correction_factor * frame.inv_h;
  const JointBody& ja = frame.bodies[0];
  const JointBody& jb = frame.bodies[1];
  if (joint.axial_mass > 0) {
    const Real error = joint.angle_error + relative_turn(a, b);
    const Real braking = 0.5 * def.max_torque / joint.axial_mass;
    const Real speed = approach_speed(std::abs(error), rate, braking);
    const JointMotor turn{true, error > 0 ? -speed : speed, def.max_torque};
    solve_angular_motor(a, b, frame, joint.axial_mass, turn, joint.angular_impulse);
  }
  const CurrentAnchors c = current_anchors(frame, a, b);
  const Real distance = c.separation.norm();
  Vec2 velocity(0, 0);
  if (distance > 0) {
    const Vec2 n = c.separation / distance;
    // The anchors' relative acceleration along n per unit force along n.
    const Real inv_mass = ja.inv_mass + jb.inv_mass +
                          ja.inv_inertia * cross(c.ra, n) * cross(c.ra, n) +
                          jb.inv_inertia * cross(c.rb, n) * cross(c.rb, n);
    const Real braking = 0.5 * def.max_force * inv_mass;
    velocity = -approach_speed(distance, rate, braking) * n;
  }
  solve_point_motor(a, b, frame, velocity, def.max_force, joint.linear_impulse);
}

JointReaction reaction(const MotorJoint& joint, const JointFrame& frame) {
  return {frame.inv_h * joint.linear_impulse, frame.inv_h * joint.angular_impulse};
}

void draw(const MotorJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  // The target (a point and B's target direction) and B's origin on its way there.
  const Vec2 target = a.pose.apply(joint.def.linear_offset);
  const Rotation heading = Rotation::from_angle(a.pose.rotation.angle() + joint.def.angular_offset);
  draw.draw_segment(target, b.pose.position, kJointColor);
  draw.draw_segment(target, target + heading.apply(Vec2(0.25, 0)), kJointAxisColor);
  draw.draw_point(target, 5, kJointAxisColor);
  draw.draw_point(b.pose.position, 5, kJointColor);
}

}  // namespace mink::detail
