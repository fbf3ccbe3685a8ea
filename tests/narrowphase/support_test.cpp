#include "mink/narrowphase/support.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "narrowphase_test_support.hpp"

namespace {

using namespace mink_test;
using mink::support_index_binary;
using mink::support_index_climb;
using mink::support_index_linear;

Vec2 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<Real> angle(-std::numbers::pi, std::numbers::pi);
  const Real t = angle(rng);
  return Vec2(std::cos(t), std::sin(t));
}

TEST(Support, SearchesAgreeWithTheLinearScanOnRandomHulls) {
  std::mt19937_64 rng(7);
  for (std::size_t n : {3u, 4u, 5u, 8u, 17u, 64u, 255u, 1024u, 4000u}) {
    for (int h = 0; h < 20 / kScale + 1; ++h) {
      const PreparedHull hull = random_hull(rng, n);
      std::uniform_int_distribution<std::size_t> start(0, hull.size() - 1);
      for (int k = 0; k < 200; ++k) {
        const Vec2 d = random_direction(rng);
        const std::size_t linear = support_index_linear(hull, d);
        const Real best = hull.vertices()[linear].dot(d);
        ASSERT_EQ(hull.vertices()[support_index_binary(hull, d)].dot(d), best)
            << "n=" << hull.size() << " d=" << format_point(d);
        ASSERT_EQ(hull.vertices()[support_index_climb(hull, d, start(rng))].dot(d), best);
        ASSERT_EQ(hull.vertices()[mink::support_index(hull, d)].dot(d), best);
      }
    }
  }
}

// A NaN direction matches no vertex: every search still names one of the hull's, rather than
// an index past the end (the single-block scan returned 16 of 8, the long scan ran off the
// end; a snapshot restore harness input whose state stepped into NaN found the first).
TEST(Support, ANanDirectionStillNamesAVertex) {
  std::mt19937_64 rng(11);
  const Vec2 nan_direction(std::numeric_limits<Real>::quiet_NaN(), 1);
  for (std::size_t n : {3u, 5u, 8u, 17u, 64u, 65u, 300u}) {
    const PreparedHull hull = random_hull(rng, n);
    EXPECT_LT(support_index_linear(hull, nan_direction), hull.size()) << n;
    EXPECT_LT(mink::support_index(hull, nan_direction), hull.size()) << n;
  }
}

TEST(Support, TiesAlongAnEdgeGiveAMaximalVertex) {
  const PreparedHull square = box(1, 1);
  for (const Vec2& d : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1), Vec2(1, 1)}) {
    const Real best = square.vertices()[support_index_linear(square, d)].dot(d);
    EXPECT_EQ(square.vertices()[support_index_binary(square, d)].dot(d), best);
    for (std::size_t s = 0; s < 4; ++s) {
      EXPECT_EQ(square.vertices()[support_index_climb(square, d, s)].dot(d), best);
    }
  }
}

TEST(Support, NormalsAreUnitOutwardAndAnglesSorted) {
  std::mt19937_64 rng(11);
  const PreparedHull hull = random_hull(rng, 300);
  const auto v = hull.vertices();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2& n = hull.normals()[i];
    EXPECT_NEAR(n.norm(), 1, 1e-15);
    EXPECT_NEAR(n.dot(v[(i + 1) % v.size()] - v[i]), 0, 1e-12);
    EXPECT_GT(n.dot(v[i] - hull.centroid()), 0);
  }
  EXPECT_TRUE(
      std::is_sorted(hull.sorted_normal_angles().begin(), hull.sorted_normal_angles().end()));
}

TEST(Support, PosedSupportIsTheFarthestWorldVertex) {
  std::mt19937_64 rng(13);
  for (int k = 0; k < 200; ++k) {
    const PreparedHull hull = random_hull(rng, k % 2 == 0 ? 6 : 100);
    const Pose pose = random_pose(rng, 10);
    const Vec2 d = random_direction(rng);
    const Vec2 s = mink::support_point(hull, pose, d);
    for (const Vec2& w : world_vertices(hull, pose)) EXPECT_LE(w.dot(d), s.dot(d) + 1e-12);
  }
}

TEST(Support, PseudoAngleIsMonotoneInTheAngle) {
  Real previous = -1;
  for (int k = 0; k < 3600; ++k) {
    const Real t = 2 * std::numbers::pi * k / 3600;
    const Real p = mink::pseudo_angle(Vec2(std::cos(t), std::sin(t)));
    EXPECT_GT(p, previous) << "k=" << k;
    EXPECT_LT(p, 4);
    previous = p;
  }
}

}  // namespace
