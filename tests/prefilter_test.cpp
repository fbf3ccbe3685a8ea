#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/akl_toussaint.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/geometry/point_sets.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_point;
using mink_test::format_points;

// The filter's contract: the output is the input with points removed (order kept), and every
// vertex of the input's hull survives, so the hull is unchanged.
::testing::AssertionResult is_safe_filtering(std::span<const Vec2> input,
                                             std::span<const Vec2> output) {
  std::size_t at = 0;
  for (const Vec2& p : output) {
    while (at < input.size() && input[at] != p) ++at;
    if (at == input.size()) {
      return ::testing::AssertionFailure()
             << format_point(p) << " is not in the input, or not in input order";
    }
    ++at;
  }
  const auto hull = mink_test::reference_hull(input);
  std::vector<Vec2> kept(output.begin(), output.end());
  std::sort(kept.begin(), kept.end(), mink::lex_less);
  for (const Vec2& v : hull) {
    if (!std::binary_search(kept.begin(), kept.end(), v, mink::lex_less)) {
      return ::testing::AssertionFailure() << "hull vertex " << format_point(v) << " was dropped";
    }
  }
  const auto filtered_hull = mink_test::reference_hull(output);
  if (filtered_hull != hull) {
    return ::testing::AssertionFailure() << "the hull changed";
  }
  return ::testing::AssertionSuccess();
}

std::vector<Vec2> scaled(std::vector<Vec2> points, double factor) {
  for (Vec2& p : points) p *= factor;
  return points;
}

TEST(AklToussaint, KeepsEveryHullVertexOnEveryDistribution) {
  const std::size_t largest = 100'000;
  for (mink::PointDistribution distribution : mink::all_point_distributions()) {
    for (std::size_t size : {std::size_t{3}, std::size_t{10}, std::size_t{1'000}, largest}) {
      for (std::uint64_t seed = 1; seed <= (size <= 10 ? 50u : 2u); ++seed) {
        const auto points = mink::generate_points(distribution, size, seed);
        if (mink_test::reference_hull(points).size() < 3) continue;  // degenerate: throws
        SCOPED_TRACE(testing::Message()
                     << mink::to_string(distribution) << ", " << size << " points, seed " << seed);
        EXPECT_TRUE(is_safe_filtering(points, mink::akl_toussaint_filter(points)));
      }
    }
  }
}

TEST(AklToussaint, RemovesMostPointsOfAUniformDisk) {
  const auto points = mink::generate_points(mink::PointDistribution::uniform_disk, 100'000, 3);
  const auto kept = mink::akl_toussaint_filter(points);
  EXPECT_LT(kept.size(), points.size() * 3 / 10);
  EXPECT_TRUE(is_safe_filtering(points, kept));
}

TEST(AklToussaint, ExtremeMagnitudesKeepEveryHullVertex) {
  // Edge tests overflow to infinity or NaN at 1e300 and underflow at 1e-300; either way no hull
  // vertex may be dropped.
  const auto disk = mink::generate_points(mink::PointDistribution::uniform_disk, 5'000, 4);
  for (double factor : {1e300, 1.7e308, 1e-300, 1e-320, 1e150, 1e-150}) {
    SCOPED_TRACE(testing::Message() << "scale " << factor);
    const auto points = scaled(disk, factor);
    EXPECT_TRUE(is_safe_filtering(points, mink::akl_toussaint_filter(points)));
  }
}

TEST(AklToussaint, PointsOnTheExtremePolygonBoundaryAreKept) {
  // Lattice points on the edges of the extreme octagon are hull candidates, not interior.
  std::vector<Vec2> points;
  for (int x = -10; x <= 10; ++x) {
    for (int y = -10; y <= 10; ++y) {
      if (std::abs(x) + std::abs(y) <= 15) points.push_back({x + 0.0, y + 0.0});
    }
  }
  const auto kept = mink::akl_toussaint_filter(points);
  EXPECT_TRUE(is_safe_filtering(points, kept));
  EXPECT_LT(kept.size(), points.size());
}

TEST(AklToussaint, CollinearExtremesKeepEverything) {
  // All eight extremes are (0, 0) or (3, 1); the third point is not extreme in any of the
  // eight directions, yet makes the set non-degenerate.
  const std::vector<Vec2> points = {{0, 0}, {3, 1}, {1.5, 0.5 + 1e-9}};
  const auto kept = mink::akl_toussaint_filter(points);
  EXPECT_EQ(kept, points);
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    EXPECT_TRUE(mink_test::same_ring(
        mink_test::reference_hull(points),
        mink::build_hull(points, algorithm, mink::HullOptions{true}).vertices()))
        << mink::to_string(algorithm);
  }
}

TEST(AklToussaint, ValidatesItsInput) {
  EXPECT_THROW(mink::akl_toussaint_filter(std::vector<Vec2>{{0, 0}, {1, 1}}),
               mink::DegenerateInputError);
  EXPECT_THROW(mink::akl_toussaint_filter(std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}}),
               mink::DegenerateInputError);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  try {
    mink::akl_toussaint_filter(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}, {nan, 0}});
    ADD_FAILURE() << "no exception for a NaN";
  } catch (const mink::NonFiniteInputError& error) {
    EXPECT_EQ(error.index(), 3u);
  }
}

}  // namespace
