#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A weld joint: B's anchor held on A's (a point row) and the relative angle held (an angle
// row); each part rigid, or a spring of its own frequency.
struct WeldJoint {
  WeldJointDef def;
  // Accumulated impulses, kept between steps for warm starting.
  Vec2 linear_impulse{0, 0};
  Real angular_impulse = 0;
  // Prepared for the step.
  Real axial_mass = 0;                 // 1 / (iA + iB)
  Real angle_error = 0;                // relative angle minus the reference at step start, wrapped
  Softness linear_soft, angular_soft;  // of the springs (unused by a rigid part)
};

// The functions every joint kind implements (see joint.cpp for when each runs).
void prepare(WeldJoint& joint, JointFrame& frame);
void warm_start(const WeldJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(WeldJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const WeldJoint& joint, const JointFrame& frame);
void draw(const WeldJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
