#include "collide_circles.hpp"

namespace mink::detail {

Manifold collide_circles(const Circle& a, const Pose& pose_a, const Circle& b, const Pose& pose_b,
                         Real speculative_distance) {
  Manifold m;
  const Vec2 ca = pose_a.apply(a.center);
  const Vec2 cb = pose_b.apply(b.center);
  const Vec2 d = cb - ca;
  const Real distance = d.norm();
  const Real separation = distance - a.radius - b.radius;
  if (separation > speculative_distance) return m;
  // Concentric: every direction is as good; A's +y.
  const Vec2 normal = distance > 0 ? Vec2(d / distance) : pose_a.rotation.apply(Vec2(0, 1));
  m.normal = normal;
  m.point_count = 1;
  m.points[0].point = 0.5 * ((ca + a.radius * normal) + (cb - b.radius * normal));
  m.points[0].separation = separation;
  m.points[0].id = 0;
  return m;
}

}  // namespace mink::detail
