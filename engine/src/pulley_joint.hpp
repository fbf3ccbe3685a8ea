#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A pulley: length_a + ratio * length_b held at its value when made, one rigid row.
struct PulleyJoint {
  PulleyJointDef def;
  Real impulse = 0;  // accumulated, kept between steps for warm starting
  // B's rope direction (ground anchor to body) in the last pass, for the reaction.
  Vec2 axis_b{0, -1};
};

void prepare(PulleyJoint& joint, JointFrame& frame);
void warm_start(const PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const PulleyJoint& joint, const JointFrame& frame);
Real coordinate(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
