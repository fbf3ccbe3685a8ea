#pragma once

// Brute-force answers for the shape kinds, from world coordinates alone: every shape is a core
// (its points) plus a radius; overlap of cores by exact orientation, distances by scanning every
// point against every edge, depth by the separating-axis test over every edge normal.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "mink/geometry/orientation.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "narrowphase_test_support.hpp"

namespace mink_test {

using mink::ShapeGeometry;
using mink::ShapeKind;

// A posed shape as the oracles see it: world core points (1, 2, or a CCW hull) and a radius.
struct WorldCore {
  std::vector<Vec2> points;
  Real radius = 0;
};

inline WorldCore world_core(const ShapeGeometry& g, const Pose& pose) {
  WorldCore c;
  switch (mink::kind_of(g)) {
    case ShapeKind::circle:
      c.points = {pose.apply(std::get<mink::Circle>(g).center)};
      c.radius = std::get<mink::Circle>(g).radius;
      break;
    case ShapeKind::capsule:
      c.points = {pose.apply(std::get<mink::Capsule>(g).center1),
                  pose.apply(std::get<mink::Capsule>(g).center2)};
      c.radius = std::get<mink::Capsule>(g).radius;
      break;
    case ShapeKind::segment:
      c.points = {pose.apply(std::get<mink::Segment>(g).point1),
                  pose.apply(std::get<mink::Segment>(g).point2)};
      break;
    case ShapeKind::chain_segment:
      c.points = {pose.apply(std::get<mink::ChainSegment>(g).segment.point1),
                  pose.apply(std::get<mink::ChainSegment>(g).segment.point2)};
      break;
    case ShapeKind::polygon:
      c.points = world_vertices(std::get<mink::RoundedPolygon>(g).hull, pose);
      c.radius = std::get<mink::RoundedPolygon>(g).radius;
      break;
  }
  return c;
}

// The core's edges as point index pairs: none for a point, one for a segment, n for a hull.
inline std::vector<std::pair<std::size_t, std::size_t>> edges(const std::vector<Vec2>& p) {
  std::vector<std::pair<std::size_t, std::size_t>> e;
  if (p.size() == 2) e.emplace_back(0, 1);
  if (p.size() >= 3)
    for (std::size_t i = 0; i < p.size(); ++i) e.emplace_back(i, (i + 1) % p.size());
  return e;
}

// q on the closed segment a-b, exactly.
inline bool on_segment_exact(const Vec2& a, const Vec2& b, const Vec2& q) {
  return mink::orient2d(a, b, q) == 0 && std::min(a.x(), b.x()) <= q.x() &&
         q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
         q.y() <= std::max(a.y(), b.y());
}

inline bool segments_intersect_exact(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = mink::orient2d(a, b, c), o2 = mink::orient2d(a, b, d);
  const int o3 = mink::orient2d(c, d, a), o4 = mink::orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment_exact(a, b, c) || on_segment_exact(a, b, d) || on_segment_exact(c, d, a) ||
         on_segment_exact(c, d, b);
}

inline bool point_in_core_exact(const std::vector<Vec2>& p, const Vec2& q) {
  if (p.size() == 1) return p[0] == q;
  if (p.size() == 2) return on_segment_exact(p[0], p[1], q);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (mink::orient2d(p[i], p[(i + 1) % p.size()], q) < 0) return false;
  return true;
}

// Two convex sets meet iff a point of one lies in the other or two edges cross.
inline bool cores_overlap_exact(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  for (const Vec2& v : p)
    if (point_in_core_exact(q, v)) return true;
  for (const Vec2& v : q)
    if (point_in_core_exact(p, v)) return true;
  for (const auto& [i, j] : edges(p))
    for (const auto& [k, l] : edges(q))
      if (segments_intersect_exact(p[i], p[j], q[k], q[l])) return true;
  return false;
}

// Distance between disjoint cores: every point against every point and every edge.
inline Real core_distance(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const Vec2& v : p)
    for (const Vec2& w : q) best = std::min(best, (v - w).norm());
  for (int pass = 0; pass < 2; ++pass) {
    const auto& s = pass == 0 ? p : q;
    const auto& t = pass == 0 ? q : p;
    for (const Vec2& v : s)
      for (const auto& [k, l] : edges(t))
        best = std::min(best, point_segment_distance(v, t[k], t[l]));
  }
  return best;
}

