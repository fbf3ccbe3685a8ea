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
template <typename Joint>
Real angular_impulse(const Joint& joint) {
  return joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse;
}

// The rows, on a joint's record and frame or on its row's copies of them.
template <typename Joint, typename Frame>
void warm_start_rows(const Joint& joint, const Frame& frame, SolverBody* bodies) {
  warm_start_point(bodies, frame, joint.linear_impulse, angular_impulse(joint));
}

template <typename Joint, typename Frame>
void solve_rows(Joint& joint, const Frame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  if (joint.angle_rows) {
    const auto& def = joint.def;
    // The angle only where a row needs it (two arc tangents a substep, for every joint of a
    // large net otherwise), once: the rows change velocities, not the angle.
    const bool needs_angle = def.spring.enabled || def.limit.enabled;
    const Real angle = needs_angle ? frame.coordinate_a + relative_turn(a, b) : Real{0};
    if (def.spring.enabled) {
      solve_angular_spring(a, b, frame, joint.axial_mass, joint.spring_soft,
                           angle - def.spring.target, joint.spring_impulse);
    }
    if (def.motor.enabled) {
      solve_angular_motor(a, b, frame, joint.axial_mass, def.motor, joint.motor_impulse);
    }
    if (def.limit.enabled) {
      solve_angular_limits(a, b, frame, joint.axial_mass, angle, def.limit, use_bias,
                           joint.lower_impulse, joint.upper_impulse);
    }
  }
  if (!joint.direct) solve_point(a, b, frame, use_bias, joint.linear_impulse);
}

}  // namespace

void warm_start(const RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  warm_start_rows(joint, frame, bodies);
}

void solve(RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  solve_rows(joint, frame, bodies, use_bias);
}

void fill_row(RevoluteRow& row, const RevoluteJoint& joint, const JointFrame& frame) {
  static_cast<PointRowFrame&>(row.frame) = point_row_frame(frame);
  row.frame.h = frame.h;
  row.frame.inv_h = frame.inv_h;
  row.frame.coordinate_a = frame.coordinate_a;
  static_cast<RevoluteRowState&>(row.joint) = joint;
  row.joint.def.spring = joint.def.spring;
  row.joint.def.motor = joint.def.motor;
  row.joint.def.limit = joint.def.limit;
}

void store_row(const RevoluteRow& row, RevoluteJoint& joint) {
  static_cast<RevoluteRowState&>(joint) = row.joint;
}

void warm_start(const RevoluteRow& row, SolverBody* bodies) {
  warm_start_rows(row.joint, row.frame, bodies);
}

void solve(RevoluteRow& row, SolverBody* bodies, bool use_bias) {
  solve_rows(row.joint, row.frame, bodies, use_bias);
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
