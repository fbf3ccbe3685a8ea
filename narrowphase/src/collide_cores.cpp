#include "collide_cores.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "clip.hpp"
#include "face_separation.hpp"
#include "gjk_distance_loop.hpp"

namespace mink::detail {

namespace {

Vec2 unit_right_normal(const Vec2& p, const Vec2& q) {
  const Vec2 e = q - p;
  return rescaled_direction(Vec2(e.y(), -e.x())).normalized();
}

// A point of `core` in A's frame.
Vec2 in_a(const Core& core, std::size_t i, bool on_b, const Pose& b_to_a) {
  return on_b ? b_to_a.apply(core.point(i)) : core.point(i);
}

// Face `index` of the segment p0 -> p1 (A's frame), whose face 0 has the unit normal `normal0`.
ReferenceFace segment_face(const Vec2& p0, const Vec2& p1, std::uint32_t index, bool on_b,
                           const Vec2& normal0) {
  ReferenceFace f;
  f.index = index;
  f.on_b = on_b;
  f.v1 = index == 0 ? p0 : p1;
  f.v2 = index == 0 ? p1 : p0;
  f.normal = index == 0 ? normal0 : Vec2(-normal0);
  return f;
}

// The faces of the two cores in A's frame, each segment's normal found once per pair rather
// than at every look at a face (a pair looks at each face up to three times). Face 1 of a
// segment is face 0 reversed, whose normal is the same bits negated.
class PairFaces {
 public:
  PairFaces(const Core& a, const Core& b, const Pose& b_to_a)
      : a_(a),
        b_(b),
        b_to_a_(b_to_a),
        normal_a_(segment_normal(a, false)),
        normal_b_(segment_normal(b, true)) {}

  ReferenceFace face(std::uint32_t index, bool on_b) const {
    const Core& core = on_b ? b_ : a_;
    if (core.hull != nullptr) return core_face(core, index, on_b, b_to_a_);
    return segment_face(in_a(core, 0, on_b, b_to_a_), in_a(core, 1, on_b, b_to_a_), index, on_b,
                        on_b ? normal_b_ : normal_a_);
  }

  // Only the normal of face `index`.
  Vec2 normal(std::uint32_t index, bool on_b) const {
    const Core& core = on_b ? b_ : a_;
    if (core.hull != nullptr) {
      const Vec2& local = core.hull->normals()[index];
      return on_b ? b_to_a_.rotation.apply(local) : local;
    }
    const Vec2& n = on_b ? normal_b_ : normal_a_;
    return index == 0 ? n : Vec2(-n);
  }

 private:
  Vec2 segment_normal(const Core& core, bool on_b) const {
    if (core.hull != nullptr || core.size() != 2) return Vec2(0, 0);
    return unit_right_normal(in_a(core, 0, on_b, b_to_a_), in_a(core, 1, on_b, b_to_a_));
  }

