#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A distance joint: one row along the line between the anchors. Rigid at `length`; or a
// spring towards it; or, with a limit whose bounds differ, free between them (a rope with
// lower 0). The motor drives the length's rate.
struct DistanceJoint {
  DistanceJointDef def;
  // Accumulated impulses along the line (B pushed away from A when positive).
  Real impulse = 0, lower_impulse = 0, upper_impulse = 0, motor_impulse = 0;
  // Prepared for the step.
  Softness spring_soft;
};

void prepare(DistanceJoint& joint, JointFrame& frame);
void warm_start(const DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(DistanceJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const DistanceJoint& joint, const JointFrame& frame);
Real coordinate(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const DistanceJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
