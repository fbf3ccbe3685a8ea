#pragma once

#include "mink/geometry/convex_hull.hpp"

namespace mink {

// A hull in its shape's local frame, with what queries need precomputed once at shape
// creation (centroid, edge normals, search structures for large vertex counts).
class PreparedHull {
 public:
  explicit PreparedHull(ConvexHull hull);

  const ConvexHull& hull() const noexcept { return hull_; }
  std::span<const Vec2> vertices() const noexcept { return hull_.vertices(); }
  std::size_t size() const noexcept { return hull_.size(); }
  const Vec2& centroid() const noexcept { return centroid_; }

 private:
  ConvexHull hull_;
  Vec2 centroid_{0, 0};
};

}  // namespace mink