  const Core& a_;
  const Core& b_;
  const Pose& b_to_a_;
  Vec2 normal_a_, normal_b_;
};

// The largest separation of the other core's points beyond a face, over every face of both
// (-infinity when neither core has faces): the separating-axis test, exact in 2D for overlap
// depth because A - B has exactly the faces of A and B.
struct BestFace {
  Real separation = -std::numeric_limits<Real>::infinity();
  std::uint32_t index = 0;
  bool on_b = false;
};

BestFace best_face(const Core& a, const Core& b, const Pose& b_to_a, const PairFaces& faces_of) {
  BestFace best;
  if (a.hull != nullptr && b.hull != nullptr) {
    const FaceSeparation on_a = max_face_separation(*a.hull, *b.hull, b_to_a);
    const FaceSeparation on_b = max_face_separation(*b.hull, *a.hull, inverse(b_to_a));
    if (on_b.separation > on_a.separation) return {on_b.separation, on_b.edge, true};
    return {on_a.separation, on_a.edge, false};
  }
  for (int side = 0; side < 2; ++side) {
    const bool on_b = side == 1;
    const Core& owner = on_b ? b : a;
    const Core& other = on_b ? a : b;
    const std::size_t faces = face_count(owner);
    for (std::uint32_t i = 0; i < faces; ++i) {
      const ReferenceFace f = faces_of.face(i, on_b);
      Real deepest = std::numeric_limits<Real>::infinity();
      for (std::size_t j = 0; j < other.size(); ++j) {
        deepest = std::min(deepest, f.normal.dot(in_a(other, j, !on_b, b_to_a) - f.v1));
      }
      if (deepest > best.separation) best = {deepest, i, on_b};
    }
  }
  return best;
}

// The face (of either core) whose outward normal is closest to `normal` (A towards B).
ReferenceFace most_aligned_face(const Core& a, const Core& b, const PairFaces& faces_of,
                                const Vec2& normal, Real& alignment) {
  ReferenceFace best;
  alignment = -2;
  for (int side = 0; side < 2; ++side) {
    const bool on_b = side == 1;
    const Core& owner = on_b ? b : a;
    const Vec2 towards = on_b ? Vec2(-normal) : normal;
    const std::size_t faces = face_count(owner);
    for (std::uint32_t i = 0; i < faces; ++i) {
      const Real dot = faces_of.normal(i, on_b).dot(towards);
      if (dot > alignment) {
        alignment = dot;
        best.index = i;
        best.on_b = on_b;
      }
    }
  }
  if (alignment > -2) best = faces_of.face(best.index, best.on_b);
  return best;
}

// The incident core's feature facing the reference normal (A's frame): its single point, its
// segment, or its edge most opposed to the normal, with vertex indices.
int incident_feature(const Core& core, bool on_b, const Pose& b_to_a, const Vec2& normal,
                     std::array<ClipVertex, 2>& out, std::array<std::uint32_t, 2>& index) {
  if (core.size() <= 2) {
    for (std::size_t i = 0; i < core.size(); ++i) {
      out[i].point = in_a(core, i, on_b, b_to_a);
      index[i] = static_cast<std::uint32_t>(i);
    }
    return static_cast<int>(core.size());
  }
  const Vec2 local = on_b ? b_to_a.rotation.apply_inverse(normal) : normal;
  const std::span<const Vec2> normals = core.hull->normals();
  const std::size_t n = normals.size();
  std::size_t edge = 0;
  if (n <= kLinearSupportLimit) {
    Real best = normals[0].dot(local);
    for (std::size_t i = 1; i < n; ++i) {
      const Real dot = normals[i].dot(local);
      if (dot < best) {
        best = dot;
        edge = i;
      }
    }
  } else {
    // The deepest vertex along -normal starts one of the two candidate edges.
    const std::size_t k = support_index(*core.hull, -local);
    const std::size_t before = k == 0 ? n - 1 : k - 1;
    edge = normals[before].dot(local) < normals[k].dot(local) ? before : k;
  }
  index = {static_cast<std::uint32_t>(edge),
           static_cast<std::uint32_t>(edge + 1 == n ? 0 : edge + 1)};
  out[0].point = in_a(core, index[0], on_b, b_to_a);
  out[1].point = in_a(core, index[1], on_b, b_to_a);
  return 2;
}

// Emits a point of the incident core at `c` (A's frame), `core_separation` beyond the
// reference face: placed midway between the two surfaces.
void emit(Manifold& m, const Pose& pose_a, const ReferenceFace& face, const Vec2& c,
          Real core_separation, Real r_reference, Real r_incident, std::uint32_t id) {
  ManifoldPoint& p = m.points[static_cast<std::size_t>(m.point_count++)];
  p.point = pose_a.apply(c + (0.5 * (r_reference - r_incident - core_separation)) * face.normal);
  p.separation = core_separation - r_reference - r_incident;
  p.id = id | (face.on_b ? kReferenceOnB : 0);
}

// Clips the incident feature to the face's sides and emits the points within the margin.
Manifold clip_to_face(const Core& a, const Pose& pose_a, const Core& b, const Pose& b_to_a,
                      const ReferenceFace& face, Real speculative_distance) {
  Manifold m;
  const Core& reference = face.on_b ? b : a;
  const Core& incident = face.on_b ? a : b;
  std::array<ClipVertex, 2> feature{};
  std::array<std::uint32_t, 2> index{};
  const int count = incident_feature(incident, !face.on_b, b_to_a, face.normal, feature, index);
  const std::uint32_t edge_end = face.index + 1 == face_count(reference) ? 0 : face.index + 1;
  for (int k = 0; k < count; ++k) {
    feature[static_cast<std::size_t>(k)].id =
        feature_id(face.index, index[static_cast<std::size_t>(k)], kVertexInFace);
  }
  const Vec2 tangent(-face.normal.y(), face.normal.x());  // along v1 -> v2
  std::array<ClipVertex, 2> once{};
  std::array<ClipVertex, 2> twice{};
  const int after_first = clip(feature, count, once, -tangent, -tangent.dot(face.v1),
                               feature_id(face.index, index[0], kClipped));
  const int kept = clip(once, after_first, twice, tangent, tangent.dot(face.v2),
                        feature_id(edge_end, index[0], kClipped));
  m.normal = pose_a.rotation.apply(face.on_b ? Vec2(-face.normal) : face.normal);
  for (int k = 0; k < kept; ++k) {
    const ClipVertex& c = twice[static_cast<std::size_t>(k)];
    const Real core_separation = face.normal.dot(c.point - face.v1);
    if (core_separation - reference.radius - incident.radius > speculative_distance) continue;
    emit(m, pose_a, face, c.point, core_separation, reference.radius, incident.radius, c.id);
  }
  return m;
}

Real min_separation(const Manifold& m) {
  Real lowest = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < m.point_count; ++i)
    lowest = std::min(lowest, m.points[static_cast<std::size_t>(i)].separation);
  return lowest;
}

}  // namespace

