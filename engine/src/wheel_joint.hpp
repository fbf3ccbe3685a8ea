#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct WheelJoint {
  WheelJointDef def;
};

void prepare(WheelJoint& joint, JointFrame& frame);
void warm_start(const WheelJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(WheelJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const WheelJoint& joint, const JointFrame& frame);
void finish(WheelJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
