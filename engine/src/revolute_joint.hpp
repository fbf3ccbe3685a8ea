#pragma once

#include "joint_common.hpp"
#include "joint_rows.hpp"
#include "revolute_rows.hpp"

namespace mink::detail {

// What a revolute joint's rows keep between substeps and read of its preparing: its impulses,
// accumulated and kept between steps for warm starting, and its prepared masses and flags.
struct RevoluteRowState {
  Vec2 linear_impulse{0, 0};
  Real spring_impulse = 0, motor_impulse = 0, lower_impulse = 0, upper_impulse = 0;
  bool direct = false;  // its point row is solved with its chain's (joint_chain_solver.hpp)
  // Prepared for the step. Whether an angle row (spring, motor, limit) is on and the pair can
  // turn: beside `direct`, so a plain pin's solve reads one line of the record, not the
  // definition's three (in a large net of pins those reads were most of the solve).
  bool angle_rows = false;
  Real axial_mass = 0;
  Softness spring_soft;
};

// A revolute joint: a point constraint, plus on the relative angle a spring, a motor and
// limits, each its own row solved in that order (the point last, as it matters most). The
// solver's state first and the definition after it: a plain pin's solve then reads the
// record's first line only.
struct RevoluteJoint : RevoluteRowState {
  Real angle = 0;  // the joint angle at the end of the last step, counted through full turns
  RevoluteJointDef def;
};

// The joint's rows in the solver's precision (revolute_rows.hpp) from its prepared record and
// frame: its point row too unless its chain solves that (`direct`). And the rows' impulses back.
RevoluteRow revolute_row(const RevoluteJoint& joint, const JointFrame& frame);
void store_row(const RevoluteRow& row, RevoluteJoint& joint);

// The functions every joint kind implements (see joint_solver.cpp for when each runs);
// finish, coordinate and speed only where the kind has something to say (joint.hpp).
void prepare(RevoluteJoint& joint, JointFrame& frame);
// A revolute joint with no spring, motor or limit, solved as a pin (joint_solver.hpp): only
// what its pin row reads, its anchors, is prepared in `frame`.
void prepare_pin(RevoluteJoint& joint, JointFrame& frame);
void warm_start(const RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(RevoluteJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const RevoluteJoint& joint, const JointFrame& frame);
// The same for substeps of 1 / inv_h (a pin's, whose record's frame is not prepared).
JointReaction reaction(const RevoluteJoint& joint, Real inv_h);
void finish(RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b);
// finish() from what it reads of the bodies: their rotations and the turns the solver counted.
void finish_angle(RevoluteJoint& joint, const Rotation& a, const Rotation& b, Real turned_a,
                  Real turned_b);
Real coordinate(const RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const RevoluteJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
