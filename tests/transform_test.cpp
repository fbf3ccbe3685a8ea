#include <gtest/gtest.h>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/geometry/transform.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;

std::vector<Vec2> sample_points() {
  return {{0, 0}, {1, 0}, {0.5, 2}, {-3.25, 1.5}, {7, -4}, {1e-3, 1e3}};
}

// Disk points rounded to multiples of 2^-20: adding offsets that are multiples of 2^-20 and
// below 2^30 is then exact, so translation cannot move a point off a hull edge by rounding.
std::vector<Vec2> quantized_points(mink::PointDistribution distribution, std::size_t count,
                                   std::uint64_t seed) {
  auto points = mink::generate_points(distribution, count, seed);
  for (Vec2& p : points) {
    p = Vec2(std::round(std::ldexp(p.x(), 20)), std::round(std::ldexp(p.y(), 20)));
    p = Vec2(std::ldexp(p.x(), -20), std::ldexp(p.y(), -20));
  }
  return points;
}

std::vector<Vec2> vertices_of(const mink::ConvexHull& hull) {
  return {hull.vertices().begin(), hull.vertices().end()};
}

TEST(Transform, TranslateMovesEveryPointByTheOffset) {
  const auto points = sample_points();
  const Vec2 offset(2.5, -1.25);
  const auto moved = mink::translate(points, offset);
  ASSERT_EQ(moved.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(moved[i], points[i] + offset);
  EXPECT_TRUE(mink::translate(std::vector<Vec2>{}, offset).empty());
}

TEST(Transform, ScaleAboutKeepsTheFixedPointAndScalesDistances) {
  const Vec2 fixed(1.5, -2);
  std::vector<Vec2> points = sample_points();
  points.push_back(fixed);
  for (double factor : {2.0, 0.5, 3.0, -1.0, -0.25, 1e-3}) {
    SCOPED_TRACE(testing::Message() << "factor " << factor);
    const auto scaled = mink::scale_about(points, fixed, Vec2(factor, factor));
    ASSERT_EQ(scaled.size(), points.size());
    EXPECT_EQ(scaled.back(), fixed);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double before = (points[i] - fixed).norm();
      const double after = (scaled[i] - fixed).norm();
      EXPECT_NEAR(after, std::abs(factor) * before, 1e-12 * (1 + before));
    }
    // Pairwise distances scale too, not only distances to the fixed point.
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const double before = (points[i + 1] - points[i]).norm();
      const double after = (scaled[i + 1] - scaled[i]).norm();
      EXPECT_NEAR(after, std::abs(factor) * before, 1e-12 * (1 + before));
    }
  }
}

TEST(Transform, ScaleAboutWithDifferentFactorsPerAxis) {
  const Vec2 fixed(-1, 4);
  const Vec2 factor(2, -0.5);
  const auto points = sample_points();
  const auto scaled = mink::scale_about(points, fixed, factor);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Eq. 6 per axis: x' = x_f + s_x (x - x_f), y' = y_f + s_y (y - y_f).
    EXPECT_NEAR(scaled[i].x(), fixed.x() + factor.x() * (points[i].x() - fixed.x()), 1e-12);
    EXPECT_NEAR(scaled[i].y(), fixed.y() + factor.y() * (points[i].y() - fixed.y()), 1e-12);
  }
}

TEST(Transform, ScaleAboutRejectsZeroAndNonFiniteFactors) {
  const auto points = sample_points();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec2& factor : {Vec2(0, 1), Vec2(1, 0), Vec2(0, 0), Vec2(-0.0, 2), Vec2(nan, 1),
                             Vec2(1, nan), Vec2(inf, 1), Vec2(1, -inf)}) {
    SCOPED_TRACE(mink_test::format_point(factor));
    EXPECT_THROW(mink::scale_about(points, Vec2(0, 0), factor), mink::InvalidArgumentError);
    try {
      mink::scale_about(points, Vec2(0, 0), factor);
    } catch (const mink::InvalidArgumentError& error) {
      EXPECT_NE(std::string(error.what()).find("scale factor"), std::string::npos) << error.what();
    }
  }
  // An empty point set is no excuse for a bad factor.
  EXPECT_THROW(mink::scale_about(std::vector<Vec2>{}, Vec2(0, 0), Vec2(0, 1)),
               mink::InvalidArgumentError);
}

TEST(Transform, RotationMatrixIsAProperRotation) {
  for (double radians : {0.0, 0.3, std::numbers::pi / 2, 2.0, -1.0, 10.0}) {
    SCOPED_TRACE(testing::Message() << radians << " rad");
    const mink::Mat2 r = mink::rotation(radians);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-15);
    EXPECT_TRUE((r.transpose() * r).isApprox(mink::Mat2::Identity(), 1e-15));
    EXPECT_TRUE((r * mink::rotation(-radians)).isApprox(mink::Mat2::Identity(), 1e-15));
    // Counter-clockwise: the x axis turns towards the y axis.
    const Vec2 turned = r * Vec2(1, 0);
    EXPECT_NEAR(turned.x(), std::cos(radians), 1e-15);
    EXPECT_NEAR(turned.y(), std::sin(radians), 1e-15);
  }
  EXPECT_TRUE((mink::rotation(0.4) * mink::rotation(0.7)).isApprox(mink::rotation(1.1), 1e-15));
}

