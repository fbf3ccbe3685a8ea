// Wheel joint: B's anchor rides the line through A's anchor along A's axis, sprung along it
// (the suspension) and free to spin. Rows in the soft step's form (joint_rows.hpp): the row
// across the axis is rigid; the spring is soft in both passes; limits are speculative until
// reached; the motor drives the spin with a bounded torque.

#include "wheel_joint.hpp"

#include "joint_rows.hpp"

namespace mink::detail {

namespace {

Real axial_impulse(const WheelJoint& joint) {
  return joint.spring_impulse + joint.lower_impulse - joint.upper_impulse;
}

}  // namespace

void prepare(WheelJoint& joint, JointFrame& frame) {
  const WheelJointDef& def = joint.def;
  set_anchors(frame, def.local_anchor_a, def.local_anchor_b);
  joint.axis = frame.starts[0].rotation.apply(def.local_axis_a);
  const Real k = frame.bodies[0].inv_inertia + frame.bodies[1].inv_inertia;
  joint.motor_mass = k > 0 ? 1 / k : 0;
  joint.spring_soft = make_softness(def.spring.hertz, def.spring.damping_ratio, frame.h);
  drop_switched_off(joint);
}

void warm_start(const WheelJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const SliderRows s = make_slider_rows(frame, a, b, joint.axis);
  const Vec2 p = axial_impulse(joint) * s.axis + joint.perp_impulse * s.across.axis;
  // The linear impulse acts at B's anchor: A's lever arm reaches there.
  apply_pair(a, b, frame, s.anchors.ra + s.anchors.separation, s.anchors.rb, p,
             joint.motor_impulse);
}

void solve(WheelJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const WheelJointDef& def = joint.def;
  const SliderRows s = make_slider_rows(frame, a, b, joint.axis);
  if (def.motor.enabled && joint.motor_mass > 0) {
    solve_angular_motor(a, b, frame, joint.motor_mass, def.motor, joint.motor_impulse);
  }
  if (def.spring.enabled) {
    solve_axial_spring(s.along, frame, a, b, joint.spring_soft, s.translation - def.spring.target,
                       joint.spring_impulse);
  }
  if (def.limit.enabled) {
    solve_axial_limits(s.along, frame, a, b, s.translation, def.limit, use_bias,
                       joint.lower_impulse, joint.upper_impulse);
  }
  solve_axial(s.across, frame, a, b, s.across.axis.dot(s.anchors.separation), use_bias,
              joint.perp_impulse);
}

JointReaction reaction(const WheelJoint& joint, const JointFrame& frame) {
  const Vec2 p = axial_impulse(joint) * joint.axis + joint.perp_impulse * left_perp(joint.axis);
  return {frame.inv_h * p, frame.inv_h * joint.motor_impulse};
}

Real coordinate(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const WheelJointDef& def = joint.def;
  return slider_translation(a, b, def.local_anchor_a, def.local_anchor_b, def.local_axis_a);
}

Real speed(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const WheelJointDef& def = joint.def;
  return slider_speed(a, b, def.local_anchor_a, def.local_anchor_b, def.local_axis_a);
}

void draw(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const WheelJointDef& def = joint.def;
  const Vec2 pa = a.pose.apply(def.local_anchor_a);
  const Vec2 pb = b.pose.apply(def.local_anchor_b);
  draw_axis(draw, pa, a.pose.rotation.apply(def.local_axis_a), def.limit);
  draw.draw_segment(a.center, pa, kJointColor);
  draw.draw_segment(pa, pb, kJointColor);
  draw.draw_point(pa, 5, kJointColor);
  draw.draw_point(pb, 5, kJointColor);
}

}  // namespace mink::detail
