#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "constraint_graph.hpp"
#include "joint_kinds.hpp"

namespace mink::detail {

// A joint record: its kind's settings and solver state, its bodies (slots), its place in the
// constraint graph and what the last step measured.
struct Joint {
  JointKind kind;
  // Bodies by slot: A and B; a gear also C and D (the A bodies of its two joints).
  std::array<std::uint32_t, 4> body{};
  int body_count = 2;
  std::array<std::uint32_t, 2> gear_joints{};  // a gear's joints (slots)
  std::vector<std::uint32_t> gears;            // gears built on this joint (slots)
  bool alive = false;
  std::uint32_t generation = 0;
  // Constraint graph colour, and the body flags it was taken with (so it can be given back).
  std::uint8_t color = kNoColor;
  bool a_fixed = false, b_fixed = false;
  JointFrame frame;
  JointReaction reaction;  // of the last step it was solved in
};

// A joint's bodies as the island pass and the step's gathering of joints read them: a
// compact copy of Joint::body, body_count and color per joint slot (count 0 while the slot is
// free), so those passes stay off the kilobyte records.
struct JointBodies {
  std::array<std::uint32_t, 4> body{};
  std::uint32_t count = 0;
  std::uint8_t color = kNoColor;
};

// Forgets the impulses a joint warm starts from, and its last reaction (divergence.cpp): its
// bodies were stopped where the step began.
void forget_impulses(Joint& joint);

// A kind's end-of-step bookkeeping, free coordinate and its rate: kinds without one (a weld,
// a motor joint) leave the function out and read 0.
template <typename Kind>
void finish_kind(Kind& kind, const JointBodyState& a, const JointBodyState& b) {
  if constexpr (requires { finish(kind, a, b); }) finish(kind, a, b);
}
template <typename Kind>
Real coordinate_of(const Kind& kind, const JointBodyState& a, const JointBodyState& b) {
  if constexpr (requires { coordinate(kind, a, b); }) {
    return coordinate(kind, a, b);
  } else {
    return 0;
  }
}
template <typename Kind>
Real speed_of(const Kind& kind, const JointBodyState& a, const JointBodyState& b) {
  if constexpr (requires { speed(kind, a, b); }) {
    return speed(kind, a, b);
  } else {
    return 0;
  }
}

// The settings every kind shares.
inline const JointBase& base(const Joint& joint) {
  return std::visit([](const auto& k) -> const JointBase& { return k.def; }, joint.kind);
}
inline JointBase& base(Joint& joint) {
  return std::visit([](auto& k) -> JointBase& { return k.def; }, joint.kind);
}
// The joint's settings as its kind's definition.
inline JointDef def_of(const Joint& joint) {
  return std::visit([](const auto& k) -> JointDef { return k.def; }, joint.kind);
}
// The API's checks of a joint definition (World::create_joint's, which the snapshot loader
// runs as well): throws InvalidArgumentError naming the offending field.
void check_joint_def(const JointDef& def);

inline JointType type_of(const Joint& joint) {
  return static_cast<JointType>(joint.kind.index());
}

}  // namespace mink::detail
