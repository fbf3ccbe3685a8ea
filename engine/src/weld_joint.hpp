#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct WeldJoint {
  WeldJointDef def;
};

void prepare(WeldJoint& joint, JointFrame& frame);
void warm_start(const WeldJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(WeldJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const WeldJoint& joint, const JointFrame& frame);
void finish(WeldJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const WeldJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const WeldJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const WeldJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
