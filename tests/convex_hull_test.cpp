#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_points;
using mink_test::rotated_start;

const std::vector<Vec2> kSquare = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};

std::vector<Vec2> regular_polygon(int sides) {
  std::vector<Vec2> ring;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2 * std::numbers::pi * i / sides + 0.1;
    ring.push_back({std::cos(angle), std::sin(angle)});
  }
  return ring;
}

// Expects from_ccw_vertices to reject `ring` with DegenerateInputError mentioning `phrase`,
// and is_strictly_convex_ccw to agree.
void expect_rejected(const std::vector<Vec2>& ring, const std::string& phrase) {
  EXPECT_FALSE(mink::is_strictly_convex_ccw(ring)) << format_points(ring);
  try {
    mink::ConvexHull::from_ccw_vertices(ring);
    ADD_FAILURE() << "accepted " << format_points(ring);
  } catch (const mink::DegenerateInputError& error) {
    EXPECT_NE(std::string(error.what()).find(phrase), std::string::npos)
        << "message '" << error.what() << "' lacks '" << phrase << "'";
  }
}

TEST(ConvexHullFromVertices, AcceptsAValidRingStartingAnywhere) {
  for (const auto& ring : {kSquare, regular_polygon(3), regular_polygon(50)}) {
    const auto canonical = mink_test::canonical_ring(ring);
    for (std::size_t start = 0; start < ring.size(); ++start) {
      const auto shifted = rotated_start(ring, start);
      EXPECT_TRUE(mink::is_strictly_convex_ccw(shifted));
      const auto hull = mink::ConvexHull::from_ccw_vertices(shifted);
      EXPECT_TRUE(mink_test::same_ring(canonical, hull.vertices())) << "start " << start;
      EXPECT_EQ(hull.size(), ring.size());
      EXPECT_EQ(hull[0], canonical[0]);
    }
  }
}

TEST(ConvexHullFromVertices, EqualsTheBuiltHull) {
  std::vector<Vec2> points = kSquare;
  points.push_back({1, 1});
  points.push_back({1, 0});
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    EXPECT_EQ(mink::build_hull(points, algorithm),
              mink::ConvexHull::from_ccw_vertices(rotated_start(kSquare, 2)))
        << mink::to_string(algorithm);
  }
}

TEST(ConvexHullFromVertices, RejectsClockwise) {
  std::vector<Vec2> clockwise(kSquare.rbegin(), kSquare.rend());
  expect_rejected(clockwise, "counter-clockwise");
  std::vector<Vec2> triangle = {{0, 0}, {0, 1}, {1, 0}};
  expect_rejected(triangle, "counter-clockwise");
}

TEST(ConvexHullFromVertices, RejectsCollinearVertices) {
  expect_rejected({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, "counter-clockwise");
  expect_rejected({{0, 0}, {1, 1}, {2, 2}}, "counter-clockwise");
}

TEST(ConvexHullFromVertices, RejectsDuplicateVertices) {
  expect_rejected({{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}}, "counter-clockwise");
  expect_rejected({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}}, "counter-clockwise");
}

TEST(ConvexHullFromVertices, RejectsSelfWindingRings) {
  // A pentagram: the vertices of a regular pentagon in order 0, 2, 4, 1, 3 turn left at every
  // vertex but wind around twice.
  const auto pentagon = regular_polygon(5);
  expect_rejected({pentagon[0], pentagon[2], pentagon[4], pentagon[1], pentagon[3]}, "wind");
  // The square traversed twice.
  std::vector<Vec2> twice = kSquare;
  twice.insert(twice.end(), kSquare.begin(), kSquare.end());
  expect_rejected(twice, "wind");
  // A heptagram {7/3}.
  const auto heptagon = regular_polygon(7);
  std::vector<Vec2> heptagram;
  for (int i = 0; i < 7; ++i) heptagram.push_back(heptagon[(3 * i) % 7]);
  expect_rejected(heptagram, "wind");
}

TEST(ConvexHullFromVertices, RejectsTooFewVertices) {
  expect_rejected({}, "at least 3");
  expect_rejected({{0, 0}, {1, 0}}, "at least 3");
}

TEST(ConvexHullFromVertices, RejectsNonFiniteVertices) {
  std::vector<Vec2> ring = kSquare;
  ring[2].x() = std::numeric_limits<double>::infinity();
  try {
    mink::ConvexHull::from_ccw_vertices(ring);
    ADD_FAILURE() << "accepted an infinite vertex";
  } catch (const mink::NonFiniteInputError& error) {
    EXPECT_EQ(error.index(), 2u);
  }
}

}  // namespace
