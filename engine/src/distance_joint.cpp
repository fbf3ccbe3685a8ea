// Distance joint: the anchors' distance held at a length (rigid), pulled towards it (spring),
// or kept between bounds (a rope or a rod with play), with an optional motor on its rate.

#include "distance_joint.hpp"

#include "joint_rows.hpp"

namespace mink::detail {

namespace {

// Free between its bounds: only the limits (and spring, motor) act, no rigid row.
bool has_play(const DistanceJointDef& def) {
  return def.limit.enabled && def.limit.lower < def.limit.upper;
}

// The line between the anchors now, as a row along it (A's lever arm to A's anchor: the
// anchors lie on the axis, so the separation adds nothing to it).
AxialRow line_row(const JointFrame& frame, const CurrentAnchors& anchors, Real& length) {
  length = anchors.separation.norm();
  const Vec2 axis = length > 0 ? Vec2(anchors.separation / length) : Vec2(1, 0);
  return make_axial_row(frame, anchors, axis);
}

Vec2 anchor_offset(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  return b.pose.apply(joint.def.local_anchor_b) - a.pose.apply(joint.def.local_anchor_a);
}

}  // namespace

void prepare(DistanceJoint& joint, JointFrame& frame) {
  set_anchors(frame, joint.def.local_anchor_a, joint.def.local_anchor_b);
  joint.spring_soft =
      make_softness(joint.def.spring.hertz, joint.def.spring.damping_ratio, frame.h);
  drop_switched_off(joint);
}

void warm_start(const DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  Real length = 0;
  const AxialRow row = line_row(frame, current_anchors(frame, a, b), length);
  const Real total =
      joint.impulse + joint.lower_impulse - joint.upper_impulse + joint.motor_impulse;
  apply_axial(row, frame, a, b, total);
}

void solve(DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const DistanceJointDef& def = joint.def;
  Real length = 0;
  const AxialRow row = line_row(frame, current_anchors(frame, a, b), length);
  if (def.spring.enabled) {
    if (def.spring.hertz > 0 || def.spring.damping_ratio > 0) {
      solve_axial_spring(row, frame, a, b, joint.spring_soft, length - def.length, joint.impulse);
    }
  } else if (!has_play(def)) {
    const Real target = def.limit.enabled ? def.limit.lower : def.length;
    solve_axial(row, frame, a, b, length - target, use_bias, joint.impulse);
  }
  if (def.limit.enabled && has_play(def)) {
    solve_axial_limits(row, frame, a, b, length, def.limit, use_bias, joint.lower_impulse,
                       joint.upper_impulse);
  }
  if (def.motor.enabled) solve_axial_motor(row, frame, a, b, def.motor, joint.motor_impulse);
}

JointReaction reaction(const DistanceJoint& joint, const JointFrame& frame) {
  // Along the line as the step began (the rows' directions move only a little in a step).
  const Vec2 line = frame.delta_center + frame.anchor_b - frame.anchor_a;
  const Real length = line.norm();
  const Vec2 axis = length > 0 ? Vec2(line / length) : Vec2(1, 0);
  const Real total =
      joint.impulse + joint.lower_impulse - joint.upper_impulse + joint.motor_impulse;
  return {frame.inv_h * total * axis, 0};
}

Real coordinate(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  return anchor_offset(joint, a, b).norm();
}

Real speed(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const Vec2 d = anchor_offset(joint, a, b);
  const Real length = d.norm();
  if (length == 0) return 0;
  const Vec2 va = a.velocity_at(a.pose.apply(joint.def.local_anchor_a));
  const Vec2 vb = b.velocity_at(b.pose.apply(joint.def.local_anchor_b));
  return d.dot(vb - va) / length;
}

void draw(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const Vec2 pa = a.pose.apply(joint.def.local_anchor_a);
  const Vec2 pb = b.pose.apply(joint.def.local_anchor_b);
  draw.draw_segment(pa, pb, kJointColor);
  draw.draw_point(pa, 4, kJointColor);
  draw.draw_point(pb, 4, kJointColor);
  if (joint.def.limit.enabled) {
    // Where the bounds lie along the current line.
    const Vec2 d = pb - pa;
    const Real length = d.norm();
    if (length > 0) {
      const Vec2 axis = d / length;
      const Vec2 across = 0.1 * left_perp(axis);
      for (const Real bound : {joint.def.limit.lower, joint.def.limit.upper}) {
        const Vec2 at = pa + bound * axis;
        draw.draw_segment(at - across, at + across, kJointLimitColor);
      }
    }
  }
}

}  // namespace mink::detail
