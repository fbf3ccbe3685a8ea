#pragma once

#include <cmath>

#include "mink/geometry/types.hpp"

namespace mink {

/// @brief A rotation stored as its cosine and sine, so applying it costs four multiplies and the
/// angle is never re-evaluated per vertex.
struct Rotation {
  Real cos = 1;  ///< cosine of the angle
  Real sin = 0;  ///< sine of the angle

  /// @brief The rotation by `radians` counter-clockwise.
  static Rotation from_angle(Real radians) { return {std::cos(radians), std::sin(radians)}; }
  /// @brief The angle in radians, in [-pi, pi].
  Real angle() const { return std::atan2(sin, cos); }
  /// @brief `v` rotated counter-clockwise by the angle.
  Vec2 apply(const Vec2& v) const { return {cos * v.x() - sin * v.y(), sin * v.x() + cos * v.y()}; }
  /// @brief `v` rotated back (clockwise) by the angle.
  Vec2 apply_inverse(const Vec2& v) const {
    return {cos * v.x() + sin * v.y(), -sin * v.x() + cos * v.y()};
  }
};

/// A rigid transform: rotate about the local origin, then translate. Shapes keep their hull
/// in local coordinates (scale is applied once, when the shape is created) and are posed by this.
struct Pose {
  Vec2 position{0, 0};  ///< where the local origin lies in the world
  Rotation rotation{};  ///< orientation of the local axes in the world

  /// @brief A local point in world coordinates.
  Vec2 apply(const Vec2& local) const { return rotation.apply(local) + position; }
  /// @brief A world point in local coordinates.
  Vec2 apply_inverse(const Vec2& world) const { return rotation.apply_inverse(world - position); }
};

/// @brief B's pose in A's frame: A's pose applied after it gives B's, up to rounding.
inline Pose relative_pose(const Pose& a, const Pose& b) {
  const Rotation& ra = a.rotation;
  const Rotation& rb = b.rotation;
  Pose relative;
  relative.rotation = {ra.cos * rb.cos + ra.sin * rb.sin, ra.cos * rb.sin - ra.sin * rb.cos};
  relative.position = ra.apply_inverse(b.position - a.position);
  return relative;
}

}  // namespace mink