ReferenceFace core_face(const Core& core, std::uint32_t index, bool on_b, const Pose& b_to_a) {
  ReferenceFace f;
  f.index = index;
  f.on_b = on_b;
  if (core.hull != nullptr) {
    const std::size_t n = core.size();
    f.v1 = in_a(core, index, on_b, b_to_a);
    f.v2 = in_a(core, index + 1 == n ? 0 : index + 1, on_b, b_to_a);
    const Vec2& local = core.hull->normals()[index];
    f.normal = on_b ? b_to_a.rotation.apply(local) : local;
    return f;
  }
  const Vec2 p0 = in_a(core, 0, on_b, b_to_a);
  const Vec2 p1 = in_a(core, 1, on_b, b_to_a);
  return segment_face(p0, p1, index, on_b, unit_right_normal(p0, p1));
}

Manifold collide_on_face(const Core& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                         const ReferenceFace& face, Real speculative_distance) {
  return clip_to_face(a, pose_a, b, relative_pose(pose_a, pose_b), face, speculative_distance);
}

Manifold collide_cores(const Core& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                       Real speculative_distance) {
  const Pose b_to_a = relative_pose(pose_a, pose_b);
  const Real radii = a.radius + b.radius;
  const PairFaces faces_of(a, b, b_to_a);
  // A face separation bounds the distance from below: a cheap early out for far pairs.
  const BestFace sat = best_face(a, b, b_to_a, faces_of);
  if (sat.separation - radii > speculative_distance) return {};
  const CoreFrame frame(a, b, b_to_a);
  const LocalDistance gjk = distance_loop(frame, nullptr);

  if (!gjk.overlap) {
    const Real separation = gjk.distance - radii;
    if (separation > speculative_distance) return {};
    const Vec2 normal = gjk.gap / gjk.distance;
    // Two points when the nearest features are a face and what lies on it: then the GJK normal
    // is that face's normal (up to rounding).
    Real alignment = -2;
    const ReferenceFace face = most_aligned_face(a, b, faces_of, normal, alignment);
    if (alignment >= 1 - 1e-10) {
      const Manifold m = clip_to_face(a, pose_a, b, b_to_a, face, speculative_distance);
      const Real tolerance = 1e-10 * (gjk.distance + (face.v2 - face.v1).norm() + radii);
      if (m.point_count > 0 && min_separation(m) <= separation + tolerance) return m;
    }
    // Otherwise the nearest points alone (corner against corner, point cores).
    Manifold m;
    m.normal = pose_a.rotation.apply(normal);
    m.point_count = 1;
    ManifoldPoint& p = m.points[0];
    p.point =
        pose_a.apply(0.5 * ((gjk.point_a + a.radius * normal) + (gjk.point_b - b.radius * normal)));
    p.separation = separation;
    const auto [ia, ib] = gjk.simplex.lowest_pair();
    p.id = feature_id(ia, ib, kNearest);
    return m;
  }

  // The cores touch or overlap.
  if (face_count(a) == 0 && face_count(b) == 0) {
    // Two coincident points: every direction is as good; +y.
    Manifold m;
    const Vec2 normal(0, 1);
    const Vec2 c = b_to_a.apply(b.point(0));
    m.normal = pose_a.rotation.apply(normal);
    m.point_count = 1;
    m.points[0].point = pose_a.apply(c + (0.5 * (a.radius - b.radius)) * normal);
    m.points[0].separation = -radii;
    m.points[0].id = feature_id(0, 0, kNearest);
    return m;
  }
  const Real separation = sat.separation - radii;
  if (separation > speculative_distance) return {};
  const ReferenceFace face = faces_of.face(sat.index, sat.on_b);
  Manifold m = clip_to_face(a, pose_a, b, b_to_a, face, speculative_distance);
  const Real tolerance = 1e-10 * (std::abs(sat.separation) + (face.v2 - face.v1).norm() + radii);
  if (m.point_count > 0 && min_separation(m) <= separation + tolerance) return m;
  // The deepest incident point lies beside the face (a long edge reaching past a short face):
  // it replaces the shallower clipped point, so the manifold carries the true depth.
  const Core& incident = sat.on_b ? a : b;
  const Core& reference = sat.on_b ? b : a;
  const Vec2 local = sat.on_b ? Vec2(-face.normal) : b_to_a.rotation.apply_inverse(-face.normal);
  const std::uint32_t deepest = incident.support(local);
  const Vec2 c = in_a(incident, deepest, !sat.on_b, b_to_a);
  if (m.point_count == 2) {
    const std::size_t shallow = m.points[0].separation > m.points[1].separation ? 0 : 1;
    if (shallow == 0) m.points[0] = m.points[1];
    m.point_count = 1;
  }
  emit(m, pose_a, face, c, face.normal.dot(c - face.v1), reference.radius, incident.radius,
       feature_id(face.index, deepest, kVertexInFace));
  return m;
}

}  // namespace mink::detail
