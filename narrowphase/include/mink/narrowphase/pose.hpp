#pragma once

#include <cmath>

#include "mink/geometry/types.hpp"

namespace mink {

// A rotation stored as its cosine and sine, so applying it costs four multiplies and the
// angle is never re-evaluated per vertex.
struct Rotation {
  Real cos = 1;
  Real sin = 0;

  static Rotation from_angle(Real radians) { return {std::cos(radians), std::sin(radians)}; }
  Real angle() const { return std::atan2(sin, cos); }
  Vec2 apply(const Vec2& v) const { return {cos * v.x() - sin * v.y(), sin * v.x() + cos * v.y()}; }
  Vec2 apply_inverse(const Vec2& v) const {
    return {cos * v.x() + sin * v.y(), -sin * v.x() + cos * v.y()};
  }
};

// A rigid transform: rotate about the local origin, then translate. Shapes keep their hull in
// local coordinates (scale is applied once, when the shape is created) and are posed by this.
struct Pose {
  Vec2 position{0, 0};
  Rotation rotation{};

  Vec2 apply(const Vec2& local) const { return rotation.apply(local) + position; }
  Vec2 apply_inverse(const Vec2& world) const { return rotation.apply_inverse(world - position); }
};

}  // namespace mink
