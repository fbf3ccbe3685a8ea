// Prismatic joint: B slides along an axis fixed in A without turning relative to A. Across the
// axis and on the angle the joint is rigid; along it a spring, a motor and limits act, each
// its own row (in the soft step's form, as in joint_rows.hpp).

#include "prismatic_joint.hpp"

#include "joint_rows.hpp"

namespace mink::detail {

namespace {

// The rows across the axis and on the angle, solved together: with B's anchor off its centre
// of mass a force across the axis also turns B, so one at a time the two rows would undo each
// other's work and converge slowly.
void solve_block(const SliderRows& s, const JointFrame& frame, SolverBody& a, SolverBody& b,
                 Real angle_error, bool use_bias, Vec2& impulse) {
  const AxialRow& row = s.across;
  const JointBody& ja = frame.bodies[0];
  const JointBody& jb = frame.bodies[1];
  const Real k11 = ja.inv_mass + jb.inv_mass + ja.inv_inertia * row.a1 * row.a1 +
                   jb.inv_inertia * row.a2 * row.a2;
  const Real k12 = ja.inv_inertia * row.a1 + jb.inv_inertia * row.a2;
  Real k22 = ja.inv_inertia + jb.inv_inertia;
  if (k22 == 0) k22 = 1;  // neither body turns: keep the block invertible
  Vec2 rhs(axial_velocity(row, a, b), b.w - a.w);
  Softness soft{0, 1, 0};
  if (use_bias) {
    soft = frame.soft;
    rhs += soft.bias_rate * Vec2(row.axis.dot(s.anchors.separation), angle_error);
  }
  Real det = k11 * k22 - k12 * k12;
  if (det != 0) det = 1 / det;
  const Vec2 solved(det * (k22 * rhs.x() - k12 * rhs.y()), det * (k11 * rhs.y() - k12 * rhs.x()));
  const Vec2 p = -soft.mass_scale * solved - soft.impulse_scale * impulse;
  impulse += p;
  // The force acts at B's anchor, so A's lever arm reaches there (its anchor plus the offset).
  apply_pair(a, b, frame, s.anchors.ra + s.anchors.separation, s.anchors.rb, p.x() * row.axis,
             p.y());
}

Real axial_impulse(const PrismaticJoint& joint) {
  return joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse;
}

}  // namespace

void prepare(PrismaticJoint& joint, JointFrame& frame) {
  const PrismaticJointDef& def = joint.def;
  set_anchors(frame, def.local_anchor_a, def.local_anchor_b);
  const JointBodyStart& a = frame.starts[0];
  const JointBodyStart& b = frame.starts[1];
  joint.axis = a.rotation.apply(def.local_axis_a);
  joint.angle_error = wrap_angle(relative_angle(a.rotation, b.rotation) - def.reference_angle);
  joint.spring_soft = make_softness(def.spring.hertz, def.spring.damping_ratio, frame.h);
  drop_switched_off(joint);
}

void warm_start(const PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const SliderRows s = make_slider_rows(frame, a, b, joint.axis);
  const Vec2 p = axial_impulse(joint) * s.axis + joint.block_impulse.x() * s.across.axis;
  apply_pair(a, b, frame, s.anchors.ra + s.anchors.separation, s.anchors.rb, p,
             joint.block_impulse.y());
}

void solve(PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const PrismaticJointDef& def = joint.def;
  const SliderRows s = make_slider_rows(frame, a, b, joint.axis);
  if (def.spring.enabled) {
    solve_axial_spring(s.along, frame, a, b, joint.spring_soft, s.translation - def.spring.target,
                       joint.spring_impulse);
  }
  if (def.motor.enabled) {
    solve_axial_motor(s.along, frame, a, b, def.motor, joint.motor_impulse);
  }
  if (def.limit.enabled) {
    solve_axial_limits(s.along, frame, a, b, s.translation, def.limit, use_bias,
                       joint.lower_impulse, joint.upper_impulse);
  }
  const Real angle_error = joint.angle_error + relative_turn(a, b);
  solve_block(s, frame, a, b, angle_error, use_bias, joint.block_impulse);
}

JointReaction reaction(const PrismaticJoint& joint, const JointFrame& frame) {
  const Vec2 p =
      axial_impulse(joint) * joint.axis + joint.block_impulse.x() * left_perp(joint.axis);
  return {frame.inv_h * p, frame.inv_h * joint.block_impulse.y()};
}

Real coordinate(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const PrismaticJointDef& def = joint.def;
  return slider_translation(a, b, def.local_anchor_a, def.local_anchor_b, def.local_axis_a);
}

Real speed(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const PrismaticJointDef& def = joint.def;
  return slider_speed(a, b, def.local_anchor_a, def.local_anchor_b, def.local_axis_a);
}

void draw(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const PrismaticJointDef& def = joint.def;
  const Vec2 pa = a.pose.apply(def.local_anchor_a);
  const Vec2 pb = b.pose.apply(def.local_anchor_b);
  draw_axis(draw, pa, a.pose.rotation.apply(def.local_axis_a), def.limit);
  draw_anchors(draw, a, b, pa, pb);
}

}  // namespace mink::detail