TEST(Transform, RotateAboutKeepsThePivotAndDistances) {
  const Vec2 pivot(2, -3);
  std::vector<Vec2> points = sample_points();
  points.push_back(pivot);
  const double radians = 0.7;
  const auto rotated = mink::rotate_about(points, pivot, radians);
  ASSERT_EQ(rotated.size(), points.size());
  EXPECT_EQ(rotated.back(), pivot);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 before = points[i] - pivot;
    const Vec2 after = rotated[i] - pivot;
    EXPECT_NEAR(after.norm(), before.norm(), 1e-12 * (1 + before.norm()));
    if (before.norm() > 0) {
      // The angle turned is the requested one, counter-clockwise.
      const double turned =
          std::atan2(before.x() * after.y() - before.y() * after.x(), before.dot(after));
      EXPECT_NEAR(turned, radians, 1e-12);
    }
  }
  // A quarter turn about the origin maps (1, 0) to (0, 1).
  const auto quarter =
      mink::rotate_about(std::vector<Vec2>{{1, 0}}, Vec2(0, 0), std::numbers::pi / 2);
  EXPECT_NEAR(quarter[0].x(), 0, 1e-15);
  EXPECT_NEAR(quarter[0].y(), 1, 1e-15);
}

TEST(Transform, HullOfTranslatedPointsIsTheTranslatedHull) {
  const std::vector<Vec2> offsets = {Vec2(0x1p20, -0x1p10), Vec2(-0x1p29, 0x1p-3), Vec2(0.5, 0.25),
                                     Vec2(-0x1p15 - 0x1p-20, 0x1p25)};
  for (mink::PointDistribution distribution :
       {mink::PointDistribution::uniform_disk, mink::PointDistribution::on_circle,
        mink::PointDistribution::lattice, mink::PointDistribution::clusters}) {
    const auto points = quantized_points(distribution, 2'000, 7);
    for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
      const auto hull = mink::build_hull(points, algorithm);
      for (const Vec2& offset : offsets) {
        SCOPED_TRACE(testing::Message()
                     << mink::to_string(distribution) << ", " << mink::to_string(algorithm)
                     << ", offset " << mink_test::format_point(offset));
        const auto moved_hull = mink::build_hull(mink::translate(points, offset), algorithm);
        EXPECT_TRUE(
            mink_test::same_ring(mink::translate(hull.vertices(), offset), moved_hull.vertices()));
      }
    }
  }
}

TEST(Transform, HullOfScaledPointsIsTheScaledHull) {
  // Scaling about the origin by powers of two is exact; a negative factor mirrors the set,
  // which reverses the hull's orientation, so compare in canonical form from CGAL.
  const auto points = mink::generate_points(mink::PointDistribution::gaussian, 2'000, 8);
  for (const Vec2& factor : {Vec2(2, 2), Vec2(0.25, 0.25), Vec2(0x1p-40, 0x1p30)}) {
    SCOPED_TRACE(mink_test::format_point(factor));
    const auto hull = mink::build_hull(points, mink::HullAlgorithm::monotone_chain);
    const auto scaled_hull =
        mink::build_hull(mink::scale_about(points, Vec2(0, 0), factor), mink::HullAlgorithm::chan);
    EXPECT_TRUE(mink_test::same_ring(mink::scale_about(vertices_of(hull), Vec2(0, 0), factor),
                                     scaled_hull.vertices()));
  }
  const auto mirrored = mink::scale_about(points, Vec2(0, 0), Vec2(-1, 1));
  const auto mirrored_hull = mink::build_hull(mirrored, mink::HullAlgorithm::graham);
  EXPECT_TRUE(mink_test::same_ring(mink_test::reference_hull(mirrored), mirrored_hull.vertices()));
  EXPECT_EQ(mirrored_hull.size(), mink::build_hull(points, mink::HullAlgorithm::graham).size());
}

TEST(Transform, HullOfRotatedPointsHasTheRotatedVertices) {
  // The rotated hull vertices are the very doubles rotate_about gives for those points, so
  // each must appear in the hull of the rotated set.
  const auto points = mink::generate_points(mink::PointDistribution::uniform_disk, 1'000, 9);
  const auto hull = mink::build_hull(points, mink::HullAlgorithm::chan);
  const auto rotated = mink::rotate_about(points, Vec2(0.25, -0.5), 1.0);
  const auto rotated_hull = mink::build_hull(rotated, mink::HullAlgorithm::chan);
  const auto expected =
      mink_test::canonical_ring(mink::rotate_about(hull.vertices(), Vec2(0.25, -0.5), 1.0));
  EXPECT_TRUE(mink_test::same_ring(expected, rotated_hull.vertices()));
}

}  // namespace
