#include "mink/narrowphase/minkowski_difference.hpp"

#include <gtest/gtest.h>

#include "mink/error.hpp"
#include "mink/geometry/orientation.hpp"
#include "narrowphase_test_support.hpp"

namespace {

using namespace mink_test;

std::vector<Vec2> all_differences(std::span<const Vec2> a, std::span<const Vec2> b) {
  std::vector<Vec2> out;
  for (const Vec2& p : a) {
    for (const Vec2& q : b) out.push_back(p - q);
  }
  return out;
}

// Integer coordinates keep every difference exact, so the merge must equal the hull of all
// n * m differences vertex for vertex.
TEST(MinkowskiDifference, EqualsTheHullOfAllDifferencesOnIntegerPolygons) {
  std::mt19937_64 rng(61);
  std::uniform_int_distribution<int> coordinate(-40, 40);
  for (int k = 0; k < 500; ++k) {
    std::vector<Vec2> pa, pb;
    for (int i = 0; i < 12; ++i) pa.push_back(Vec2(coordinate(rng), coordinate(rng)));
    for (int i = 0; i < 5 + k % 20; ++i) pb.push_back(Vec2(coordinate(rng), coordinate(rng)));
    const auto a = mink::build_hull(pa, mink::HullAlgorithm::graham);
    const auto b = mink::build_hull(pb, mink::HullAlgorithm::graham);
    const auto merged = mink::minkowski_difference(a.vertices(), b.vertices());
    const auto expected =
        mink::build_hull(all_differences(a.vertices(), b.vertices()), mink::HullAlgorithm::graham);
    ASSERT_EQ(mink::ConvexHull::from_ccw_vertices(merged), expected) << "pair " << k;
  }
}

TEST(MinkowskiDifference, FloatingPolygonsStayOnTheExactHull) {
  std::mt19937_64 rng(62);
  for (int k = 0; k < 200; ++k) {
    const PreparedHull a = random_hull(rng, 3 + k % 30);
    const PreparedHull b = random_hull(rng, 3 + k % 7);
    const Pose pa = random_pose(rng, 2);
    const Pose pb = random_pose(rng, 2);
    const auto merged = mink::minkowski_difference(a, pa, b, pb);
    const auto expected = mink::build_hull(
        all_differences(world_vertices(a, pa), world_vertices(b, pb)), mink::HullAlgorithm::graham);
    // Every vertex of the exact hull appears, and the rest lie on its boundary.
    for (const Vec2& v : expected.vertices()) {
      EXPECT_NE(std::find(merged.begin(), merged.end(), v), merged.end());
    }
    EXPECT_LE(merged.size(), a.size() + b.size());
    const auto ev = expected.vertices();
    for (const Vec2& v : merged) {
      Real nearest = 1e300;
      for (std::size_t i = 0; i < ev.size(); ++i) {
        nearest = std::min(nearest, point_segment_distance(v, ev[i], ev[(i + 1) % ev.size()]));
      }
      EXPECT_LT(nearest, 1e-12);
    }
  }
}

TEST(MinkowskiDifference, RejectsDegenerateInput) {
  const std::vector<Vec2> segment = {Vec2(0, 0), Vec2(1, 0)};
  const std::vector<Vec2> triangle = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  EXPECT_THROW(mink::minkowski_difference(segment, triangle), mink::InvalidArgumentError);
}

}  // namespace
