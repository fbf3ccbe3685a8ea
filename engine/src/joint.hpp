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
  std::uint64_t gathered_step = ~std::uint64_t{0};  // the step that last listed it to solve
  JointFrame frame;
  JointReaction reaction;  // of the last step it was solved in
};

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
inline JointType type_of(const Joint& joint) {
  return static_cast<JointType>(joint.kind.index());
}

}  // namespace mink::detail
