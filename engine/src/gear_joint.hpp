#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct GearJoint {
  GearJointDef def;
};

void prepare(GearJoint& joint, JointFrame& frame);
void warm_start(const GearJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(GearJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const GearJoint& joint, const JointFrame& frame);
void finish(GearJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const GearJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const GearJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const GearJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
