#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace mink {

/// Handle to a body.
/// Handles in the style of Box2D v3: a slot index plus the slot's generation when the handle
/// was issued. Destroying the object bumps the generation, so a kept handle is detected as
/// stale instead of silently reaching whatever reuses the slot.
struct BodyId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< slot; max() when null
  std::uint32_t generation = 0;  ///< the slot's generation at issue
  /// @brief True for a default-constructed id, which names nothing.
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const BodyId&) const = default;
};

/// @brief Handle to a shape; generation-checked like BodyId.
struct ShapeId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< slot; max() when null
  std::uint32_t generation = 0;  ///< the slot's generation at issue
  /// @brief True for a default-constructed id, which names nothing.
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const ShapeId&) const = default;
};

/// @brief "BodyId{index I, generation G}", as error messages name ids.
std::string to_string(BodyId id);
/// @brief "ShapeId{index I, generation G}".
std::string to_string(ShapeId id);

}  // namespace mink
