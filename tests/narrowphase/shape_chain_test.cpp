// Chain segments: one-sided, and smooth across their joints (the ghost vertices decide which
// normals exist there).

#include <gtest/gtest.h>

#include "mink/narrowphase/collide.hpp"
#include "shape_oracle.hpp"

namespace {

using namespace mink_test;
using mink::ChainSegment;
using mink::Manifold;

// The chain through `points` as segments with their ghosts (open ends repeat the line).
std::vector<ChainSegment> chain(const std::vector<Vec2>& points) {
  std::vector<ChainSegment> segments;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec2 before = i == 0 ? Vec2(2 * points[0] - points[1]) : points[i - 1];
    const Vec2 after = i + 2 < points.size() ? points[i + 2] : Vec2(2 * points[i + 1] - points[i]);
    segments.push_back({before, mink::Segment{points[i], points[i + 1]}, after});
  }
  return segments;
}

// Points along y = 0 from x = `right` down to x = `left` (right to left, so the right-hand
// normal is +y), `count` segments.
std::vector<Vec2> flat_line(Real right, Real left, int count) {
  std::vector<Vec2> points;
  for (int i = 0; i <= count; ++i) points.emplace_back(right + (left - right) * i / count, 0);
  return points;
}

ShapeGeometry box_shape(Real hx, Real hy) {
  return mink::RoundedPolygon{box(hx, hy), 0};
}

struct SweepResult {
  int poses = 0;
  int touched = 0;       // poses where some segment gave points
  int sideways = 0;      // chain normals that are not +y
  int raw_sideways = 0;  // the same poses against two-sided segments
};

// Slides `shape` across every joint of the chain, sunk `depth` into it and tilted slightly,
// collecting every normal the chain segments give.
SweepResult sweep(const std::vector<ChainSegment>& segments, const ShapeGeometry& shape,
                  Real half_height, Real x0, Real x1) {
  SweepResult r;
  for (int i = 0; i <= 4000; ++i) {
    const Real x = x0 + (x1 - x0) * i / 4000;
    for (Real depth : {0.0, 0.002, 0.02, 0.1}) {
      for (Real angle : {0.0, 1e-7, -1e-3}) {
        const Pose pose = pose_at(x, half_height - depth, angle);
        ++r.poses;
        bool touched = false;
        for (const ChainSegment& s : segments) {
          const Manifold m = collide_shapes(s, Pose{}, shape, pose, 0.05);
          if (m.point_count > 0) touched = true;
          if (m.point_count > 0 && (m.normal - Vec2(0, 1)).norm() > 1e-9) ++r.sideways;
          const Manifold raw = collide_shapes(s.segment, Pose{}, shape, pose, 0.05);
          if (raw.point_count > 0 && (raw.normal - Vec2(0, 1)).norm() > 1e-9) ++r.raw_sideways;
        }
        if (touched) ++r.touched;
      }
    }
  }
  return r;
}

TEST(Chain, BoxAcrossAFlatJointOnlyGetsTheUpNormal) {
  const auto segments = chain(flat_line(2, -2, 2));  // joint at x = 0
  const SweepResult r = sweep(segments, box_shape(0.5, 0.5), 0.5, -0.7, 0.7);
  EXPECT_EQ(r.touched, r.poses);
  EXPECT_EQ(r.sideways, 0);
  // Two-sided segments in the same poses do catch: the test can fail.
  EXPECT_GT(r.raw_sideways, 0);
}

TEST(Chain, CapsuleAcrossAFlatJointOnlyGetsTheUpNormal) {
  const auto segments = chain(flat_line(2, -2, 2));
  const ShapeGeometry capsule = mink::Capsule{Vec2(-0.6, 0), Vec2(0.6, 0), 0.25};
  const SweepResult r = sweep(segments, capsule, 0.25, -1.0, 1.0);
  EXPECT_EQ(r.touched, r.poses);
  EXPECT_EQ(r.sideways, 0);
  EXPECT_GT(r.raw_sideways, 0);
}

TEST(Chain, BoxAlongManyCollinearSegmentsOnlyGetsTheUpNormal) {
  const auto segments = chain(flat_line(5, -5, 40));  // joints every 0.25
  const SweepResult r = sweep(segments, box_shape(0.4, 0.3), 0.3, -4, 4);
  EXPECT_EQ(r.touched, r.poses);
  EXPECT_EQ(r.sideways, 0);
  EXPECT_GT(r.raw_sideways, 0);
}

TEST(Chain, ShapesBehindTheChainGetNothing) {
  const auto segments = chain(flat_line(2, -2, 2));
  const std::vector<ShapeGeometry> shapes = {box_shape(0.5, 0.5), mink::Circle{Vec2(0, 0), 0.4},
                                             mink::Capsule{Vec2(-0.5, 0), Vec2(0.5, 0), 0.2},
                                             mink::Segment{Vec2(-1, 0), Vec2(1, 0)},
                                             mink::RoundedPolygon{box(0.3, 0.2), 0.1}};
  int overlapping = 0;
  for (const ShapeGeometry& shape : shapes) {
    for (int i = 0; i <= 200; ++i) {
      // Centre below the line (the left side), overlapping the chain or not.
      const Pose pose = pose_at(-1.5 + 3.0 * i / 200, -0.05 - 0.4 * (i % 7) / 7, 0.1 * (i % 5));
      for (const ChainSegment& s : segments) {
        if (shape_distance(s, Pose{}, shape, pose).overlap) ++overlapping;
        EXPECT_EQ(collide_shapes(s, Pose{}, shape, pose, 0.1).point_count, 0);
        EXPECT_EQ(collide_shapes(shape, pose, s, Pose{}, 0.1).point_count, 0);
      }
    }
  }
  EXPECT_GT(overlapping, 500);  // they did overlap the segments
}

