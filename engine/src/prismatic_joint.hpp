#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A prismatic joint: B's anchor kept on the line through A's anchor along A's axis and the
// relative angle held (together, one 2x2 block), plus along the axis a spring, a motor and
// limits, each its own row.
struct PrismaticJoint {
  PrismaticJointDef def;
  // Accumulated impulses, kept between steps for warm starting: across the axis and on the
  // angle (the block), and along the axis.
  Vec2 block_impulse{0, 0};
  Real spring_impulse = 0, motor_impulse = 0, lower_impulse = 0, upper_impulse = 0;
  // Prepared for the step.
  Vec2 axis{1, 0};       // world axis at step start
  Real angle_error = 0;  // relative angle minus the reference at step start, wrapped
  Softness spring_soft;
};

// The functions every joint kind implements (see joint.cpp for when each runs).
void prepare(PrismaticJoint& joint, JointFrame& frame);
void warm_start(const PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(PrismaticJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const PrismaticJoint& joint, const JointFrame& frame);
Real coordinate(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const PrismaticJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
