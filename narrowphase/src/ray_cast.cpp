#include "mink/narrowphase/ray_cast.hpp"

#include <limits>

namespace mink {

std::optional<RayHit> ray_cast_hull(const ConvexHull& hull, const Pose& pose, const Vec2& origin,
                                    const Vec2& translation) {
  // In the hull's frame the hull is the intersection of its edges' inner half planes; clip
  // the parameter interval [0, 1] against each (Cyrus-Beck).
  const Vec2 p = pose.apply_inverse(origin);
  const Vec2 d = pose.rotation.apply_inverse(translation);
  const auto vertices = hull.vertices();
  const std::size_t n = vertices.size();
  Real lower = 0, upper = 1;
  std::size_t entering_edge = n;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = vertices[i];
    const Vec2& b = vertices[(i + 1) % n];
    const Vec2 edge = b - a;
    const Vec2 normal(edge.y(), -edge.x());  // outward for a counter-clockwise ring
    // Inside where dot(normal, x - a) <= 0: numerator + t * denominator <= 0.
    const Real numerator = normal.dot(p - a);
    const Real denominator = normal.dot(d);
    if (denominator == 0) {
      if (numerator > 0) return std::nullopt;  // parallel and outside this edge
      continue;
    }
    const Real t = -numerator / denominator;
    if (denominator < 0) {
      if (t > lower) {
        lower = t;
        entering_edge = i;
      }
    } else if (t < upper) {
      upper = t;
    }
    if (upper < lower) return std::nullopt;
  }
  if (entering_edge == n) return std::nullopt;  // starts inside
  const Vec2 edge = vertices[(entering_edge + 1) % n] - vertices[entering_edge];
  RayHit hit;
  hit.fraction = lower;
  hit.point = origin + lower * translation;
  hit.normal = pose.rotation.apply(Vec2(edge.y(), -edge.x()).normalized());
  return hit;
}

bool hull_contains(const ConvexHull& hull, const Pose& pose, const Vec2& point) {
  const Vec2 p = pose.apply_inverse(point);
  const auto vertices = hull.vertices();
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 edge = vertices[(i + 1) % n] - vertices[i];
    const Vec2 r = p - vertices[i];
    if (edge.x() * r.y() - edge.y() * r.x() < 0) return false;
  }
  return true;
}

}  // namespace mink
