#include "mink/narrowphase/gjk_overlap.hpp"

#include "face_separation.hpp"
#include "mink/geometry/orientation.hpp"
#include "pair_frame.hpp"

namespace mink {

namespace {

// The perpendicular of segment p -> q on the side of the origin, given that side (+1 left).
Vec2 perpendicular_towards(const Vec2& p, const Vec2& q, int origin_side) {
  const Vec2 e = q - p;
  return origin_side > 0 ? Vec2(-e.y(), e.x()) : Vec2(e.y(), -e.x());
}

enum class Outcome { overlap, apart, cap };

// The paper's loop on A - B in A's frame. On `apart`, `separating` is a direction along which
// A - B lies wholly below zero.
Outcome run_gjk(const detail::PairFrame& frame, detail::LocalSimplex& s, int& iterations,
                Vec2& separating) {
  // Eq. 2: from centroid to centroid. Equal centroids: any direction serves.
  Vec2 d = frame.relative().apply(frame.b().centroid()) - frame.a().centroid();
  if (d.x() == 0 && d.y() == 0) d = Vec2(1, 0);
  const int cap = static_cast<int>(2 * (frame.a().size() + frame.b().size())) + 16;
  while (iterations < cap) {
    d = detail::rescaled_direction(d);
    const detail::LocalVertex v = frame.support(d);
    ++iterations;
    // A - B lies in {x : x.d <= v.d}: if that excludes the origin, the hulls are apart.
    if (v.point.dot(d) < 0) {
      separating = d;
      return Outcome::apart;
    }
    s.vertices[static_cast<std::size_t>(s.count++)] = v;
    if (s.count == 1) {
      if (v.point.x() == 0 && v.point.y() == 0) return Outcome::overlap;  // touching at a vertex
      d = -v.point;
      continue;
    }
    if (s.count == 2) {
      const Vec2& newest = s.vertices[1].point;
      const Vec2& older = s.vertices[0].point;
      const int side = detail::orient_about_origin(newest, older);
      // Collinear: the origin lies between the two points (older.d < 0 <= newest.d), so on
      // the segment: touching or overlapping.
      if (side == 0) return Outcome::overlap;
      d = perpendicular_towards(newest, older, side);
      continue;
    }
    // Triangle [c, b, a], a newest. The origin is on a's side of bc by construction, so only
    // the edges through a can have it outside.
    const Vec2& pa = s.vertices[2].point;
    const Vec2& pb = s.vertices[1].point;
    const Vec2& pc = s.vertices[0].point;
    const int winding = orient2d(pa, pb, pc);
    if (winding == 0) {
      // Degenerate (only through rounding): keep the newest edge and go on.
      s.vertices[0] = s.vertices[1];
      s.vertices[1] = s.vertices[2];
      s.count = 2;
      const int side = detail::orient_about_origin(pa, pb);
      if (side == 0) return Outcome::overlap;
      d = perpendicular_towards(s.vertices[1].point, s.vertices[0].point, side);
      continue;
    }
    const int side_ab = detail::orient_about_origin(pa, pb);
    if (side_ab == -winding) {  // outside edge ab: drop c
      // The direction first: pa and pb refer into the simplex the shift below overwrites.
      d = perpendicular_towards(pa, pb, side_ab);
      s.vertices[0] = s.vertices[1];
      s.vertices[1] = s.vertices[2];
      s.count = 2;
      continue;
    }
    const int side_ca = detail::orient_about_origin(pc, pa);
    if (side_ca == -winding) {  // outside edge ca: drop b
      d = perpendicular_towards(pc, pa, side_ca);
      s.vertices[1] = s.vertices[2];
      s.count = 2;
      continue;
    }
    const int side_bc = detail::orient_about_origin(pb, pc);
    if (side_bc == -winding) {  // only through rounding: drop a and search again past bc
      s.count = 2;
      d = perpendicular_towards(pb, pc, side_bc);
      continue;
    }
    return Outcome::overlap;  // inside or on the boundary of the triangle
  }
  return Outcome::cap;
}

}  // namespace

OverlapResult gjk_overlap(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                          const Pose& pose_b) {
  const detail::PairFrame frame(a, pose_a, b, pose_b);
  OverlapResult result;
  Vec2 separating(0, 0);
  detail::LocalSimplex local;
  const Outcome outcome = run_gjk(frame, local, result.iterations, separating);
  result.simplex = detail::PairFrame::indices(local);
  if (outcome == Outcome::overlap) {
    result.overlap = true;
  } else if (outcome == Outcome::apart) {
    result.separating_direction = pose_a.rotation.apply(separating);
  } else {
    // Past the cap (not reached in any test): the face-normal test decides.
    result.reached_iteration_cap = true;
    const Pose a_to_b = detail::inverse(frame.relative());
    result.overlap = !(std::max(detail::max_face_separation(a, b, frame.relative()).separation,
                                detail::max_face_separation(b, a, a_to_b).separation) > 0);
  }
  return result;
}

bool hulls_overlap_exact(std::span<const Vec2> a, std::span<const Vec2> b) {
  // Strictly convex CCW hulls: an edge separates iff every vertex of the other hull is
  // strictly right of it.
  auto separates = [](std::span<const Vec2> p, std::span<const Vec2> q) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2& from = p[i];
      const Vec2& to = p[(i + 1) % p.size()];
      bool all_right = true;
      for (const Vec2& w : q) {
        if (orient2d(from, to, w) >= 0) {
          all_right = false;
          break;
        }
      }
      if (all_right) return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

}  // namespace mink
