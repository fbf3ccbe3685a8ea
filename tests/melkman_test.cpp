#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/melkman.hpp"
#include "mink/geometry/monotone_chain.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/geometry/point_sets.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_points;

std::vector<Vec2> sorted_copy(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), mink::lex_less);
  return points;
}

bool is_degenerate(const std::vector<Vec2>& points) {
  try {
    mink::validate_hull_input(points);
    return false;
  } catch (const mink::DegenerateInputError&) {
    return true;
  }
}

// What a hull of sorted points with no area is: the first point, and the last if it differs.
std::vector<Vec2> degenerate_ring(const std::vector<Vec2>& sorted) {
  if (sorted.front() == sorted.back()) return {sorted.front()};
  return {sorted.front(), sorted.back()};
}

// Sorts `points` first, so a case written out of order still tests a sorted chain.
void expect_matches_monotone_chain(const std::vector<Vec2>& points) {
  const std::vector<Vec2> sorted = sorted_copy(points);
  const std::vector<Vec2> ring = mink::melkman_sorted_chain_hull(sorted);
  if (is_degenerate(sorted)) {
    EXPECT_TRUE(mink_test::same_ring(degenerate_ring(sorted), ring)) << format_points(sorted);
  } else {
    EXPECT_TRUE(mink_test::same_ring(mink::monotone_chain_hull(sorted).vertices(), ring))
        << format_points(sorted);
  }
}

TEST(Melkman, RejectsUnsortedInput) {
  const std::vector<std::vector<Vec2>> unsorted = {
      {{1, 0}, {0, 0}, {2, 1}},
      {{0, 1}, {0, 0}, {1, 1}},  // equal x, y out of order
      {{0, 0}, {1, 0}, {2, 2}, {3, 0}, {2.5, 5}},
  };
  for (const auto& points : unsorted) {
    try {
      mink::melkman_sorted_chain_hull(points);
      ADD_FAILURE() << "no exception for " << format_points(points);
    } catch (const mink::InvalidArgumentError& error) {
      EXPECT_NE(std::string(error.what()).find("order"), std::string::npos) << error.what();
    }
  }
}

TEST(Melkman, DegenerateSortedInputs) {
  const Vec2 p(1.5, -2);
  EXPECT_TRUE(mink_test::same_ring(std::vector<Vec2>{p},
                                   mink::melkman_sorted_chain_hull(std::vector<Vec2>{p})));
  EXPECT_TRUE(mink_test::same_ring(std::vector<Vec2>{p},
                                   mink::melkman_sorted_chain_hull(std::vector<Vec2>(5, p))));
  const std::vector<std::vector<Vec2>> segments = {
      {{0, 0}, {1, 2}},
      {{0, 0}, {0, 0}, {1, 2}, {1, 2}},
      {{0, 0}, {1, 1}, {2, 2}, {3, 3}},
      {{-1, -1}, {0, 0}, {0, 0}, {1, 1}, {1, 1}, {5, 5}},
      {{2, -3}, {2, 0}, {2, 0}, {2, 7}},  // vertical
      {{-4, 1}, {0, 1}, {9, 1}},          // horizontal
      {{0x1p52 + 1, 3}, {0x1p52 + 2, 5}, {0x1p52 + 3, 7}},
  };
  for (const auto& sorted : segments) {
    EXPECT_TRUE(
        mink_test::same_ring(degenerate_ring(sorted), mink::melkman_sorted_chain_hull(sorted)))
        << format_points(sorted);
  }
}

TEST(Melkman, CollinearPrefixThenATurn) {
  // The first points are collinear; the hull appears only with the last one.
  expect_matches_monotone_chain({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 0}});
  expect_matches_monotone_chain({{0, 0}, {0, 1}, {0, 2}, {1, 0}});
  expect_matches_monotone_chain({{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {3, 1}, {3, 1}});
  // Collinear points at the end, on the top and bottom chains.
  expect_matches_monotone_chain({{0, 0}, {1, 1}, {1, -1}, {2, 2}, {2, -2}, {3, 3}, {3, -3}});
  expect_matches_monotone_chain({{0, 0}, {1, 5}, {2, 0}, {3, 0}, {4, 0}, {4, 0}});
}

TEST(Melkman, MatchesMonotoneChainOnSortedRandomSets) {
  for (mink::PointDistribution distribution : mink::all_point_distributions()) {
    SCOPED_TRACE(mink::to_string(distribution));
    for (std::size_t size : {1, 2, 3, 4, 5, 6, 8, 10, 20}) {
      for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        expect_matches_monotone_chain(mink::generate_points(distribution, size, seed));
      }
    }
    for (std::size_t size : {100, 1'000, 100'000}) {
      expect_matches_monotone_chain(mink::generate_points(distribution, size, 1));
    }
  }
}

TEST(Melkman, RingStartsAtTheFirstPointAndIsStrictlyConvex) {
  const auto sorted =
      sorted_copy(mink::generate_points(mink::PointDistribution::gaussian, 10'000, 5));
  const auto ring = mink::melkman_sorted_chain_hull(sorted);
  ASSERT_GE(ring.size(), 3u);
  EXPECT_EQ(ring.front(), sorted.front());
  EXPECT_TRUE(mink::is_strictly_convex_ccw(ring)) << format_points(ring);
}

}  // namespace
