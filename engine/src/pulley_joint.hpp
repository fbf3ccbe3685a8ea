#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct PulleyJoint {
  PulleyJointDef def;
};

void prepare(PulleyJoint& joint, JointFrame& frame);
void warm_start(const PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(PulleyJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const PulleyJoint& joint, const JointFrame& frame);
void finish(PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const PulleyJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
