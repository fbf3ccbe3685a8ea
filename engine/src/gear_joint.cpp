// Gear joint: couples two revolute or prismatic joints so that coordinate1 + ratio *
// coordinate2 keeps the value it had when the gear was made (Box2D 2.4's b2GearJoint, as one
// rigid row of the soft step). The joints' coordinates are read as each step begins
// (frame.coordinate_a and coordinate_b) and followed through the substeps from the bodies'
// position and rotation change, so a revolute's angle counts full turns.

#include "gear_joint.hpp"

#include <variant>

namespace mink::detail {

namespace {

// The gear's row on one body.
struct GearTerm {
  std::int32_t solver = 0;
  Vec2 linear{0, 0};
  Real angular = 0;
  Real inv_mass = 0, inv_inertia = 0;
};

// The gear's row as the bodies are now: its value (coordinate1 + ratio * coordinate2) and its
// Jacobian. Bodies may be shared by both joints (two wheels on one chassis); their terms are
// merged, so the effective mass counts each body once with its whole coefficient.
struct GearRow {
  std::array<GearTerm, 4> terms{};
  int count = 0;
  Real value = 0;
  Real mass = 0;  // 1 / effective mass, 0 when nothing can move

  void add(const JointBody& body, const Vec2& linear, Real angular) {
    for (int i = 0; i < count; ++i) {
      GearTerm& t = terms[static_cast<std::size_t>(i)];
      if (t.solver == body.solver) {
        t.linear += linear;
        t.angular += angular;
        return;
      }
    }
    terms[static_cast<std::size_t>(count++)] = {body.solver, linear, angular, body.inv_mass,
                                                body.inv_inertia};
  }
};

GearRow gear_row(const GearJoint& joint, const JointFrame& frame, const SolverBody* bodies) {
  GearRow row;
  for (std::size_t g = 0; g < 2; ++g) {
    const GearedJoint& geared = joint.joints[g];
    const Real scale = g == 0 ? 1 : joint.def.ratio;
    const JointBody& jb = frame.bodies[g];
    const JointBody& ja = frame.bodies[g + 2];
    const SolverBody& b = bodies[jb.solver];
    const SolverBody& a = bodies[ja.solver];
    Real value = g == 0 ? frame.coordinate_a : frame.coordinate_b;
    if (geared.prismatic) {
      // Translation = axis . d with the axis turning with A: its rate has A's lever arm from
      // A's centre to B's anchor (as the prismatic joint's own axial rows).
      const Vec2 ra = delta_rotation(a).apply(geared.anchor_a);
      const Vec2 rb = delta_rotation(b).apply(geared.anchor_b);
      const Vec2 d = (delta_position(b) - delta_position(a)) + geared.delta_center + (rb - ra);
      const Vec2 axis = delta_rotation(a).apply(geared.axis);
      value += axis.dot(d) - geared.start_translation;
      row.add(ja, -scale * axis, -scale * cross(d + ra, axis));
      row.add(jb, scale * axis, scale * cross(rb, axis));
    } else {
      value += relative_turn(a, b);
      row.add(ja, Vec2(0, 0), -scale);
      row.add(jb, Vec2(0, 0), scale);
    }
    row.value += scale * value;
  }
  Real k = 0;
  for (int i = 0; i < row.count; ++i) {
    const GearTerm& t = row.terms[static_cast<std::size_t>(i)];
    k += t.inv_mass * t.linear.squaredNorm() + t.inv_inertia * t.angular * t.angular;
  }
  row.mass = k > 0 ? 1 / k : 0;
  return row;
}

Real row_velocity(const GearRow& row, const SolverBody* bodies) {
  Real v = 0;
  for (int i = 0; i < row.count; ++i) {
    const GearTerm& t = row.terms[static_cast<std::size_t>(i)];
    const SolverBody& s = bodies[t.solver];
    v += t.linear.dot(velocity_of(s)) + t.angular * s.w;
  }
  return v;
}

void apply_row(const GearRow& row, SolverBody* bodies, Real impulse) {
  for (int i = 0; i < row.count; ++i) {
    const GearTerm& t = row.terms[static_cast<std::size_t>(i)];
    SolverBody& s = bodies[t.solver];
    s.vx += t.inv_mass * impulse * t.linear.x();
    s.vy += t.inv_mass * impulse * t.linear.y();
    s.w += t.inv_inertia * impulse * t.angular;
  }
}

Real constant_of(const GearJoint& joint) {
  return joint.joints[0].created + joint.def.ratio * joint.joints[1].created;
}

}  // namespace

void attach(GearJoint& gear, std::size_t slot, const JointDef& geared, Real coordinate) {
  GearedJoint& g = gear.joints[slot];
  g = GearedJoint{};
  if (const auto* p = std::get_if<PrismaticJointDef>(&geared)) {
    g.prismatic = true;
    g.local_anchor_a = p->local_anchor_a;
    g.local_anchor_b = p->local_anchor_b;
    g.local_axis_a = p->local_axis_a;
  }
  g.created = coordinate;
}

void prepare(GearJoint& joint, JointFrame& frame) {
  for (std::size_t g = 0; g < 2; ++g) {
    GearedJoint& geared = joint.joints[g];
    if (!geared.prismatic) continue;
    const JointBodyStart& b = frame.starts[g];
    const JointBodyStart& a = frame.starts[g + 2];
    geared.anchor_a = a.rotation.apply(geared.local_anchor_a - a.local_center);
    geared.anchor_b = b.rotation.apply(geared.local_anchor_b - b.local_center);
    geared.axis = a.rotation.apply(geared.local_axis_a);
    geared.delta_center = b.center - a.center;
    // The step's translations are measured from this, so the prismatic joint's own coordinate
    // (frame.coordinate_*) stays the reference whatever its origin.
    geared.start_translation =
        geared.axis.dot(geared.delta_center + geared.anchor_b - geared.anchor_a);
  }
}

void warm_start(const GearJoint& joint, const JointFrame& frame, SolverBody* bodies) {
  apply_row(gear_row(joint, frame, bodies), bodies, joint.impulse);
}

void solve(GearJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias) {
  const GearRow row = gear_row(joint, frame, bodies);
  const Real error = row.value - constant_of(joint);
  Real bias = 0, mass_scale = 1, impulse_scale = 0;
  if (use_bias) {
    bias = frame.soft.bias_rate * error;
    mass_scale = frame.soft.mass_scale;
    impulse_scale = frame.soft.impulse_scale;
  }
  const Real cdot = row_velocity(row, bodies);
  const Real p = -mass_scale * row.mass * (cdot + bias) - impulse_scale * joint.impulse;
  joint.impulse += p;
  apply_row(row, bodies, p);
}

JointReaction reaction(const GearJoint& joint, const JointFrame& frame) {
  // On body B (joint2's B), with its row terms as the step began.
  const GearedJoint& geared = joint.joints[1];
  const Real p = joint.def.ratio * joint.impulse * frame.inv_h;
  if (!geared.prismatic) return {Vec2(0, 0), p};
  return {p * geared.axis, p * cross(geared.anchor_b, geared.axis)};
}

void draw(const GearJoint&, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw) {
  // The two geared bodies, linked.
  draw.draw_segment(a.center, b.center, kJointColor);
  draw.draw_point(a.center, 5, kJointColor);
  draw.draw_point(b.center, 5, kJointColor);
}

}  // namespace mink::detail
