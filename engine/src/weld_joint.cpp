// Weld joint: B glued to A at an anchor. A part with hertz 0 is rigid and pushes its error
// out through the joint softness in the biased pass only (solve_point, solve_angle); a part
// with hertz > 0 is a spring, soft with its own frequency in both passes (it is a force the
// bodies feel, not an error to remove), as Box2D v3's weld.

#include "weld_joint.hpp"

#include "joint_rows.hpp"

namespace mink::detail {

void prepare(WeldJoint& joint, JointFrame& frame) {
  const WeldJointDef& def = joint.def;
  set_anchors(frame, def.local_anchor_a, def.local_anchor_b);
  const Real k = frame.bodies[0].inv_inertia + frame.bodies[1].inv_inertia;
  joint.axial_mass = k > 0 ? 1 / k : 0;
  joint.angle_error = wrap_angle(
      relative_angle(frame.starts[0].rotation, frame.starts[1].rotation) - def.reference_angle);
  joint.linear_soft = make_softness(def.linear_hertz, def.linear_damping_ratio, frame.h);
  joint.angular_soft = make_softness(def.angular_hertz, def.angular_damping_ratio, frame.h);
}

void warm_start(const WeldJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  warm_start_point(bodies, frame, joint.linear_impulse, joint.angular_impulse);
}

void solve(WeldJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const WeldJointDef& def = joint.def;
  if (joint.axial_mass > 0) {
    const Real error = joint.angle_error + relative_turn(a, b);
    if (def.angular_hertz > 0) {
      solve_angular_spring(a, b, frame, joint.axial_mass, joint.angular_soft, error,
                           joint.angular_impulse);
    } else {
      solve_angle(a, b, frame, joint.axial_mass, error, use_bias, joint.angular_impulse);
    }
  }
  // The point last, as it matters most.
  if (def.linear_hertz > 0) {
    solve_point_spring(a, b, frame, joint.linear_soft, joint.linear_impulse);
  } else {
    solve_point(a, b, frame, use_bias, joint.linear_impulse);
  }
}

JointReaction reaction(const WeldJoint& joint, const JointFrame& frame) {
  return {frame.inv_h * joint.linear_impulse, frame.inv_h * joint.angular_impulse};
}

void draw(const WeldJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const Vec2 pa = a.pose.apply(joint.def.local_anchor_a);
  const Vec2 pb = b.pose.apply(joint.def.local_anchor_b);
  draw_anchors(draw, a, b, pa, pb);
  // A soft weld's anchors drift apart: the gap shows the spring's stretch.
  draw.draw_segment(pa, pb, kJointAxisColor);
}

}  // namespace mink::detail
