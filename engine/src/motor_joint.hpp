#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct MotorJoint {
  MotorJointDef def;
};

void prepare(MotorJoint& joint, JointFrame& frame);
void warm_start(const MotorJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(MotorJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const MotorJoint& joint, const JointFrame& frame);
void finish(MotorJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const MotorJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const MotorJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const MotorJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
