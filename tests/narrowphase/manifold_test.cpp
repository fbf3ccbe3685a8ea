#include "mink/narrowphase/manifold.hpp"

#include <gtest/gtest.h>

#include "mink/narrowphase/gjk_overlap.hpp"
#include "narrowphase_test_support.hpp"

namespace {

using namespace mink_test;
using mink::collide_hulls;
using mink::Manifold;

constexpr Real kTol = 1e-12;

void expect_point(const Manifold& m, const Vec2& point, Real separation) {
  for (int i = 0; i < m.point_count; ++i) {
    const auto& p = m.points[static_cast<std::size_t>(i)];
    if ((p.point - point).norm() < 1e-9) {
      EXPECT_NEAR(p.separation, separation, 1e-12);
      return;
    }
  }
  ADD_FAILURE() << "no contact point at " << format_point(point);
}

TEST(Manifold, OverlappingBoxesFaceToFace) {
  const PreparedHull a = box(0.5, 0.5);
  const Manifold m = collide_hulls(a, pose_at(0, 0), a, pose_at(0.2, 0.9), 0.05);
  ASSERT_EQ(m.point_count, 2);
  EXPECT_NEAR((m.normal - Vec2(0, 1)).norm(), 0, kTol);
  // A's top face at y = 0.5, B's bottom at y = 0.4: midway 0.45; clipped to x in [-0.3, 0.5].
  expect_point(m, Vec2(0.5, 0.45), -0.1);
  expect_point(m, Vec2(-0.3, 0.45), -0.1);
  EXPECT_NE(m.points[0].id, m.points[1].id);
}

TEST(Manifold, NormalPointsFromAToBWhenBIsTheReference) {
  const PreparedHull small = box(0.25, 0.25);
  const PreparedHull large = box(2, 0.5);
  // The small box sits on the large one; swapping the roles flips the normal.
  const Manifold m = collide_hulls(small, pose_at(0, 0.7), large, pose_at(0, 0), 0.05);
  ASSERT_EQ(m.point_count, 2);
  EXPECT_NEAR((m.normal - Vec2(0, -1)).norm(), 0, kTol);
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].separation, -0.05, kTol);
}

