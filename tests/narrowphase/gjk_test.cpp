#include <gtest/gtest.h>

#include "mink/error.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/penetration.hpp"
#include "narrowphase_test_support.hpp"

namespace {

using namespace mink_test;
using mink::gjk_distance;
using mink::gjk_overlap;
using mink::hulls_overlap_exact;
using mink::penetration;

PreparedHull hull_of(std::vector<Vec2> points) {
  return PreparedHull(mink::build_hull(points, mink::HullAlgorithm::monotone_chain));
}

const Pose kIdentity{};

// Fewer pairs for large hulls: the brute-force oracles cost n * m each.
int pairs_for(std::size_t n, int base) {
  return std::max<int>(20, static_cast<int>(base * 16 / std::max<std::size_t>(n, 16))) / kScale;
}

// ---- The paper's boolean -------------------------------------------------------------------

TEST(GjkOverlap, AgreesWithTheExactTestOnRandomPairs) {
  std::mt19937_64 rng(21);
  int overlapping = 0;
  int total = 0;
  for (std::size_t n : {3u, 4u, 8u, 16u, 64u, 256u, 1024u}) {
    for (int k = 0; k < pairs_for(n, 1500); ++k) {
      const RandomPair pair = random_pair(rng, n, k % 2 == 0 ? n : 5, 1.5);
      const auto& [a, b, pa, pb, wa, wb] = pair;
      const bool exact = hulls_overlap_exact(wa, wb);
      const mink::OverlapResult r = gjk_overlap(a, pa, b, pb);
      ASSERT_FALSE(r.reached_iteration_cap);
      // Rounding in the posed vertices can only matter right at touching.
      const Real margin = exact ? brute_depth(wa, wb).depth : brute_distance(wa, wb);
      if (margin < 1e-12) continue;
      ASSERT_EQ(r.overlap, exact) << "n=" << n << " pair " << k;
      if (!r.overlap) {
        // The reported direction separates the world vertices.
        const Vec2 d = r.separating_direction;
        Real max_a = -1e300, min_b = 1e300;
        for (const Vec2& v : wa) max_a = std::max(max_a, v.dot(d));
        for (const Vec2& v : wb) min_b = std::min(min_b, v.dot(d));
        EXPECT_LT(max_a, min_b);
      } else {
        // The final simplex, drawn in world coordinates, holds the origin.
        ASSERT_GE(r.simplex.count, 1);
        const mink::Simplex s = mink::world_simplex(r.simplex, a, pa, b, pb);
        for (int i = 0; i < s.count; ++i) {
          const auto& v = s.vertices[static_cast<std::size_t>(i)];
          EXPECT_EQ(v.a, wa[v.index_a]);
          EXPECT_EQ(v.point, v.a - v.b);
        }
        if (s.count == 3) {
          const Vec2 o(0, 0);
          const auto& p = s.vertices;
          const int w = mink::orient2d(p[0].point, p[1].point, p[2].point);
          EXPECT_NE(mink::orient2d(p[0].point, p[1].point, o), -w);
          EXPECT_NE(mink::orient2d(p[1].point, p[2].point, o), -w);
          EXPECT_NE(mink::orient2d(p[2].point, p[0].point, o), -w);
        }
      }
      overlapping += exact;
      ++total;
    }
  }
  EXPECT_GT(overlapping, total / 5);
  EXPECT_LT(overlapping, total * 4 / 5);
}

// Long thin boxes against small ones, as a wall against the bodies it holds: here the
// simplex often leaves through edge ab, the case that once aimed the search along a zero
// direction and answered "overlap" for hulls centimetres apart.
TEST(GjkOverlap, ThinWallsAgreeWithTheExactTest) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<Real> length(2, 30), thickness(0.05, 1), side(0.2, 1);
  int overlapping = 0;
  int total = 0;
  for (int k = 0; k < 40000 / kScale; ++k) {
    const Real l = length(rng), t = thickness(rng), s = side(rng);
    const PreparedHull wall =
        hull_of({{-l / 2, -t / 2}, {l / 2, -t / 2}, {l / 2, t / 2}, {-l / 2, t / 2}});
    const PreparedHull box =
        hull_of({{-s / 2, -s / 2}, {s / 2, -s / 2}, {s / 2, s / 2}, {-s / 2, s / 2}});
    const Pose pa = random_pose(rng, 1);
    const Pose pb = random_pose(rng, l / 2);
    const std::vector<Vec2> wa = world_vertices(wall, pa);
    const std::vector<Vec2> wb = world_vertices(box, pb);
    const bool exact = hulls_overlap_exact(wa, wb);
    const Real margin = exact ? brute_depth(wa, wb).depth : brute_distance(wa, wb);
    if (margin < 1e-12) continue;
    ASSERT_EQ(gjk_overlap(wall, pa, box, pb).overlap, exact) << "pair " << k;
    overlapping += exact;
    ++total;
  }
  EXPECT_GT(overlapping, total / 20);
  EXPECT_LT(overlapping, total * 19 / 20);
}

