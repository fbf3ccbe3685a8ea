#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace mink::detail {

inline constexpr std::uint8_t kGraphColors = 24;  // colours before the overflow
inline constexpr std::uint8_t kOverflowColor = kGraphColors;
inline constexpr std::uint8_t kNoColor = 255;

// The constraint graph: a constraint (a contact now; joints share it) takes a colour when it
// starts acting and keeps it until it stops, such that no two constraints of a colour share a
// body the solver moves. A colour's constraints are then independent and are solved four at a
// time in SIMD lanes, or spread over threads, with nothing to colour per step. Bodies the
// solver never moves (static, kinematic) do not block a colour: several lanes writing back
// their unchanged velocity is harmless. Colours are tried in order, first fit; a constraint
// that finds none joins the overflow, solved one at a time.
class ConstraintGraph {
 public:
  std::uint8_t add(std::uint32_t body_a, bool a_fixed, std::uint32_t body_b, bool b_fixed);
  // Puts a constraint in `color` (one below kGraphColors) if neither of its moving bodies is
  // there yet: what add() tries colour by colour, and what a snapshot's check rebuilds its
  // colours with.
  bool place(std::uint8_t color, std::uint32_t body_a, bool a_fixed, std::uint32_t body_b,
             bool b_fixed);
  void remove(std::uint8_t color, std::uint32_t body_a, bool a_fixed, std::uint32_t body_b,
              bool b_fixed);
  // Per colour, one bit per body: for snapshots.
  std::array<std::vector<std::uint64_t>, kGraphColors>& bits() noexcept { return bits_; }
  // Whether both hold the same bodies in every colour (however long their bit lists).
  bool same_colours(const ConstraintGraph& other) const;

 private:
  std::array<std::vector<std::uint64_t>, kGraphColors> bits_;
};

}  // namespace mink::detail