TEST(Chain, ConvexJointGivesAnInBetweenNormal) {
  // A hill top at the origin: flat to the right, sloping down at 45 degrees to the left.
  const auto segments = chain({Vec2(2, 0), Vec2(0, 0), Vec2(-2, -2)});
  const Vec2 n0(0, 1);
  const Vec2 n1 = Vec2(-1, 1).normalized();
  const Vec2 bisector = (n0 + n1).normalized();
  const ShapeGeometry circle = mink::Circle{Vec2(0, 0), 0.5};
  for (const ChainSegment& s : segments) {
    const Manifold m =
        collide_shapes(s, Pose{}, circle, pose_at(0.45 * bisector.x(), 0.45 * bisector.y()), 0.0);
    ASSERT_EQ(m.point_count, 1);
    EXPECT_NEAR((m.normal - bisector).norm(), 0, 1e-12);
    EXPECT_NEAR(m.points[0].separation, -0.05, 1e-12);
  }
  // The same place on a concave (valley) joint: only the segments' own normals.
  const auto valley = chain({Vec2(2, 0), Vec2(0, 0), Vec2(-2, 2)});
  const Vec2 up_left = Vec2(1, 1).normalized();  // right normal of (0,0) -> (-2,2)
  for (const ChainSegment& s : valley) {
    const Manifold m = collide_shapes(s, Pose{}, circle, pose_at(0, 0.45), 0.0);
    ASSERT_EQ(m.point_count, 1);
    EXPECT_TRUE((m.normal - n0).norm() < 1e-12 || (m.normal - up_left).norm() < 1e-12)
        << format_point(m.normal);
  }
}

// With ghosts that turn a right angle away (a cliff at each end), every normal on the front
// side is admissible, so a shape wholly in front of the segment gets exactly the two-sided
// answer; with flat ghosts every normal is the segment's.
TEST(Chain, RandomShapesInFrontMatchTheOracleOrUseTheSegmentNormal) {
  std::mt19937_64 rng(77);
  int compared = 0;
  int flat_checked = 0;
  for (int k = 0; k < 40000 / kScale; ++k) {
    const ShapeKind kind = static_cast<ShapeKind>(rng() % 5);
    if (kind == ShapeKind::chain_segment) continue;
    const ShapeGeometry shape = random_shape(rng, kind);
    const Pose pose = random_pose(rng, 1.4);
    const Vec2 p1 = random_point(rng, 1.2);
    Vec2 p2 = random_point(rng, 1.2);
    while ((p2 - p1).norm() < 0.3) p2 = random_point(rng, 1.2);
    const Vec2 e = p2 - p1;
    const Vec2 n = Vec2(e.y(), -e.x()).normalized();
    const WorldCore core = world_core(shape, pose);
    bool in_front = true;
    for (const Vec2& p : core.points) in_front = in_front && n.dot(p - p1) > 1e-6;
    const ChainSegment cliff{p1 - n, mink::Segment{p1, p2}, p2 - n};
    const ChainSegment flat{p1 - e, mink::Segment{p1, p2}, p2 + e};
    const Pose chain_pose = random_pose(rng, 0.5);
    const Pose shape_pose = [&] {
      Pose q;  // the shape's pose composed with the chain's, so the chain frame is the world
      q.rotation = mink::Rotation::from_angle(pose.rotation.angle() + chain_pose.rotation.angle());
      q.position = chain_pose.apply(pose.position);
      return q;
    }();
    const Manifold m = collide_shapes(cliff, chain_pose, shape, shape_pose, 0.2);
    const Real gap = signed_gap(core, WorldCore{{p1, p2}, 0}).gap;
    if (in_front) {
      if (std::abs(gap - 0.2) > 1e-9) {
        ASSERT_EQ(m.point_count > 0, gap < 0.2) << k;
      }
      if (m.point_count > 0) {
        Real lowest = m.points[0].separation;
        if (m.point_count == 2) lowest = std::min(lowest, m.points[1].separation);
        EXPECT_NEAR(lowest, gap, 1e-9 * (1 + std::abs(gap))) << k;
        ++compared;
      }
    }
    const Manifold f = collide_shapes(shape, shape_pose, flat, chain_pose, 0.2);
    if (f.point_count > 0) {
      EXPECT_NEAR((f.normal + chain_pose.rotation.apply(n)).norm(), 0, 1e-9) << k;
      ++flat_checked;
    }
  }
  EXPECT_GT(compared, 2000 / kScale);
  EXPECT_GT(flat_checked, 2000 / kScale);
}

}  // namespace
