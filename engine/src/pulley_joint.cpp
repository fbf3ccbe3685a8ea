// Pulley joint: each body hangs on a rope over a fixed ground point, and length_a + ratio *
// length_b keeps its value when made (Box2D 2.4's b2PulleyJoint: an equality, so the ropes
// push as well as pull). One rigid row in the soft step's form, its directions taken from the
// bodies' current anchors each substep.

#include "pulley_joint.hpp"

#include "joint_rows.hpp"

namespace mink::detail {

namespace {

// Below this a rope's direction is unreliable, and the row leaves that side alone (Box2D's ten
// linear slops).
constexpr Real kShortestRope = 0.05;

// One rope: its length and unit direction from the ground anchor to the body's anchor (0 when
// too short to tell).
struct Rope {
  Real length = 0;
  Vec2 axis{0, 0};
};
Rope rope(const Vec2& ground, const Vec2& anchor) {
  Rope r;
  const Vec2 d = anchor - ground;
  r.length = d.norm();
  if (r.length > kShortestRope) r.axis = d / r.length;
  return r;
}

// The row as the bodies are now: anchor offsets, rope directions and lengths, and the mass.
struct PulleyRow {
  Vec2 ra{0, 0}, rb{0, 0};
  Rope a, b;
  Real ca = 0, cb = 0;  // the ropes' lever arms: r x u
  Real mass = 0;
};

PulleyRow pulley_row(const PulleyJoint& joint, const JointFrame& frame, const SolverBody& a,
                     const SolverBody& b) {
  PulleyRow row;
  row.ra = delta_rotation(a).apply(frame.anchor_a);
  row.rb = delta_rotation(b).apply(frame.anchor_b);
  row.a = rope(joint.def.ground_anchor_a, frame.starts[0].center + delta_position(a) + row.ra);
  row.b = rope(joint.def.ground_anchor_b, frame.starts[1].center + delta_position(b) + row.rb);
  row.ca = cross(row.ra, row.a.axis);
  row.cb = cross(row.rb, row.b.axis);
  const JointBody& ja = frame.bodies[0];
  const JointBody& jb = frame.bodies[1];
  const Real ratio = joint.def.ratio;
  const Real k =
      ja.inv_mass * row.a.axis.squaredNorm() + ja.inv_inertia * row.ca * row.ca +
      ratio * ratio * (jb.inv_mass * row.b.axis.squaredNorm() + jb.inv_inertia * row.cb * row.cb);
  row.mass = k > 0 ? 1 / k : 0;
  return row;
}

// Impulse p lengthens A's rope and, by ratio, B's.
void apply_row(const PulleyRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
               Real ratio, Real p) {
  const JointBody& ja = frame.bodies[0];
  const JointBody& jb = frame.bodies[1];
  a.vx += ja.inv_mass * p * row.a.axis.x();
  a.vy += ja.inv_mass * p * row.a.axis.y();
  a.w += ja.inv_inertia * p * row.ca;
  const Real pb = ratio * p;
  b.vx += jb.inv_mass * pb * row.b.axis.x();
  b.vy += jb.inv_mass * pb * row.b.axis.y();
  b.w += jb.inv_inertia * pb * row.cb;
}

Real total_length(const PulleyJointDef& def) {
  return def.length_a + def.ratio * def.length_b;
}

}  // namespace

void prepare(PulleyJoint& joint, JointFrame& frame) {
  set_anchors(frame, joint.def.local_anchor_a, joint.def.local_anchor_b);
}

void warm_start(const PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  apply_row(pulley_row(joint, frame, a, b), frame, a, b, joint.def.ratio, joint.impulse);
}

void solve(PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  SolverBody& a = bodies[frame.bodies[0].solver];
  SolverBody& b = bodies[frame.bodies[1].solver];
  const Real ratio = joint.def.ratio;
  const PulleyRow row = pulley_row(joint, frame, a, b);
  const Real error = row.a.length + ratio * row.b.length - total_length(joint.def);
  Real bias = 0, mass_scale = 1, impulse_scale = 0;
  if (use_bias) {
    bias = frame.soft.bias_rate * error;
    mass_scale = frame.soft.mass_scale;
    impulse_scale = frame.soft.impulse_scale;
  }
  const Vec2 va = velocity_of(a) + cross(a.w, row.ra);
  const Vec2 vb = velocity_of(b) + cross(b.w, row.rb);
  const Real cdot = row.a.axis.dot(va) + ratio * row.b.axis.dot(vb);
  const Real p = -mass_scale * row.mass * (cdot + bias) - impulse_scale * joint.impulse;
  joint.impulse += p;
  apply_row(row, frame, a, b, ratio, p);
  joint.axis_b = row.b.axis;
}

JointReaction reaction(const PulleyJoint& joint, const JointFrame& frame) {
  // Along B's rope through B's anchor, so no torque about the anchor.
  return {frame.inv_h * joint.def.ratio * joint.impulse * joint.axis_b, 0};
}

// Nothing to settle: the constant comes from the definition.

Real coordinate(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const Real la = (a.pose.apply(joint.def.local_anchor_a) - joint.def.ground_anchor_a).norm();
  const Real lb = (b.pose.apply(joint.def.local_anchor_b) - joint.def.ground_anchor_b).norm();
  return la + joint.def.ratio * lb;
}

Real speed(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b) {
  const Vec2 pa = a.pose.apply(joint.def.local_anchor_a);
  const Vec2 pb = b.pose.apply(joint.def.local_anchor_b);
  const Rope ra = rope(joint.def.ground_anchor_a, pa);
  const Rope rb = rope(joint.def.ground_anchor_b, pb);
  return ra.axis.dot(a.velocity_at(pa)) + joint.def.ratio * rb.axis.dot(b.velocity_at(pb));
}

void draw(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw) {
  const Vec2 pa = a.pose.apply(joint.def.local_anchor_a);
  const Vec2 pb = b.pose.apply(joint.def.local_anchor_b);
  const Vec2& ga = joint.def.ground_anchor_a;
  const Vec2& gb = joint.def.ground_anchor_b;
  draw.draw_segment(ga, pa, kJointColor);
  draw.draw_segment(gb, pb, kJointColor);
  draw.draw_segment(ga, gb, kJointColor);
  draw.draw_point(ga, 5, kJointColor);
  draw.draw_point(gb, 5, kJointColor);
  draw.draw_point(pa, 5, kJointColor);
  draw.draw_point(pb, 5, kJointColor);
}

}  // namespace mink::detail
