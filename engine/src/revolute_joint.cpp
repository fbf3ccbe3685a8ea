// Revolute joint: B's anchor held on A's anchor; the relative angle free, or sprung, driven
// or bounded. Rows in the soft step's form: rigid rows push their error out through the
// joint softness only in the biased pass, limits are speculative while not reached.

#include "revolute_joint.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "joint_rows.hpp"

namespace mink::detail {

void prepare(RevoluteJoint& joint, JointFrame& frame) {
  set_anchors(frame, joint.def.local_anchor_a, joint.def.local_anchor_b);
  const Real k = frame.bodies[0].inv_inertia + frame.bodies[1].inv_inertia;
  joint.axial_mass = k > 0 ? 1 / k : 0;
  const RevoluteJointDef& def = joint.def;
  joint.angle_rows =
      joint.axial_mass > 0 && (def.spring.enabled || def.motor.enabled || def.limit.enabled);
  joint.spring_soft =
      make_softness(joint.def.spring.hertz, joint.def.spring.damping_ratio, frame.h);
  frame.coordinate_a = joint.angle;
  drop_switched_off(joint);
}

void prepare_pin(RevoluteJoint& joint, JointFrame& frame) {
  set_anchors(frame, joint.def.local_anchor_a, joint.def.local_anchor_b);
  joint.angle_rows = false;
  joint.direct = false;
  drop_switched_off(joint);
}

namespace {

// What the angle's rows (spring, motor, limits) hold together.
Real angular_impulse(const RevoluteJoint& joint) {
  return joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse;
}

}  // namespace

RevoluteRow revolute_row(const RevoluteJoint& joint, const JointFrame& frame) {
  const auto f = [](Real x) { return static_cast<SolverReal>(x); };
  const auto on = [&](bool enabled) {
    return SolverReal{joint.angle_rows && enabled ? 1.0f : 0.0f};
  };
  const RevoluteJointDef& def = joint.def;
  RevoluteRow row;
  static_cast<PinRow&>(row) = pin_row(frame, joint.direct ? Vec2(0, 0) : joint.linear_impulse);
  row.axial_mass = f(joint.axial_mass);
  row.spring_bias_rate = f(joint.spring_soft.bias_rate);
  row.spring_mass_scale = f(joint.spring_soft.mass_scale);
  row.spring_impulse_scale = f(joint.spring_soft.impulse_scale);
  // The step-start angle counts whole turns and may be large; its differences with the
  // targets, taken here in double precision, are what the rows need and are small near them.
  row.spring_offset = f(frame.coordinate_a - def.spring.target);
  row.motor_speed = f(def.motor.speed);
  row.motor_max_impulse = f(frame.h * def.motor.max_force);
  row.lower_offset = f(frame.coordinate_a - def.limit.lower);
  row.upper_offset = f(def.limit.upper - frame.coordinate_a);
  row.inv_h = f(frame.inv_h);
  row.spring_on = on(def.spring.enabled);
  row.motor_on = on(def.motor.enabled);
  row.limit_on = on(def.limit.enabled);
  row.spring_impulse = f(joint.spring_impulse);
  row.motor_impulse = f(joint.motor_impulse);
  row.lower_impulse = f(joint.lower_impulse);
  row.upper_impulse = f(joint.upper_impulse);
  row.point = !joint.direct;
  return row;
}

void store_row(const RevoluteRow& row, RevoluteJoint& joint) {
  if (row.point) joint.linear_impulse = Vec2(row.impulse_x, row.impulse_y);
  joint.spring_impulse = row.spring_impulse;
  joint.motor_impulse = row.motor_impulse;
  joint.lower_impulse = row.lower_impulse;
  joint.upper_impulse = row.upper_impulse;
}

// From the record, as from a row (the solver keeps rows for its joints; these are for a joint
// solved alone).
void warm_start(const RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  warm_start_revolute(bodies, revolute_row(joint, frame));
}

void solve(RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  RevoluteRow row = revolute_row(joint, frame);
  solve_revolute(bodies, row, use_bias);
  store_row(row, joint);
}

JointReaction reaction(const RevoluteJoint& joint, Real inv_h) {
  return {inv_h * joint.linear_impulse, inv_h * angular_impulse(joint)};
}

JointReaction reaction(const RevoluteJoint& joint, const JointFrame& frame) {
  return reaction(joint, frame.inv_h);
}

namespace {

Real coordinate(const RevoluteJoint& joint, const Rotation& a, const Rotation& b) {
  const Real now = relative_angle(a, b) - joint.def.reference_angle;
  return joint.angle + wrap_angle(now - joint.angle);
}

}  // namespace

Real coordinate(const RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  return coordinate(joint, a.pose.rotation, b.pose.rotation);
}

void finish(RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  finish_angle(joint, a.pose.rotation, b.pose.rotation, a.turned, b.turned);
}

void finish_angle(RevoluteJoint& joint, const Rotation& a, const Rotation& b, Real turned_a,
                  Real turned_b) {
  // The poses give the angle up to whole turns, taken nearest the last; a fast pair turns
  // half a turn and more in a step, and the solver's count of its turn says by how many whole
  // turns the nearest is off.
  constexpr Real two_pi = 2 * std::numbers::pi;
  const Real nearest = coordinate(joint, a, b);
  const Real whole = std::round((joint.angle + (turned_b - turned_a) - nearest) / two_pi);
  joint.angle = nearest + two_pi * whole;
}

Real speed(const RevoluteJoint&, const JointBodyState& a, const JointBodyState& b) {
  return b.angular_velocity - a.angular_velocity;
}

void draw(const RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const Vec2 pa = a.pose.apply(joint.def.local_anchor_a);
  const Vec2 pb = b.pose.apply(joint.def.local_anchor_b);
  draw_anchors(draw, a, b, pa, pb);
  if (joint.def.limit.enabled) {
    // The limits as two rays from the anchor, in A's frame at the reference angle.
    const Real base = a.pose.rotation.angle() + joint.def.reference_angle;
    const Real length = std::max<Real>(0.25, (b.center - pb).norm());
    for (const Real limit : {joint.def.limit.lower, joint.def.limit.upper}) {
      const Rotation r = Rotation::from_angle(base + limit);
      draw.draw_segment(pa, pa + r.apply(Vec2(length, 0)), kJointLimitColor);
    }
  }
}

}  // namespace mink::detail
