#pragma once

#include "mink/geometry/types.hpp"

namespace mink {

/// Axis-aligned bounding box; `lower` <= `upper` component-wise. Touching boxes overlap.
struct Aabb {
  Vec2 lower{0, 0};
  Vec2 upper{0, 0};

  bool overlaps(const Aabb& other) const {
    return lower.x() <= other.upper.x() && other.lower.x() <= upper.x() &&
           lower.y() <= other.upper.y() && other.lower.y() <= upper.y();
  }
  bool contains(const Vec2& point) const {
    return lower.x() <= point.x() && point.x() <= upper.x() && lower.y() <= point.y() &&
           point.y() <= upper.y();
  }
  bool contains(const Aabb& other) const {
    return lower.x() <= other.lower.x() && lower.y() <= other.lower.y() &&
           other.upper.x() <= upper.x() && other.upper.y() <= upper.y();
  }
  /// The smallest box holding both.
  Aabb merged(const Aabb& other) const {
    return {lower.cwiseMin(other.lower), upper.cwiseMax(other.upper)};
  }
  Aabb fattened(Real margin) const {
    return {lower - Vec2(margin, margin), upper + Vec2(margin, margin)};
  }
};

}  // namespace mink
