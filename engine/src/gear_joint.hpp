#pragma once

#include <array>
#include <cstddef>

#include "joint_common.hpp"

namespace mink::detail {

// What a gear keeps of one of its joints: enough to follow that joint's coordinate through the
// substeps from the bodies' motion (a revolute's relative angle, a prismatic's translation).
struct GearedJoint {
  bool prismatic = false;
  Vec2 local_anchor_a{0, 0}, local_anchor_b{0, 0};
  Vec2 local_axis_a{1, 0};
  Real created = 0;  // the joint's coordinate when the gear was made
  // Prepared for the step (prismatic only): the anchors from each centre of mass and the axis,
  // world-rotated at step start, B's centre minus A's, and the translation they give then.
  Vec2 anchor_a{0, 0}, anchor_b{0, 0}, axis{1, 0}, delta_center{0, 0};
  Real start_translation = 0;
};

// A gear: coordinate1 + ratio * coordinate2 held at its value when the gear was made, one
// rigid row on the four bodies of its two joints (frame bodies: joint1.B, joint2.B, joint1.A,
// joint2.A). Its coordinate and speed are its joints' (WorldState::joint_coordinate), as its
// own two bodies cannot give them.
struct GearJoint {
  GearJointDef def;
  std::array<GearedJoint, 2> joints{};
  Real impulse = 0;  // accumulated, kept between steps for warm starting
};

// Called by create_joint before the gear is first solved: the gear's joint `slot` (0 for
// joint1, 1 for joint2) has definition `geared` (revolute or prismatic) and coordinate
// `coordinate` now, which fixes the gear's constant.
void attach(GearJoint& gear, std::size_t slot, const JointDef& geared, Real coordinate);

void prepare(GearJoint& joint, JointFrame& frame);
void warm_start(const GearJoint& joint, const JointFrame& frame, SolverBody* bodies);
void solve(GearJoint& joint, const JointFrame& frame, SolverBody* bodies, bool use_bias);
JointReaction reaction(const GearJoint& joint, const JointFrame& frame);
void draw(const GearJoint& joint, const JointBodyState& a, const JointBodyState& b,
          DebugDraw& draw);

}  // namespace mink::detail