// Depth of overlapping cores: the cheapest push of q out of p over every edge normal of both
// (both sides of a segment), scanning every point.
inline Real core_depth(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  Real best = std::numeric_limits<Real>::infinity();
  std::vector<Vec2> axes;
  for (const auto* s : {&p, &q}) {
    for (const auto& [i, j] : edges(*s)) {
      const Vec2 e = (*s)[j] - (*s)[i];
      const Vec2 u = Vec2(e.y(), -e.x()).normalized();
      axes.push_back(u);
      axes.push_back(-u);
    }
  }
  if (axes.empty()) return 0;  // two coincident points
  for (const Vec2& u : axes) {
    Real hi = -std::numeric_limits<Real>::infinity();
    Real lo = std::numeric_limits<Real>::infinity();
    for (const Vec2& v : p) hi = std::max(hi, v.dot(u));
    for (const Vec2& w : q) lo = std::min(lo, w.dot(u));
    best = std::min(best, hi - lo);
  }
  return best;
}

// Signed surface distance of two posed shapes: the distance when apart, minus the depth when
// overlapping, radii included; and whether the cores overlap (exact).
struct SignedGap {
  Real gap = 0;
  bool cores_overlap = false;
};

inline SignedGap signed_gap(const WorldCore& a, const WorldCore& b) {
  SignedGap s;
  s.cores_overlap = cores_overlap_exact(a.points, b.points);
  const Real radii = a.radius + b.radius;
  s.gap = s.cores_overlap ? -core_depth(a.points, b.points) - radii
                          : core_distance(a.points, b.points) - radii;
  return s;
}

// Signed distance of a world point to a shape (negative inside), brute force.
inline Real point_signed_distance(const WorldCore& c, const Vec2& q) {
  Real d = std::numeric_limits<Real>::infinity();
  if (c.points.size() == 1) d = (q - c.points[0]).norm();
  for (const auto& [i, j] : edges(c.points))
    d = std::min(d, point_segment_distance(q, c.points[i], c.points[j]));
  if (c.points.size() >= 3 && point_in_core_exact(c.points, q)) d = -d;
  return d - c.radius;
}

// ---- random shapes --------------------------------------------------------------------------

inline Vec2 random_point(std::mt19937_64& rng, Real extent) {
  std::uniform_real_distribution<Real> u(-extent, extent);
  return Vec2(u(rng), u(rng));
}

// A shape of `kind` about the local origin, at most about 2 across.
inline ShapeGeometry random_shape(std::mt19937_64& rng, ShapeKind kind) {
  std::uniform_real_distribution<Real> radius(0.05, 0.6);
  std::uniform_int_distribution<int> coin(0, 1);
  switch (kind) {
    case ShapeKind::circle:
      return mink::Circle{random_point(rng, 0.3), radius(rng)};
    case ShapeKind::capsule: {
      const Vec2 a = random_point(rng, 0.8);
      Vec2 b = random_point(rng, 0.8);
      while ((b - a).norm() < 1e-3) b = random_point(rng, 0.8);
      return mink::Capsule{a, b, radius(rng)};
    }
    case ShapeKind::segment:
    case ShapeKind::chain_segment: {
      const Vec2 a = random_point(rng, 1.2);
      Vec2 b = random_point(rng, 1.2);
      while ((b - a).norm() < 1e-3) b = random_point(rng, 1.2);
      if (kind == ShapeKind::segment) return mink::Segment{a, b};
      return mink::ChainSegment{a + random_point(rng, 1), mink::Segment{a, b},
                                b + random_point(rng, 1)};
    }
    case ShapeKind::polygon: {
      std::uniform_int_distribution<int> small(3, 8);
      std::uniform_int_distribution<int> large(9, 40);
      const std::size_t n = static_cast<std::size_t>(rng() % 8 == 0 ? large(rng) : small(rng));
      const Real r = coin(rng) == 0 ? 0 : radius(rng) * 0.5;
      return mink::RoundedPolygon{random_hull(rng, n), r};
    }
  }
  return mink::Circle{};
}

}  // namespace mink_test