TEST(Manifold, TouchingBoxesGiveZeroSeparation) {
  const PreparedHull a = box(0.5, 0.5);
  const Manifold m = collide_hulls(a, pose_at(0, 0), a, pose_at(0, 1), 0);
  ASSERT_EQ(m.point_count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(m.points[static_cast<std::size_t>(i)].separation, 0);
  // Corner to corner: one point, not two coincident ones.
  const Manifold corner = collide_hulls(a, pose_at(0, 0), a, pose_at(1, 1), 0);
  ASSERT_EQ(corner.point_count, 1);
  EXPECT_NEAR((corner.points[0].point - Vec2(0.5, 0.5)).norm(), 0, kTol);
  EXPECT_EQ(corner.points[0].separation, 0);
}

TEST(Manifold, SpeculativePointsWithinTheMarginOnly) {
  const PreparedHull a = box(0.5, 0.5);
  const Manifold near = collide_hulls(a, pose_at(0, 0), a, pose_at(0, 1.05), 0.1);
  ASSERT_EQ(near.point_count, 2);
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(near.points[static_cast<std::size_t>(i)].separation, 0.05, kTol);
  EXPECT_EQ(collide_hulls(a, pose_at(0, 0), a, pose_at(0, 1.2), 0.1).point_count, 0);
  // Corner to corner the face test sees 0.08 but the hulls are 0.08 * sqrt(2) apart.
  EXPECT_EQ(collide_hulls(a, pose_at(0, 0), a, pose_at(1.08, 1.08), 0.1).point_count, 0);
  EXPECT_EQ(collide_hulls(a, pose_at(0, 0), a, pose_at(1.06, 1.06), 0.1).point_count, 1);
}

TEST(Manifold, RotatedBoxOnItsCorner) {
  const PreparedHull a = box(0.5, 0.5);
  const Real h = std::sqrt(0.5);  // half diagonal
  const Manifold m =
      collide_hulls(a, pose_at(0, 0), a, pose_at(0.1, 0.5 + h - 0.01, std::numbers::pi / 4), 0.05);
  ASSERT_EQ(m.point_count, 1);
  EXPECT_NEAR((m.normal - Vec2(0, 1)).norm(), 0, 1e-12);
  EXPECT_NEAR(m.points[0].separation, -0.01, 1e-12);
  EXPECT_NEAR((m.points[0].point - Vec2(0.1, 0.495)).norm(), 0, 1e-12);
}

TEST(Manifold, FeatureIdsStableUnderSmallMotion) {
  std::mt19937_64 rng(3);
  const PreparedHull a = box(0.5, 0.5);
  const PreparedHull b = box(0.5, 0.25);
  std::uniform_real_distribution<Real> jitter(-0.01, 0.01);
  const Manifold base = collide_hulls(a, pose_at(0, 0), b, pose_at(0.3, 0.72, 0.05), 0.05);
  ASSERT_EQ(base.point_count, 2);
  for (int k = 0; k < 100; ++k) {
    const Manifold moved =
        collide_hulls(a, pose_at(0, 0), b,
                      pose_at(0.3 + jitter(rng), 0.72 + jitter(rng), 0.05 + jitter(rng)), 0.05);
    ASSERT_EQ(moved.point_count, 2);
    for (int i = 0; i < 2; ++i) {
      const auto& p = moved.points[static_cast<std::size_t>(i)];
      // The same features, so the same ids, matched by position (within the motion).
      const auto& q =
          (p.point - base.points[0].point).norm() < (p.point - base.points[1].point).norm()
              ? base.points[0]
              : base.points[1];
      EXPECT_EQ(p.id, q.id);
    }
  }
}

TEST(Manifold, LargeHullsUseTheSameContactRules) {
  // A 1000-gon approximating a disk resting on a box: one point, depth from the geometry.
  std::vector<Vec2> ring;
  for (int i = 0; i < 1000; ++i) {
    const Real t = 2 * std::numbers::pi * (i + 0.5) / 1000 - std::numbers::pi / 2;
    ring.push_back(Vec2(std::cos(t), std::sin(t)));
  }
  const PreparedHull disk(mink::ConvexHull::from_ccw_vertices(ring));
  const PreparedHull ground = box(5, 0.5);
  const Real bottom = std::cos(std::numbers::pi / 1000);  // the lowest edge's distance
  const Manifold m =
      collide_hulls(ground, pose_at(0, 0), disk, pose_at(0, 0.5 + bottom - 0.02), 0.05);
  ASSERT_GE(m.point_count, 1);
  EXPECT_NEAR((m.normal - Vec2(0, 1)).norm(), 0, 1e-9);
  for (int i = 0; i < m.point_count; ++i) {
    EXPECT_NEAR(m.points[static_cast<std::size_t>(i)].separation, -0.02, 1e-9);
  }
}

// Against brute force on random pairs: contacts exist exactly when the hulls are within the
// margin, no point is deeper than the penetration depth, and the normal is a unit vector.
TEST(Manifold, AgreesWithBruteForceOnRandomPairs) {
  std::mt19937_64 rng(5);
  const Real margin = 0.05;
  int with_points = 0;
  for (int k = 0; k < 4000 / kScale; ++k) {
    const std::size_t na = k % 3 == 0 ? 4 : (k % 3 == 1 ? 7 : 40);
    const std::size_t nb = k % 5 == 0 ? 300 : 5;
    const RandomPair pair = random_pair(rng, na, nb, 1.5);
    const auto& [a, b, pa, pb, wa, wb] = pair;
    const bool overlap = mink::hulls_overlap_exact(wa, wb);
    const Real distance = overlap ? 0 : brute_distance(wa, wb);
    const Manifold m = collide_hulls(a, pa, b, pb, margin);
    if (std::abs(distance - margin) < 1e-9) continue;
    ASSERT_EQ(m.point_count > 0, distance <= margin) << "pair " << k << " distance " << distance;
    if (m.point_count == 0) continue;
    ++with_points;
    EXPECT_NEAR(m.normal.norm(), 1, 1e-12);
    const Real depth = overlap ? brute_depth(wa, wb).depth : 0;
    for (int i = 0; i < m.point_count; ++i) {
      const auto& p = m.points[static_cast<std::size_t>(i)];
      // The reference face may be up to the flip tolerance worse than the best one.
      EXPECT_GE(p.separation, -depth - 1e-3 * std::min(a.radius(), b.radius()) - 1e-9);
      EXPECT_LE(p.separation, margin);
      if (!overlap) {
        EXPECT_GE(p.separation, -1e-9);
      }
    }
  }
  EXPECT_GT(with_points, 500 / kScale);
}

}  // namespace
