#pragma once

// Shared by the narrowphase tests: random posed hulls and brute-force answers computed from
// world vertices alone, with none of the library's search structures (the library-independent
// scans are in brute_force_support.hpp).

#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "brute_force_support.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink_test {

using mink::Pose;
using mink::PreparedHull;
using mink::Real;
using mink::Vec2;

#ifdef MINK_SANITIZED_BUILD
inline constexpr int kScale = 10;  // randomized loops run this many times fewer iterations
#else
inline constexpr int kScale = 1;
#endif

// A hull with about `vertices` vertices (exactly that many for small counts): points on a
// circle, stretched and scaled, around a local origin near its centroid.
inline PreparedHull random_hull(std::mt19937_64& rng, std::size_t vertices) {
  std::vector<Vec2> points =
      mink::generate_points(mink::PointDistribution::on_circle, vertices, rng());
  std::uniform_real_distribution<Real> stretch(0.3, 1.0);
  std::uniform_real_distribution<Real> size(0.3, 2.0);
  const Real sx = size(rng);
  const Real sy = sx * stretch(rng);
  for (Vec2& p : points) p = Vec2(p.x() * sx, p.y() * sy);
  return PreparedHull(mink::build_hull(points, mink::HullAlgorithm::monotone_chain));
}

inline Pose random_pose(std::mt19937_64& rng, Real spread) {
  std::uniform_real_distribution<Real> position(-spread, spread);
  std::uniform_real_distribution<Real> angle(-std::numbers::pi, std::numbers::pi);
  Pose pose;
  pose.position = Vec2(position(rng), position(rng));
  pose.rotation = mink::Rotation::from_angle(angle(rng));
  return pose;
}

inline std::string format_point(const Vec2& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.17g, %.17g)", p.x(), p.y());
  return text;
}

inline std::vector<Vec2> world_vertices(const PreparedHull& hull, const Pose& pose) {
  std::vector<Vec2> world;
  for (const Vec2& v : hull.vertices()) world.push_back(pose.apply(v));
  return world;
}

// Two random hulls in random poses, with their world vertices for the brute-force oracles.
struct RandomPair {
  PreparedHull a;
  PreparedHull b;
  Pose pa;
  Pose pb;
  std::vector<Vec2> wa;
  std::vector<Vec2> wb;
};

inline RandomPair random_pair(std::mt19937_64& rng, std::size_t na, std::size_t nb, Real spread) {
  PreparedHull a = random_hull(rng, na);
  PreparedHull b = random_hull(rng, nb);
  const Pose pa = random_pose(rng, spread);
  const Pose pb = random_pose(rng, spread);
  auto wa = world_vertices(a, pa);
  auto wb = world_vertices(b, pb);
  return {std::move(a), std::move(b), pa, pb, std::move(wa), std::move(wb)};
}

// Distance between two disjoint convex polygons by the library's slow twin (a plain scan).
inline Real brute_distance(std::span<const Vec2> a, std::span<const Vec2> b) {
  return mink::hull_distance_brute(a, b).distance;
}

inline std::vector<Vec2> translated(std::span<const Vec2> p, const Vec2& by) {
  std::vector<Vec2> out;
  for (const Vec2& v : p) out.push_back(v + by);
  return out;
}

inline PreparedHull box(Real half_width, Real half_height) {
  return PreparedHull(mink::ConvexHull::from_ccw_vertices(
      {Vec2(-half_width, -half_height), Vec2(half_width, -half_height),
       Vec2(half_width, half_height), Vec2(-half_width, half_height)}));
}

inline Pose pose_at(Real x, Real y, Real angle = 0) {
  Pose pose;
  pose.position = Vec2(x, y);
  pose.rotation = mink::Rotation::from_angle(angle);
  return pose;
}

}  // namespace mink_test
