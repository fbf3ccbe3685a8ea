#include <algorithm>
#include <cmath>
#include <limits>

#include "gjk_distance_loop.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "shape_core.hpp"

namespace mink {

namespace {

Vec2 closest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const Real len2 = e.squaredNorm();
  const Real t = len2 > 0 ? std::clamp((p - a).dot(e) / len2, Real(0), Real(1)) : 0;
  return a + t * e;
}

// The point of the core (local) nearest `p` (local), and whether p is inside a hull core.
struct CorePoint {
  Vec2 point{0, 0};
  bool inside = false;
};

CorePoint closest_on_core(const detail::Core& core, const Vec2& p) {
  if (core.hull == nullptr) {
    return {core.size() == 1 ? core.small[0] : closest_on_segment(p, core.small[0], core.small[1]),
            false};
  }
  const std::span<const Vec2> v = core.hull->vertices();
  const std::span<const Vec2> normals = core.hull->normals();
  const std::span<const Real> offsets = core.hull->face_offsets();
  bool inside = true;
  for (std::size_t i = 0; i < v.size(); ++i) inside = inside && normals[i].dot(p) <= offsets[i];
  if (inside) return {p, true};
  CorePoint best{v[0], false};
  Real best_d2 = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 q = closest_on_segment(p, v[i], v[i + 1 == v.size() ? 0 : i + 1]);
    const Real d2 = (p - q).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.point = q;
    }
  }
  return best;
}

}  // namespace

Aabb compute_aabb(const ShapeGeometry& geometry, const Pose& pose) {
  const detail::Core core = detail::core_of(geometry);
  Vec2 lower = pose.apply(core.point(0));
  Vec2 upper = lower;
  for (std::size_t i = 1; i < core.size(); ++i) {
    const Vec2 p = pose.apply(core.point(i));
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const Vec2 r(core.radius, core.radius);
  return {lower - r, upper + r};
}

bool contains_point(const ShapeGeometry& geometry, const Pose& pose, const Vec2& point) {
  const ShapeKind kind = kind_of(geometry);
  if (kind == ShapeKind::segment || kind == ShapeKind::chain_segment) return false;
  const detail::Core core = detail::core_of(geometry);
  const Vec2 p = pose.apply_inverse(point);
  if (kind == ShapeKind::polygon && core.radius == 0) {
    return hull_contains(core.hull->hull(), Pose{}, p);
  }
  const CorePoint nearest = closest_on_core(core, p);
  return nearest.inside || (p - nearest.point).squaredNorm() <= core.radius * core.radius;
}

Vec2 closest_point(const ShapeGeometry& geometry, const Pose& pose, const Vec2& point) {
  const detail::Core core = detail::core_of(geometry);
  const Vec2 p = pose.apply_inverse(point);
  const CorePoint nearest = closest_on_core(core, p);
  if (nearest.inside) return point;
  const Vec2 gap = p - nearest.point;
  const Real distance = gap.norm();
  if (distance <= core.radius) return point;  // inside the rounding
  return pose.apply(nearest.point + (core.radius / distance) * gap);
}

ShapeDistance shape_distance(const ShapeGeometry& a, const Pose& pose_a, const ShapeGeometry& b,
                             const Pose& pose_b) {
  const detail::Core ca = detail::core_of(a);
  const detail::Core cb = detail::core_of(b);
  ShapeDistance result;
  Vec2 core_a, core_b, normal;  // world
  Real distance = 0;
  bool cores_overlap = false;
  if (ca.hull != nullptr && cb.hull != nullptr) {
    // Two hulls: the prepared-hull GJK, the engine's fast path.
    const DistanceResult d = gjk_distance(*ca.hull, pose_a, *cb.hull, pose_b);
    cores_overlap = d.overlap;
    distance = d.distance;
    core_a = d.point_a;
    core_b = d.point_b;
    normal = d.normal;
  } else {
    const detail::CoreFrame frame(ca, cb, relative_pose(pose_a, pose_b));
    const detail::LocalDistance d = detail::distance_loop(frame, nullptr);
    cores_overlap = d.overlap;
    distance = d.distance;
    core_a = pose_a.apply(d.point_a);
    core_b = pose_a.apply(d.point_b);
    if (!d.overlap) normal = pose_a.rotation.apply(d.gap / d.distance);
  }
  const Real radii = ca.radius + cb.radius;
  if (cores_overlap || distance <= radii) {
    result.overlap = true;
    result.point_a = core_a;
    result.point_b = core_b;
    return result;
  }
  result.distance = distance - radii;
  result.normal = normal;
  result.point_a = core_a + ca.radius * normal;
  result.point_b = core_b - cb.radius * normal;
  return result;
}

}  // namespace mink
