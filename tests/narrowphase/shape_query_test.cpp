// Point queries, boxes and ray casts of every shape kind against brute-force oracles.

#include <gtest/gtest.h>

#include "shape_oracle.hpp"

namespace {

using namespace mink_test;

constexpr int kSamples = 100000 / kScale;
constexpr ShapeKind kKinds[] = {ShapeKind::circle, ShapeKind::capsule, ShapeKind::segment,
                                ShapeKind::chain_segment, ShapeKind::polygon};

bool solid(ShapeKind k) {
  return k != ShapeKind::segment && k != ShapeKind::chain_segment;
}

TEST(ShapeQueries, ContainsAndClosestPointMatchTheOracle) {
  std::mt19937_64 rng(11);
  for (ShapeKind kind : kKinds) {
    int inside = 0;
    for (int k = 0; k < kSamples; ++k) {
      const ShapeGeometry shape = random_shape(rng, kind);
      const Pose pose = random_pose(rng, 1);
      const WorldCore core = world_core(shape, pose);
      const Vec2 p = random_point(rng, 1.5);
      const Real d = point_signed_distance(core, p);
      if (std::abs(d) < 1e-12) continue;
      const bool contained = mink::contains_point(shape, pose, p);
      ASSERT_EQ(contained, solid(kind) && d < 0) << static_cast<int>(kind) << " sample " << k;
      const Vec2 q = mink::closest_point(shape, pose, p);
      if (contained) {
        ++inside;
        EXPECT_EQ(q, p);
        continue;
      }
      // Outside: as far as the oracle says, and on the surface.
      ASSERT_NEAR((q - p).norm(), d, 1e-9 * (1 + d)) << static_cast<int>(kind) << " " << k;
      ASSERT_NEAR(point_signed_distance(core, q), 0, 1e-9) << static_cast<int>(kind) << " " << k;
    }
    if (solid(kind)) {
      EXPECT_GT(inside, kSamples / 50);
    }
  }
}

TEST(ShapeQueries, AabbIsTight) {
  std::mt19937_64 rng(12);
  for (ShapeKind kind : kKinds) {
    for (int k = 0; k < kSamples / 10; ++k) {
      const ShapeGeometry shape = random_shape(rng, kind);
      const Pose pose = random_pose(rng, 1);
      const mink::Aabb box = mink::compute_aabb(shape, pose);
      // Each side touches the shape: the support along the axis equals the side.
      const WorldCore core = world_core(shape, pose);
      const Vec2 axes[] = {Vec2(1, 0), Vec2(0, 1)};
      for (const Vec2& u : axes) {
        Real hi = -1e300, lo = 1e300;
        for (const Vec2& p : core.points) {
          hi = std::max(hi, p.dot(u) + core.radius);
          lo = std::min(lo, p.dot(u) - core.radius);
        }
        EXPECT_NEAR(box.upper.dot(u), hi, 1e-12);
        EXPECT_NEAR(box.lower.dot(u), lo, 1e-12);
      }
    }
  }
}

// First t in [0, 1] with the oracle's signed distance <= 0 along the ray: a scan of 1024 steps
// then bisection. Negative when the ray never reaches the shape or only grazes it.
Real oracle_fraction(const WorldCore& core, const Vec2& o, const Vec2& d) {
  constexpr int kSteps = 1024;
  Real previous = 0;
  Real lowest = 1e300;
  for (int i = 1; i <= kSteps; ++i) {
    const Real t = Real(i) / kSteps;
    const Real s = point_signed_distance(core, o + t * d);
    lowest = std::min(lowest, s);
    if (s <= 0) {
      Real lo = previous, hi = t;
      for (int k = 0; k < 80; ++k) {
        const Real mid = 0.5 * (lo + hi);
        (point_signed_distance(core, o + mid * d) <= 0 ? hi : lo) = mid;
      }
      return hi;
    }
    previous = t;
  }
  return lowest < 1e-2 ? -2 : -1;  // -2: passes close, not judged
}

TEST(ShapeQueries, RayCastOfSolidShapesMatchesTheOracle) {
  std::mt19937_64 rng(13);
  for (ShapeKind kind : {ShapeKind::circle, ShapeKind::capsule, ShapeKind::polygon}) {
    int hits = 0, judged = 0;
    for (int k = 0; k < kSamples / 20; ++k) {
      const ShapeGeometry shape = random_shape(rng, kind);
      const Pose pose = random_pose(rng, 0.5);
      const WorldCore core = world_core(shape, pose);
      const Vec2 o = random_point(rng, 3);
      const Vec2 d = random_point(rng, 3) - o;
      const auto hit = mink::ray_cast(shape, pose, o, d);
      if (point_signed_distance(core, o) <= 0) {
        EXPECT_FALSE(hit.has_value());  // starts inside
        continue;
      }
      const Real t = oracle_fraction(core, o, d);
      if (t == -2) continue;
      ++judged;
      ASSERT_EQ(hit.has_value(), t >= 0) << static_cast<int>(kind) << " ray " << k;
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(hit->fraction, t, 1e-9) << static_cast<int>(kind) << " ray " << k;
      EXPECT_NEAR(point_signed_distance(core, hit->point), 0, 1e-9);
      EXPECT_NEAR(hit->normal.norm(), 1, 1e-12);
      EXPECT_LE(hit->normal.dot(d), 0);
      // The normal is the oracle's gradient: stepping along it leaves the surface at once.
      EXPECT_NEAR(point_signed_distance(core, hit->point + 1e-6 * hit->normal), 1e-6, 1e-9);
    }
    EXPECT_GT(hits, judged / 10);
  }
}

TEST(ShapeQueries, RayCastOfSegmentsMatchesTheExactCrossing) {
  std::mt19937_64 rng(14);
  int hits = 0, chain_misses_from_behind = 0;
  for (int k = 0; k < kSamples / 10; ++k) {
    const bool chain = (k & 1) != 0;
    const ShapeGeometry shape =
        random_shape(rng, chain ? ShapeKind::chain_segment : ShapeKind::segment);
    const Pose pose = random_pose(rng, 0.5);
    const WorldCore core = world_core(shape, pose);
    const Vec2 o = random_point(rng, 3);
    const Vec2 d = random_point(rng, 3) - o;
    const Vec2& p1 = core.points[0];
    const Vec2& p2 = core.points[1];
    const Vec2 e = p2 - p1;
    const Vec2 n = Vec2(e.y(), -e.x()).normalized();
    bool expected = segments_intersect_exact(o, o + d, p1, p2) && mink::orient2d(p1, p2, o) != 0 &&
                    mink::orient2d(p1, p2, o + d) != 0;
    if (chain && expected && n.dot(o - p1) < 0) {
      expected = false;  // from behind
      ++chain_misses_from_behind;
    }
    const auto hit = mink::ray_cast(shape, pose, o, d);
    ASSERT_EQ(hit.has_value(), expected) << k;
    if (!hit) continue;
    ++hits;
    EXPECT_NEAR(point_segment_distance(hit->point, p1, p2), 0, 1e-12);
    EXPECT_LT(hit->normal.dot(d), 0);
    if (chain) {
      EXPECT_NEAR((hit->normal - n).norm(), 0, 1e-12);
    }
  }
  EXPECT_GT(hits, kSamples / 100);
  EXPECT_GT(chain_misses_from_behind, kSamples / 400);
}

}  // namespace
