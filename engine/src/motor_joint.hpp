#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A motor joint: B's origin driven towards a point fixed in A and B's angle towards one
// relative to A, by velocity rows whose target speeds remove a fraction of the error and
// whose impulses are bounded by the maximum force and torque.
struct MotorJoint {
  MotorJointDef def;
  // Accumulated impulses, kept between steps for warm starting.
  Vec2 linear_impulse{0, 0};
  Real angular_impulse = 0;
  // Prepared for the step.
  Real axial_mass = 0;   // 1 / (iA + iB)
  Real angle_error = 0;  // relative angle minus the target at step start, wrapped
};

// The functions every joint kind implements (see joint.cpp for when each runs).
void prepare(MotorJoint& joint, JointFrame& frame);
void warm_start(const MotorJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(MotorJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const MotorJoint& joint, const JointFrame& frame);
void draw(const MotorJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
