#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct PrismaticJoint {
  PrismaticJointDef def;
};

void prepare(PrismaticJoint& joint, JointFrame& frame);
void warm_start(const PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const PrismaticJoint& joint, const JointFrame& frame);
void finish(PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
