#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace mink {

// Handles in the style of Box2D v3: a slot index plus the slot's generation when the handle
// was issued. Destroying the object bumps the generation, so a kept handle is detected as
// stale instead of silently reaching whatever reuses the slot.
struct BodyId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t generation = 0;
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const BodyId&) const = default;
};

struct ShapeId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t generation = 0;
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const ShapeId&) const = default;
};

std::string to_string(BodyId id);
std::string to_string(ShapeId id);

}  // namespace mink
