#include "mink/narrowphase/manifold.hpp"

#include <algorithm>
#include <array>

#include "clip.hpp"
#include "face_separation.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/support.hpp"
#include "pair_frame.hpp"

namespace mink {

namespace {

using detail::clip;
using detail::ClipVertex;

// Feature ids: a contact point is a vertex of the incident edge inside the reference face
// (kind 0: reference edge, incident vertex), where the incident edge crosses a side of the
// reference face (kind 1: reference vertex, incident edge), or, when clipping leaves nothing,
// the nearest points of the pair (kind 2: vertex or edge start on each hull). Each stays the
// same while the same features touch. Indices are kept modulo 2^14; bit 30 marks B as the
// reference hull.
constexpr std::uint32_t kIndexMask = 0x3fff;
constexpr std::uint32_t kFlipped = 1u << 30;
enum FeatureKind : std::uint32_t { kVertexInFace = 0, kClipped = 1, kNearest = 2 };

std::uint32_t feature_id(std::uint32_t reference, std::uint32_t incident, FeatureKind kind) {
  return (reference & kIndexMask) | ((incident & kIndexMask) << 14) |
         (static_cast<std::uint32_t>(kind) << 28);
}

// The incident hull's edge most opposed to `normal` (incident frame).
std::uint32_t incident_edge(const PreparedHull& incident, const Vec2& normal) {
  const std::span<const Vec2> normals = incident.normals();
  const std::size_t n = normals.size();
  if (n <= kLinearSupportLimit) {
    std::size_t best = 0;
    Real best_dot = normals[0].dot(normal);
    for (std::size_t i = 1; i < n; ++i) {
      const Real dot = normals[i].dot(normal);
      if (dot < best_dot) {
        best = i;
        best_dot = dot;
      }
    }
    return static_cast<std::uint32_t>(best);
  }
  // The deepest vertex along -normal starts one of the two candidate edges.
  const std::size_t k = support_index(incident, -normal);
  const std::size_t before = k == 0 ? n - 1 : k - 1;
  return static_cast<std::uint32_t>(normals[before].dot(normal) < normals[k].dot(normal) ? before
                                                                                         : k);
}

}  // namespace

Manifold collide_hulls(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                       const Pose& pose_b, Real speculative_distance) {
  Manifold manifold;
  const Pose b_to_a = relative_pose(pose_a, pose_b);
  const detail::FaceSeparation on_a = detail::max_face_separation(a, b, b_to_a);
  if (on_a.separation > speculative_distance) return manifold;
  const Pose a_to_b = detail::inverse(b_to_a);
  const detail::FaceSeparation on_b = detail::max_face_separation(b, a, a_to_b);
  if (on_b.separation > speculative_distance) return manifold;
  // Apart by less than the margin along a face normal. That only bounds the distance from
  // below (corner to corner it is smaller); a clipped point within the margin proves the
  // distance is within it too (it lies that far from a point of the reference face), and
  // without one the true distance decides, below.
  const bool apart = std::max(on_a.separation, on_b.separation) > 0;

  // Prefer A's face unless B's is clearly better, so the choice does not flicker between
  // steps when both are nearly equal (which would reset the feature ids).
  const Real tolerance = 1e-3 * std::min(a.radius(), b.radius());
  const bool flip = on_b.separation > on_a.separation + tolerance;
  const PreparedHull& reference = flip ? b : a;
  const PreparedHull& incident = flip ? a : b;
  const Pose& incident_to_reference = flip ? a_to_b : b_to_a;
  const Pose& reference_pose = flip ? pose_b : pose_a;
  const std::uint32_t edge = flip ? on_b.edge : on_a.edge;

  // Everything below is in the reference hull's frame.
  const std::span<const Vec2> rv = reference.vertices();
  const std::uint32_t edge_end = edge + 1 == rv.size() ? 0 : edge + 1;
  const Vec2 v1 = rv[edge];
  const Vec2 v2 = rv[edge_end];
  const Vec2 normal = reference.normals()[edge];
  const Vec2 tangent(-normal.y(), normal.x());  // along v1 -> v2 for a CCW hull

  const std::uint32_t i1 =
      incident_edge(incident, incident_to_reference.rotation.apply_inverse(normal));
  const std::uint32_t i2 = i1 + 1 == incident.size() ? 0 : i1 + 1;
  const std::array<ClipVertex, 2> segment = {
      ClipVertex{incident_to_reference.apply(incident.vertices()[i1]),
                 feature_id(edge, i1, kVertexInFace)},
      ClipVertex{incident_to_reference.apply(incident.vertices()[i2]),
                 feature_id(edge, i2, kVertexInFace)}};

  std::array<ClipVertex, 2> once{};
  std::array<ClipVertex, 2> twice{};
  const int after_first =
      clip(segment, 2, once, -tangent, -tangent.dot(v1), feature_id(edge, i1, kClipped));
  const int kept =
      clip(once, after_first, twice, tangent, tangent.dot(v2), feature_id(edge_end, i1, kClipped));

  const Rotation& rotation = reference_pose.rotation;
  manifold.normal = flip ? Vec2(-rotation.apply(normal)) : rotation.apply(normal);
  // Adds incident point c (reference frame), placed midway between it and the reference face.
  const auto emit = [&](const Vec2& c, Real separation, std::uint32_t id) {
    ManifoldPoint& point = manifold.points[static_cast<std::size_t>(manifold.point_count++)];
    point.point = reference_pose.apply(c - 0.5 * separation * normal);
    point.separation = separation;
    point.id = id | (flip ? kFlipped : 0);
  };
  for (int k = 0; k < kept; ++k) {
    const ClipVertex& c = twice[static_cast<std::size_t>(k)];
    const Real separation = normal.dot(c.point - v1);
    if (separation > speculative_distance) continue;
    emit(c.point, separation, c.id);
  }
  if (manifold.point_count == 0) {
    // Nothing clipped within the margin: the incident edge lies wholly beside the reference
    // face (corner against corner, or a many-sided hull reaching past a short face). One
    // point instead of none.
    if (apart) {
      const DistanceResult nearest = gjk_distance(a, pose_a, b, pose_b);
      if (nearest.distance > speculative_distance) return manifold;
      ManifoldPoint& point = manifold.points[0];
      manifold.point_count = 1;
      manifold.normal = nearest.normal;
      point.point = 0.5 * (nearest.point_a + nearest.point_b);
      point.separation = nearest.distance;
      const auto [ia, ib] = nearest.simplex.lowest_pair();
      point.id = feature_id(ia, ib, kNearest);
    } else {
      // Overlapping: the incident hull's deepest vertex, unclipped.
      const std::uint32_t deepest = static_cast<std::uint32_t>(
          support_index(incident, incident_to_reference.rotation.apply_inverse(-normal)));
      const Vec2 c = incident_to_reference.apply(incident.vertices()[deepest]);
      emit(c, normal.dot(c - v1), feature_id(edge, deepest, kVertexInFace));
    }
  }
  return manifold;
}

}  // namespace mink
