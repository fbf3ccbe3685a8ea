#pragma once

#include "joint_common.hpp"

namespace mink::detail {

// A wheel joint: B's anchor kept on the line through A's anchor along A's axis (one rigid
// row across it); along the axis a suspension spring and limits; B spins freely, or driven
// by an angular motor.
struct WheelJoint {
  WheelJointDef def;
  // Accumulated impulses, kept between steps for warm starting.
  Real perp_impulse = 0, spring_impulse = 0, lower_impulse = 0, upper_impulse = 0;
  Real motor_impulse = 0;  // angular
  // Prepared for the step.
  Vec2 axis{0, 1};      // world axis at step start
  Real motor_mass = 0;  // 1 / (iA + iB)
  Softness spring_soft;
};

// The functions every joint kind implements (see joint.cpp for when each runs).
void prepare(WheelJoint& joint, JointFrame& frame);
void warm_start(const WheelJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(WheelJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const WheelJoint& joint, const JointFrame& frame);
Real coordinate(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b);
Real speed(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b);
void draw(const WheelJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
