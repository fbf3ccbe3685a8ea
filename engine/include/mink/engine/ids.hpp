#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace mink {

/// Handle to a body.
/// Handles in the style of Box2D v3: a slot index plus the slot's generation when the handle
/// was issued, plus the world that issued it. Destroying the object bumps the generation, so a
/// kept handle is detected as stale instead of silently reaching whatever reuses the slot, and
/// a handle from another World is refused.
struct BodyId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< slot; max() when null
  std::uint32_t generation = 0;  ///< the slot's generation at issue
  std::uint32_t world = 0;       ///< the issuing world's serial number (0: none)
  /// @brief True for a default-constructed id, which names nothing.
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const BodyId&) const = default;
};

/// @brief Handle to a shape; generation- and world-checked like BodyId.
struct ShapeId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< slot; max() when null
  std::uint32_t generation = 0;  ///< the slot's generation at issue
  std::uint32_t world = 0;       ///< the issuing world's serial number (0: none)
  /// @brief True for a default-constructed id, which names nothing.
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const ShapeId&) const = default;
};

/// @brief Handle to a joint; generation- and world-checked like BodyId.
struct JointId {
  std::uint32_t index = std::numeric_limits<std::uint32_t>::max();  ///< slot; max() when null
  std::uint32_t generation = 0;  ///< the slot's generation at issue
  std::uint32_t world = 0;       ///< the issuing world's serial number (0: none)
  /// @brief True for a default-constructed id, which names nothing.
  bool is_null() const noexcept { return index == std::numeric_limits<std::uint32_t>::max(); }
  bool operator==(const JointId&) const = default;
};

/// @brief "BodyId{index I, generation G, world W}", as error messages name ids.
std::string to_string(BodyId id);
/// @brief "ShapeId{index I, generation G, world W}".
std::string to_string(ShapeId id);
/// @brief "JointId{index I, generation G, world W}".
std::string to_string(JointId id);

}  // namespace mink
