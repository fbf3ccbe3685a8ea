#include "collide_circles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace mink::detail {

namespace {

// One point between A's core point `on_a` and B's `on_b` (world), each grown by its radius
// along `normal` (A to B).
Manifold one_point(const Vec2& normal, const Vec2& on_a, Real radius_a, const Vec2& on_b,
                   Real radius_b, Real separation) {
  Manifold m;
  m.normal = normal;
  m.point_count = 1;
  m.points[0].point = 0.5 * ((on_a + radius_a * normal) + (on_b - radius_b * normal));
  m.points[0].separation = separation;
  m.points[0].id = 0;
  return m;
}

}  // namespace

Manifold collide_circles(const Circle& a, const Pose& pose_a, const Circle& b, const Pose& pose_b,
                         Real speculative_distance) {
  const Vec2 ca = pose_a.apply(a.center);
  const Vec2 cb = pose_b.apply(b.center);
  const Vec2 d = cb - ca;
  const Real distance = d.norm();
  const Real separation = distance - a.radius - b.radius;
  if (separation > speculative_distance) return {};
  // Concentric: every direction is as good; A's +y.
  const Vec2 normal = distance > 0 ? Vec2(d / distance) : pose_a.rotation.apply(Vec2(0, 1));
  return one_point(normal, ca, a.radius, cb, b.radius, separation);
}

namespace {

// The core's feature nearest `c` (B's local frame): `to_centre` is the unit direction from it
// to c, `distance` how far c lies beyond it (negative inside a hull). nearest_on_hull gives
// false when c lies beyond `reach` for certain.
struct Nearest {
  Vec2 point{0, 0};
  Vec2 to_centre{0, 1};
  Real distance = 0;
};

void nearest_on_segment(const Vec2& p, const Vec2& q, const Vec2& c, Nearest& n) {
  const Vec2 e = q - p;
  const Real length_squared = e.squaredNorm();
  Real t = length_squared > 0 ? (c - p).dot(e) / length_squared : 0;
  t = std::clamp<Real>(t, 0, 1);
  n.point = p + t * e;
  const Vec2 d = c - n.point;
  n.distance = d.norm();
  if (n.distance > 0) {
    n.to_centre = d / n.distance;
  } else if (length_squared > 0) {
    // The centre on the segment: its left side (the segment's first face) is as good as any.
    n.to_centre = Vec2(-e.y(), e.x()) / std::sqrt(length_squared);
  }
}

bool nearest_on_hull(const PreparedHull& hull, const Vec2& c, Real reach, Nearest& n) {
  const std::span<const Vec2> v = hull.vertices();
  const std::span<const Vec2> normals = hull.normals();
  const std::size_t count = v.size();
  std::size_t face = 0;
  Real best = -std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const Real s = normals[i].dot(c - v[i]);
    if (s > best) {
      best = s;
      face = i;
    }
  }
  if (best > reach) return false;
  const Vec2& v1 = v[face];
  const Vec2& v2 = v[face + 1 == count ? 0 : face + 1];
  // Outside, beyond an end of the face of greatest separation: the nearest feature is that
  // end's vertex; otherwise the face itself (inside the hull as well).
  const Vec2* corner = nullptr;
  if (best > 0) {
    if ((c - v1).dot(v2 - v1) < 0) {
      corner = &v1;
    } else if ((c - v2).dot(v1 - v2) < 0) {
      corner = &v2;
    }
  }
  if (corner != nullptr) {
    const Vec2 d = c - *corner;
    n.point = *corner;
    n.distance = d.norm();
    n.to_centre = n.distance > 0 ? Vec2(d / n.distance) : normals[face];
    return true;
  }
  n.to_centre = normals[face];
  n.distance = best;
  n.point = c - best * normals[face];
  return true;
}

}  // namespace

Manifold collide_circle_core(const Circle& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                             Real speculative_distance) {
  const Vec2 centre = pose_a.apply(a.center);
  const Vec2 c = pose_b.apply_inverse(centre);
  const Real radii = a.radius + b.radius;
  Nearest n;
  if (b.hull != nullptr) {
    if (!nearest_on_hull(*b.hull, c, radii + speculative_distance, n)) return {};
  } else {
    nearest_on_segment(b.small[0], b.count == 2 ? b.small[1] : b.small[0], c, n);
  }
  const Real separation = n.distance - radii;
  if (separation > speculative_distance) return {};
  return one_point(-pose_b.rotation.apply(n.to_centre), centre, a.radius, pose_b.apply(n.point),
                   b.radius, separation);
}

}  // namespace mink::detail
