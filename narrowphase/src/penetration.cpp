#include "mink/narrowphase/penetration.hpp"

#include <algorithm>
#include <vector>

#include "face_separation.hpp"
#include "mink/geometry/orientation.hpp"
#include "pair_frame.hpp"

namespace mink {

PenetrationResult penetration_by_faces(const PreparedHull& a, const Pose& pose_a,
                                       const PreparedHull& b, const Pose& pose_b) {
  const Pose b_to_a = relative_pose(pose_a, pose_b);
  const Pose a_to_b = detail::inverse(b_to_a);
  const detail::FaceSeparation on_a = detail::max_face_separation(a, b, b_to_a);
  const detail::FaceSeparation on_b = detail::max_face_separation(b, a, a_to_b);
  PenetrationResult result;
  result.used_face_test = true;
  Vec2 normal_local;  // in A's frame
  Vec2 deepest_a;
  if (on_a.separation >= on_b.separation) {
    normal_local = a.normals()[on_a.edge];
    result.depth = std::max<Real>(0, -on_a.separation);
    const std::size_t ib = support_index(b, b_to_a.rotation.apply_inverse(-normal_local));
    // B's deepest vertex pushed out along the normal lands on A's face.
    deepest_a = b_to_a.apply(b.vertices()[ib]) + result.depth * normal_local;
  } else {
    // A face of B: its outward normal points from B towards A.
    normal_local = -b_to_a.rotation.apply(b.normals()[on_b.edge]);
    result.depth = std::max<Real>(0, -on_b.separation);
    deepest_a = a.vertices()[support_index(a, normal_local)];
  }
  result.normal = pose_a.rotation.apply(normal_local);
  result.point_a = pose_a.apply(deepest_a);
  result.point_b = result.point_a - result.depth * result.normal;
  return result;
}

PenetrationResult penetration(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                              const Pose& pose_b, const SimplexCache& start) {
  if (start.count != 3) return penetration_by_faces(a, pose_a, b, pose_b);
  const detail::PairFrame frame(a, pose_a, b, pose_b);
  std::vector<detail::LocalVertex> polygon;
  polygon.reserve(16);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (start.index_a[k] >= a.size() || start.index_b[k] >= b.size()) {
      return penetration_by_faces(a, pose_a, b, pose_b);
    }
    polygon.push_back(frame.vertex(start.index_a[k], start.index_b[k]));
  }
  const int winding = orient2d(polygon[0].point, polygon[1].point, polygon[2].point);
  if (winding == 0) return penetration_by_faces(a, pose_a, b, pose_b);
  if (winding < 0) std::swap(polygon[1], polygon[2]);
  // The origin must be inside (or on) the start triangle for the nearest edge to be the
  // answer; GJK guarantees it up to rounding, which is checked exactly here.
  const Vec2 origin(0, 0);
  for (std::size_t i = 0; i < 3; ++i) {
    if (orient2d(polygon[i].point, polygon[(i + 1) % 3].point, origin) < 0) {
      return penetration_by_faces(a, pose_a, b, pose_b);
    }
  }

  const Real tolerance = 1e-13 * (a.radius() + b.radius());
  const int cap = static_cast<int>(a.size() + b.size()) + 8;
  PenetrationResult result;
  for (;;) {
    // The polygon edge nearest the origin.
    std::size_t nearest = 0;
    Real nearest_offset = std::numeric_limits<Real>::infinity();
    Vec2 nearest_normal(0, 0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2& p = polygon[i].point;
      const Vec2 e = polygon[(i + 1) % polygon.size()].point - p;
      const Vec2 n = detail::rescaled_direction(Vec2(e.y(), -e.x())).normalized();
      const Real offset = n.dot(p);
      if (offset < nearest_offset) {
        nearest = i;
        nearest_offset = offset;
        nearest_normal = n;
      }
    }
    const std::size_t next = (nearest + 1) % polygon.size();
    const detail::LocalVertex w = frame.support(nearest_normal);
    const bool repeated =
        (w.index_a == polygon[nearest].index_a && w.index_b == polygon[nearest].index_b) ||
        (w.index_a == polygon[next].index_a && w.index_b == polygon[next].index_b);
    if (repeated || nearest_normal.dot(w.point) - nearest_offset <= tolerance) {
      // This edge is an edge of A - B: the origin's nearest way out.
      const Vec2 p = polygon[nearest].point;
      const Vec2 e = polygon[next].point - p;
      const Real len2 = e.squaredNorm();
      const Real t = len2 > 0 ? std::clamp(-p.dot(e) / len2, Real(0), Real(1)) : 0;
      const Vec2& a0 = a.vertices()[polygon[nearest].index_a];
      const Vec2& a1 = a.vertices()[polygon[next].index_a];
      const Vec2 local_a = a0 + t * (a1 - a0);
      result.depth = std::max<Real>(0, nearest_offset);
      result.normal = pose_a.rotation.apply(nearest_normal);
      result.point_a = pose_a.apply(local_a);
      result.point_b = result.point_a - result.depth * result.normal;
      return result;
    }
    if (result.iterations >= cap) return penetration_by_faces(a, pose_a, b, pose_b);
    ++result.iterations;
    polygon.insert(polygon.begin() + static_cast<std::ptrdiff_t>(next), w);
  }
}

}  // namespace mink
