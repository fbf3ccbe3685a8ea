// The hull traces drawn in the paper's figures 9 and 10 agree with the hulls the algorithms
// build.

#include "mink/geometry/hull_trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mink/error.hpp"
#include "mink/geometry/chan.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/graham.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/geometry/point_sets.hpp"

namespace {

using mink::Vec2;

// Position of `v` in `ring`, or ring.size() when absent.
std::size_t find(std::span<const Vec2> ring, const Vec2& v) {
  return static_cast<std::size_t>(std::find(ring.begin(), ring.end(), v) - ring.begin());
}

std::vector<Vec2> ring(const mink::ConvexHull& hull) {
  return {hull.vertices().begin(), hull.vertices().end()};
}

// True when a -> b is an edge of the CCW hull.
bool is_edge(const mink::ConvexHull& hull, const Vec2& a, const Vec2& b) {
  const std::size_t i = find(hull.vertices(), a);
  return i < hull.size() && hull[(i + 1) % hull.size()] == b;
}

TEST(ChanGroups, PartitionPointsInOrderAndHullEachGroup) {
  const auto points = mink::generate_points(mink::PointDistribution::uniform_square, 103, 5);
  const mink::ChanGroups groups = mink::chan_groups(points, 16);
  ASSERT_EQ(groups.points.size(), 7u);
  ASSERT_EQ(groups.hulls.size(), 7u);
  std::vector<Vec2> joined;
  for (const auto& group : groups.points) joined.insert(joined.end(), group.begin(), group.end());
  EXPECT_EQ(joined, points);
  EXPECT_EQ(groups.points.back().size(), 103u - 6 * 16);
  for (std::size_t g = 0; g < groups.points.size(); ++g) {
    EXPECT_EQ(groups.hulls[g], ring(mink::graham_hull(groups.points[g])));
  }
  EXPECT_THROW(mink::chan_groups(points, 0), mink::InvalidArgumentError);
}

TEST(ChanTrace, RoundsGrowAsThePaperSaysAndTheLastOneCloses) {
  for (std::uint64_t seed : {2013u, 1u, 2u, 3u}) {
    const auto [first, second] = mink::paper_point_sets(seed);
    const mink::ChanTrace trace = mink::chan_trace(first);
    EXPECT_EQ(trace.hull, mink::chan_hull(first));
    ASSERT_FALSE(trace.rounds.empty());
    for (std::size_t r = 0; r < trace.rounds.size(); ++r) {
      const mink::ChanRound& round = trace.rounds[r];
      EXPECT_EQ(round.t, r + 1);
      EXPECT_EQ(round.closed, r + 1 == trace.rounds.size());
      // Every hull vertex survives every round: it is a vertex of its group's hull.
      std::vector<Vec2> survivors;
      for (const auto& ring : round.groups.hulls) {
        survivors.insert(survivors.end(), ring.begin(), ring.end());
      }
      for (const Vec2& v : trace.hull.vertices()) EXPECT_LT(find(survivors, v), survivors.size());
      if (!round.closed) {
        EXPECT_GT(trace.hull.size(), round.groups.group_size);
      }
    }
    const mink::ChanRound& last = trace.rounds.back();
    EXPECT_TRUE(last.groups.hulls.size() == 1 || trace.hull.size() <= last.groups.group_size);
  }
}

TEST(DivideConquerTrace, HalvesAndTangentsAreThoseOfTheMerge) {
  for (std::uint64_t seed : {2013u, 7u, 8u, 9u, 10u}) {
    const auto [first, second] = mink::paper_point_sets(seed);
    const mink::DivideConquerTrace trace = mink::divide_conquer_trace(second);
    EXPECT_EQ(trace.hull, mink::divide_conquer_hull(second));
    // The halves split the sorted points: every left point precedes every right point.
    ASSERT_FALSE(trace.left_points.empty());
    ASSERT_FALSE(trace.right_points.empty());
    EXPECT_TRUE(mink::lex_less(trace.left_points.back(), trace.right_points.front()));
    EXPECT_LE(trace.left_points.size(), trace.right_points.size());
    EXPECT_EQ(trace.left_points.size() + trace.right_points.size(), second.size());
    // Melkman's rings may start anywhere: compare them in canonical form.
    EXPECT_EQ(mink::ConvexHull::from_ccw_vertices(trace.left_hull),
              mink::graham_hull(trace.left_points));
    EXPECT_EQ(mink::ConvexHull::from_ccw_vertices(trace.right_hull),
              mink::graham_hull(trace.right_points));
    // The tangents are the two hull edges that cross from one half to the other.
    const Vec2& upper_left = trace.left_hull[trace.upper_left];
    const Vec2& upper_right = trace.right_hull[trace.upper_right];
    const Vec2& lower_left = trace.left_hull[trace.lower_left];
    const Vec2& lower_right = trace.right_hull[trace.lower_right];
    EXPECT_TRUE(is_edge(trace.hull, upper_right, upper_left)) << "seed " << seed;
    EXPECT_TRUE(is_edge(trace.hull, lower_left, lower_right)) << "seed " << seed;
    int crossing = 0;
    for (std::size_t i = 0; i < trace.hull.size(); ++i) {
      const bool here = find(trace.left_hull, trace.hull[i]) < trace.left_hull.size();
      const bool next =
          find(trace.left_hull, trace.hull[(i + 1) % trace.hull.size()]) < trace.left_hull.size();
      crossing += here != next;
    }
    EXPECT_EQ(crossing, 2);
    EXPECT_GT(upper_left.y() + upper_right.y(), lower_left.y() + lower_right.y());
  }
}

TEST(CommonTangents, BruteForceFindsTheSupportingPairs) {
  // Two unit squares side by side, the right one raised: the upper tangent runs from the
  // right square's top-left corner to the left square's top-left corner, the lower one from
  // the left square's bottom-right corner to the right square's bottom-right corner.
  const std::vector<Vec2> left = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Vec2> right = {{3, 1}, {4, 1}, {4, 2}, {3, 2}};
  const auto pairs = mink::detail::common_tangents_brute_force(left, right);
  EXPECT_EQ(left[pairs.upper_left], Vec2(0, 1));
  EXPECT_EQ(right[pairs.upper_right], Vec2(3, 2));
  EXPECT_EQ(left[pairs.lower_left], Vec2(1, 0));
  EXPECT_EQ(right[pairs.lower_right], Vec2(4, 1));
}

}  // namespace
