#include "mink/geometry/polygon.hpp"

#include <string>

#include "mink/error.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

Real signed_area(std::span<const Vec2> polygon) {
  if (polygon.size() < 3) return 0;
  const Vec2& origin = polygon[0];
  Real twice_area = 0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec2 a = polygon[i] - origin;
    const Vec2 b = polygon[i + 1] - origin;
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  return twice_area / 2;
}

AreaProperties area_properties(std::span<const Vec2> polygon) {
  if (polygon.size() < 3) {
    throw DegenerateInputError("a polygon needs at least 3 vertices, got " +
                               std::to_string(polygon.size()));
  }
  // Rounding can leave a small nonzero area for vertices that lie exactly on one line, so
  // flatness is decided by the exact predicate, not by the computed area.
  if (all_on_one_line(polygon)) {
    throw DegenerateInputError("polygon of " + std::to_string(polygon.size()) +
                               " vertices has zero area (all on one line)");
  }
  // Fan of triangles (origin, a, b) about the first vertex: the shoelace terms of eq. 3 with
  // the origin moved to that vertex, which keeps far-from-origin polygons precise.
  const Vec2& origin = polygon[0];
  Real twice_area = 0;
  Vec2 first_moment_6{0, 0};  // 6 * integral of r dA
  Real second_moment_12 = 0;  // 12 * integral of |r|^2 dA, r from the origin vertex
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec2 a = polygon[i] - origin;
    const Vec2 b = polygon[i + 1] - origin;
    const Real cross = a.x() * b.y() - a.y() * b.x();
    twice_area += cross;
    first_moment_6 += cross * (a + b);
    second_moment_12 += cross * (a.squaredNorm() + a.dot(b) + b.squaredNorm());
  }
  if (twice_area == 0) {
    throw DegenerateInputError("polygon of " + std::to_string(polygon.size()) +
                               " vertices has zero area");
  }
  AreaProperties properties;
  properties.area = twice_area / 2;
  const Vec2 offset = first_moment_6 / (3 * twice_area);
  properties.centroid = origin + offset;
  // Parallel-axis theorem: move the second moment from the origin vertex to the centroid.
  properties.polar_moment = second_moment_12 / 12 - properties.area * offset.squaredNorm();
  return properties;
}

Vec2 centroid(std::span<const Vec2> polygon) {
  return area_properties(polygon).centroid;
}

}  // namespace mink