TEST(GjkOverlap, TouchingCountsAsOverlap) {
  const PreparedHull a = hull_of({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  // Origin on an edge of A - B: the boxes share an edge.
  EXPECT_TRUE(gjk_overlap(a, kIdentity, a, pose_at(1, 0)).overlap);
  EXPECT_TRUE(gjk_overlap(a, kIdentity, a, pose_at(0, -1)).overlap);
  // Origin at a vertex of A - B: corners touch.
  EXPECT_TRUE(gjk_overlap(a, kIdentity, a, pose_at(1, 1)).overlap);
  EXPECT_TRUE(gjk_overlap(a, kIdentity, a, pose_at(-1, 1)).overlap);
  // Partial edge contact and a vertex on an edge.
  EXPECT_TRUE(gjk_overlap(a, kIdentity, a, pose_at(1, 0.5)).overlap);
  const PreparedHull tri = hull_of({Vec2(0, 0), Vec2(2, 1), Vec2(0, 2)});
  EXPECT_TRUE(
      gjk_overlap(a, kIdentity, tri, pose_at(1, -1 + 0.5)).overlap ||
      !hulls_overlap_exact(world_vertices(a, kIdentity), world_vertices(tri, pose_at(1, -0.5))));
  const PreparedHull diamond = hull_of({Vec2(0, -1), Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)});
  EXPECT_TRUE(gjk_overlap(a, kIdentity, diamond, pose_at(0.5, 2)).overlap);  // vertex on edge
  EXPECT_FALSE(gjk_overlap(a, kIdentity, diamond, pose_at(0.5, 2.0000001)).overlap);
  // Just apart, by one unit in the last place.
  EXPECT_FALSE(gjk_overlap(a, kIdentity, a, pose_at(std::nextafter(1.0, 2.0), 0)).overlap);
  EXPECT_FALSE(gjk_overlap(a, kIdentity, a, pose_at(1, std::nextafter(1.0, 2.0))).overlap);
}

TEST(GjkOverlap, IdenticalAndNestedShapes) {
  std::mt19937_64 rng(4);
  const PreparedHull a = random_hull(rng, 12);
  // Identical shapes in the same pose: centroid direction is zero.
  const mink::OverlapResult same = gjk_overlap(a, kIdentity, a, kIdentity);
  EXPECT_TRUE(same.overlap);
  EXPECT_FALSE(same.reached_iteration_cap);
  // One inside the other, both ways round, with the same centroid and off-centre.
  const PreparedHull inner = hull_of({Vec2(-0.01, -0.01), Vec2(0.01, -0.01), Vec2(0, 0.01)});
  for (const Pose& p : {kIdentity, pose_at(0.05, -0.02, 1.0)}) {
    EXPECT_TRUE(gjk_overlap(a, kIdentity, inner, p).overlap);
    EXPECT_TRUE(gjk_overlap(inner, p, a, kIdentity).overlap);
  }
}

TEST(GjkOverlap, HugeAndTinyCoordinates) {
  // Powers of two keep the poses' sums exact, so touching stays exactly touching.
  for (Real scale : {0x1p-500, 0x1p-1000, 0x1p500, 0x1p1000, 1e-150, 1e150}) {
    const PreparedHull a =
        hull_of({Vec2(0, 0), Vec2(scale, 0), Vec2(scale, scale), Vec2(0, scale)});
    const Vec2 far(7 * scale, 3 * scale);
    SCOPED_TRACE(scale);
    if (scale == std::ldexp(1.0, std::ilogb(scale))) {
      EXPECT_TRUE(
          gjk_overlap(a, pose_at(far.x(), far.y()), a, pose_at(far.x() + scale, far.y())).overlap);
      EXPECT_TRUE(
          gjk_overlap(a, pose_at(far.x(), far.y()), a, pose_at(far.x() + scale, far.y() + scale))
              .overlap);
      EXPECT_FALSE(gjk_overlap(a, pose_at(far.x(), far.y()), a,
                               pose_at(far.x() + scale, far.y() + scale + scale * 0x1p-40))
                       .overlap);
    }
    EXPECT_TRUE(gjk_overlap(a, pose_at(far.x(), far.y()), a,
                            pose_at(far.x() + 0.5 * scale, far.y() + 0.25 * scale))
                    .overlap);
    EXPECT_FALSE(gjk_overlap(a, pose_at(far.x(), far.y()), a,
                             pose_at(far.x() + 1.001 * scale, far.y() + 0.5 * scale))
                     .overlap);
    EXPECT_FALSE(gjk_overlap(a, kIdentity, a, pose_at(-2 * scale, -2 * scale)).overlap);
  }
}

TEST(GjkOverlap, ExactTestOnTheEdgeCases) {
  const std::vector<Vec2> a = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  EXPECT_TRUE(hulls_overlap_exact(a, translated(a, Vec2(1, 1))));
  EXPECT_TRUE(hulls_overlap_exact(a, translated(a, Vec2(1, 0.3))));
  EXPECT_FALSE(hulls_overlap_exact(a, translated(a, Vec2(std::nextafter(1.0, 2.0), 0.3))));
}

// ---- Distance ------------------------------------------------------------------------------

TEST(GjkDistance, AgreesWithBruteForceOnRandomSeparatedPairs) {
  std::mt19937_64 rng(31);
  int checked = 0;
  for (std::size_t n : {3u, 6u, 8u, 32u, 256u, 1024u}) {
    for (int k = 0; k < pairs_for(n, 1000); ++k) {
      const RandomPair pair = random_pair(rng, n, k % 3 == 0 ? 4 : n, 2.5);
      const auto& [a, b, pa, pb, wa, wb] = pair;
      const mink::DistanceResult r = gjk_distance(a, pa, b, pb);
      ASSERT_FALSE(r.reached_iteration_cap);
      if (hulls_overlap_exact(wa, wb)) {
        EXPECT_TRUE(r.overlap || r.distance < 1e-12);
        continue;
      }
      const Real expected = brute_distance(wa, wb);
      ASSERT_FALSE(r.overlap) << "n=" << n << " pair " << k;
      ASSERT_NEAR(r.distance, expected, 1e-9 * std::max<Real>(1, expected)) << "n=" << n;
      EXPECT_NEAR(r.normal.norm(), 1, 1e-12);
      // The witness points are a distance apart along the normal and lie on the hulls.
      EXPECT_NEAR((r.point_b - r.point_a - r.distance * r.normal).norm(), 0, 1e-9);
      Real max_a = -1e300, min_b = 1e300;
      for (const Vec2& v : wa) max_a = std::max(max_a, v.dot(r.normal));
      for (const Vec2& v : wb) min_b = std::min(min_b, v.dot(r.normal));
      EXPECT_NEAR(max_a, r.point_a.dot(r.normal), 1e-9);
      EXPECT_NEAR(min_b, r.point_b.dot(r.normal), 1e-9);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300 / kScale);
}

TEST(GjkDistance, WarmStartConvergesInOneOrTwoIterations) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<Real> step(-1e-3, 1e-3);
  int pairs = 0;
  for (std::size_t n : {4u, 8u, 64u, 1024u}) {
    for (int k = 0; k < 200 / kScale; ++k) {
      const PreparedHull a = random_hull(rng, n);
      const PreparedHull b = random_hull(rng, n);
      Pose pa = random_pose(rng, 0.1);
      Pose pb = random_pose(rng, 0.1);
      pb.position += Vec2(5, 0);
      mink::SimplexCache cache;
      (void)gjk_distance(a, pa, b, pb, &cache);
      int total = 0;
      int most = 0;
      for (int t = 0; t < 10; ++t) {
        pb.position += Vec2(step(rng), step(rng));
        pb.rotation = mink::Rotation::from_angle(pb.rotation.angle() + step(rng));
        const mink::DistanceResult warm = gjk_distance(a, pa, b, pb, &cache);
        const mink::DistanceResult cold = gjk_distance(a, pa, b, pb);
        EXPECT_NEAR(warm.distance, cold.distance, 1e-12 * cold.distance);
        total += warm.iterations;
        most = std::max(most, warm.iterations);
      }
      EXPECT_LE(total, 25) << "n=" << n;
      EXPECT_LE(most, 4) << "n=" << n;
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 0);
}

TEST(GjkDistance, TouchingAndOverlappingReportZero) {
  const PreparedHull a = hull_of({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  for (const Pose& p : {pose_at(1, 0), pose_at(1, 1), pose_at(0.5, 0.5), kIdentity}) {
    const mink::DistanceResult r = gjk_distance(a, kIdentity, a, p);
    EXPECT_TRUE(r.overlap);
    EXPECT_EQ(r.distance, 0);
  }
  const mink::DistanceResult apart = gjk_distance(a, kIdentity, a, pose_at(3, 4));
  EXPECT_NEAR(apart.distance, std::sqrt(2.0 * 2.0 + 3.0 * 3.0), 1e-14);
  // A stale cache (indices from other hulls) is ignored.
  mink::SimplexCache stale;
  stale.count = 3;
  stale.index_a = {9, 1, 2};
  EXPECT_NEAR(gjk_distance(a, kIdentity, a, pose_at(3, 4), &stale).distance, apart.distance, 1e-14);
}

// A gap far below unit size: its square underflows, so |gap| and gap / |gap| are taken from
// the gap scaled by a power of two (the overlap_line harness found a normal 1e-5 off unit
// length at a gap of 1e-161).
TEST(GjkDistance, TinyGapsHaveAnExactDistanceAndAUnitNormal) {
  // a's top edge and b's bottom edge on y = 0, so b can be moved a subnormal gap up.
  const std::vector<Vec2> below = {Vec2(0, -1), Vec2(1, -1), Vec2(1, 0), Vec2(0, 0)};
  const std::vector<Vec2> above = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const PreparedHull a = hull_of(below), b = hull_of(above);
  for (const Real gap : {1e-161, 3e-200, 0x1p-1000, 5e-310}) {
    SCOPED_TRACE(gap);
    const mink::DistanceResult r = gjk_distance(a, kIdentity, b, pose_at(0.25, gap));
    ASSERT_FALSE(r.overlap);
    EXPECT_EQ(r.distance, gap);
    EXPECT_EQ(r.normal, Vec2(0, 1));
    const mink::BruteDistance brute =
        mink::hull_distance_brute(below, translated(above, Vec2(0.25, gap)));
    EXPECT_EQ(brute.distance, gap);
    EXPECT_EQ(brute.normal, Vec2(0, 1));
  }
}

// Every vertex finite, two of them farther apart than a double holds: no edge or area of the
// hull can be computed, so it is refused (it used to reach the exact predicate as infinities).
TEST(PreparedHullLimits, AHullWiderThanADoubleIsRefused) {
  const mink::ConvexHull wide = mink::ConvexHull::from_ccw_vertices(
      std::vector<Vec2>{Vec2(-1.7e308, 0), Vec2(1.7e308, 0), Vec2(0, 1)});
  EXPECT_THROW(PreparedHull{wide}, mink::InvalidArgumentError);
}

// ---- Penetration depth ---------------------------------------------------------------------

TEST(Penetration, AgreesWithBruteForceAndUndoesTheOverlap) {
  std::mt19937_64 rng(51);
  int checked = 0;
  for (std::size_t n : {3u, 4u, 8u, 32u, 256u, 1024u}) {
    for (int k = 0; k < pairs_for(n, 1000); ++k) {
      const RandomPair pair = random_pair(rng, n, k % 2 == 0 ? 5 : n, 0.8);
      const auto& [a, b, pa, pb, wa, wb] = pair;
      if (!hulls_overlap_exact(wa, wb)) continue;
      const mink::DistanceResult d = gjk_distance(a, pa, b, pb);
      ASSERT_TRUE(d.overlap);
      const mink::PenetrationResult p = penetration(a, pa, b, pb, d.simplex);
      const BruteDepth expected = brute_depth(wa, wb);
      ASSERT_NEAR(p.depth, expected.depth, 1e-9 * std::max<Real>(1, expected.depth))
          << "n=" << n << " pair " << k;
      EXPECT_NEAR(p.normal.norm(), 1, 1e-12);
      // Moving B by the depth along the normal (plus a hair) separates; a little less doesn't.
      const Real hair = 1e-9 * std::max<Real>(1, p.depth);
      EXPECT_FALSE(hulls_overlap_exact(wa, translated(wb, (p.depth + hair) * p.normal)));
      if (p.depth > 2 * hair) {
        EXPECT_TRUE(hulls_overlap_exact(wa, translated(wb, (p.depth - hair) * p.normal)));
      }
      // The face test is the same answer by another route.
      EXPECT_NEAR(mink::penetration_by_faces(a, pa, b, pb).depth, expected.depth,
                  1e-9 * std::max<Real>(1, expected.depth));
      ++checked;
    }
  }
  EXPECT_GT(checked, 300 / kScale);
}

TEST(Penetration, DegenerateStartsFallBackToTheFaceTest) {
  const PreparedHull a = hull_of({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)});
  // Touching: depth 0 along the shared edge's normal.
  const mink::DistanceResult touching = gjk_distance(a, kIdentity, a, pose_at(1, 0.5));
  const mink::PenetrationResult p = penetration(a, kIdentity, a, pose_at(1, 0.5), touching.simplex);
  EXPECT_EQ(p.depth, 0);
  EXPECT_NEAR((p.normal - Vec2(1, 0)).norm(), 0, 1e-15);
  // Identical boxes in the same place: depth 1 along some axis.
  const mink::DistanceResult same = gjk_distance(a, kIdentity, a, kIdentity);
  const mink::PenetrationResult q = penetration(a, kIdentity, a, kIdentity, same.simplex);
  EXPECT_NEAR(q.depth, 1, 1e-15);
  // An empty simplex is allowed too.
  EXPECT_NEAR(penetration(a, kIdentity, a, pose_at(0.25, 0.1), mink::SimplexCache{}).depth, 0.75,
              1e-15);
}

}  // namespace
