#pragma once

#include "joint_common.hpp"

namespace mink::detail {

struct DistanceJoint {
  DistanceJointDef def;
};

void prepare(DistanceJoint& joint, JointFrame& frame);
void warm_start(const DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const DistanceJoint& joint, const JointFrame& frame);
void finish(DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real coordinate(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b, DebugDraw& draw);

}  // namespace mink::detail
