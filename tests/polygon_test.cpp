#include <CGAL/Polygon_2.h>
#include <CGAL/centroid.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/geometry/polygon.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_points;
using mink_test::Kernel;
using mink_test::rotated_start;

std::vector<Vec2> regular_polygon(int sides, double radius, const Vec2& centre) {
  std::vector<Vec2> vertices;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2 * std::numbers::pi * i / sides;
    vertices.push_back(centre + radius * Vec2(std::cos(angle), std::sin(angle)));
  }
  return vertices;
}

// Closed forms for a regular polygon of circumradius R: n triangles of apex angle 2 pi / n.
double regular_polygon_area(int sides, double radius) {
  return sides * radius * radius * std::sin(2 * std::numbers::pi / sides) / 2;
}
double regular_polygon_polar_moment(int sides, double radius) {
  const double angle = 2 * std::numbers::pi / sides;
  return sides * std::pow(radius, 4) * std::sin(angle) * (2 + std::cos(angle)) / 12;
}

double cgal_area(const std::vector<Vec2>& polygon) {
  CGAL::Polygon_2<Kernel> cgal_polygon;
  for (const Vec2& v : polygon) cgal_polygon.push_back(mink_test::to_cgal(v));
  return cgal_polygon.area();
}

// Area centroid of a convex polygon by CGAL, from a fan of triangles.
Vec2 cgal_convex_centroid(const std::vector<Vec2>& polygon) {
  std::vector<Kernel::Triangle_2> fan;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    fan.emplace_back(mink_test::to_cgal(polygon[0]), mink_test::to_cgal(polygon[i]),
                     mink_test::to_cgal(polygon[i + 1]));
  }
  return mink_test::from_cgal(
      CGAL::centroid(fan.begin(), fan.end(), Kernel(), CGAL::Dimension_tag<2>()));
}

TEST(Polygon, UnitSquare) {
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const mink::AreaProperties properties = mink::area_properties(square);
  EXPECT_EQ(properties.area, 1.0);
  EXPECT_EQ(properties.centroid, Vec2(0.5, 0.5));
  EXPECT_NEAR(properties.polar_moment, 1.0 / 6, 1e-15);  // (1 + 1) / 12
  EXPECT_EQ(mink::signed_area(square), 1.0);
  EXPECT_EQ(mink::centroid(square), Vec2(0.5, 0.5));
}

TEST(Polygon, ClockwiseOrderGivesNegativeAreaAndTheSameCentroid) {
  const std::vector<Vec2> square = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  const mink::AreaProperties properties = mink::area_properties(square);
  EXPECT_EQ(properties.area, -1.0);
  EXPECT_EQ(properties.centroid, Vec2(0.5, 0.5));
  EXPECT_EQ(mink::signed_area(square), -1.0);
}

TEST(Polygon, Rectangle) {
  // 4 x 2 with its lower-left corner at (1, -3): J = A (w^2 + h^2) / 12.
  const std::vector<Vec2> rectangle = {{1, -3}, {5, -3}, {5, -1}, {1, -1}};
  const mink::AreaProperties properties = mink::area_properties(rectangle);
  EXPECT_EQ(properties.area, 8.0);
  EXPECT_DOUBLE_EQ(properties.centroid.x(), 3.0);
  EXPECT_DOUBLE_EQ(properties.centroid.y(), -2.0);
  EXPECT_NEAR(properties.polar_moment, 8.0 * (16 + 4) / 12, 1e-12);
}

TEST(Polygon, RightTriangle) {
  // Legs 3 along x and 4 along y: centroid at a third of each leg, J = A (a^2 + b^2) / 18.
  const std::vector<Vec2> triangle = {{0, 0}, {3, 0}, {0, 4}};
  const mink::AreaProperties properties = mink::area_properties(triangle);
  EXPECT_EQ(properties.area, 6.0);
  EXPECT_DOUBLE_EQ(properties.centroid.x(), 1.0);
  EXPECT_DOUBLE_EQ(properties.centroid.y(), 4.0 / 3);
  EXPECT_NEAR(properties.polar_moment, 6.0 * (9 + 16) / 18, 1e-12);
}

TEST(Polygon, NonConvexLShape) {
  // Three unit squares; centroid (5/6, 5/6); J = 3 * (1/6) + parallel-axis terms 2/9 + 5/9 + 5/9.
  const std::vector<Vec2> shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const mink::AreaProperties properties = mink::area_properties(shape);
  EXPECT_EQ(properties.area, 3.0);
  EXPECT_NEAR(properties.centroid.x(), 5.0 / 6, 1e-15);
  EXPECT_NEAR(properties.centroid.y(), 5.0 / 6, 1e-15);
  EXPECT_NEAR(properties.polar_moment, 11.0 / 6, 1e-14);
  EXPECT_EQ(cgal_area(shape), 3.0);
}

TEST(Polygon, RegularPolygonsMatchClosedFormsAndCgal) {
  const Vec2 centre(0.3, -0.7);
  const double radius = 2.5;
  for (int sides : {3, 4, 5, 8, 64, 1000}) {
    SCOPED_TRACE(testing::Message() << sides << " sides");
    const auto polygon = regular_polygon(sides, radius, centre);
    const mink::AreaProperties properties = mink::area_properties(polygon);
    const double area = regular_polygon_area(sides, radius);
    EXPECT_NEAR(properties.area, area, 1e-13 * area);
    EXPECT_NEAR(properties.area, cgal_area(polygon), 1e-13 * area);
    EXPECT_NEAR(mink::signed_area(polygon), area, 1e-13 * area);
    EXPECT_NEAR(properties.centroid.x(), centre.x(), 1e-13);
    EXPECT_NEAR(properties.centroid.y(), centre.y(), 1e-13);
    const Vec2 reference_centroid = cgal_convex_centroid(polygon);
    EXPECT_NEAR(properties.centroid.x(), reference_centroid.x(), 1e-13);
    EXPECT_NEAR(properties.centroid.y(), reference_centroid.y(), 1e-13);
    const double moment = regular_polygon_polar_moment(sides, radius);
    EXPECT_NEAR(properties.polar_moment, moment, 1e-12 * moment);
  }
}

TEST(Polygon, StartingVertexDoesNotMatter) {
  const auto polygon = regular_polygon(7, 3.0, Vec2(-2, 5));
  const mink::AreaProperties reference = mink::area_properties(polygon);
  for (std::size_t start = 1; start < polygon.size(); ++start) {
    const mink::AreaProperties properties = mink::area_properties(rotated_start(polygon, start));
    EXPECT_NEAR(properties.area, reference.area, 1e-13 * reference.area);
    EXPECT_NEAR((properties.centroid - reference.centroid).norm(), 0, 1e-13);
    EXPECT_NEAR(properties.polar_moment, reference.polar_moment, 1e-12 * reference.polar_moment);
  }
}

TEST(Polygon, RandomConvexPolygonsMatchCgal) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto points = mink::generate_points(mink::PointDistribution::gaussian, 200, seed);
    const auto polygon = mink_test::reference_hull(points);
    SCOPED_TRACE(format_points(polygon));
    const mink::AreaProperties properties = mink::area_properties(polygon);
    const double area = cgal_area(polygon);
    EXPECT_NEAR(properties.area, area, 1e-13 * area);
    const Vec2 reference_centroid = cgal_convex_centroid(polygon);
    EXPECT_NEAR((properties.centroid - reference_centroid).norm(), 0, 1e-13);
  }
}

TEST(Polygon, UnitSquareFarFromOriginKeepsFullPrecision) {
  // The translation is exact, and so are the differences from the first vertex.
  const Vec2 offset(1e9, -3e9);
  const std::vector<Vec2> square = {offset + Vec2(0, 0), offset + Vec2(1, 0), offset + Vec2(1, 1),
                                    offset + Vec2(0, 1)};
  const mink::AreaProperties properties = mink::area_properties(square);
  EXPECT_EQ(properties.area, 1.0);
  EXPECT_EQ(properties.centroid, offset + Vec2(0.5, 0.5));
  EXPECT_NEAR(properties.polar_moment, 1.0 / 6, 1e-15);
  EXPECT_EQ(mink::signed_area(square), 1.0);
}

TEST(Polygon, RegularPolygonFarFromOriginMatchesTheOneAtTheOrigin) {
  // Vertices at 1e9 are rounded to ~1e-7, a relative change of ~1e-10 for radius 1000; a
  // shoelace sum about the origin would lose everything to terms of size 1e18.
  const int sides = 12;
  const double radius = 1000;
  const Vec2 offset(1e9, -3e9);
  const auto far = regular_polygon(sides, radius, offset);
  const mink::AreaProperties properties = mink::area_properties(far);
  const double area = regular_polygon_area(sides, radius);
  EXPECT_NEAR(properties.area, area, 1e-9 * area);
  EXPECT_NEAR(mink::signed_area(far), area, 1e-9 * area);
  EXPECT_NEAR(properties.centroid.x(), offset.x(), 1e-5);
  EXPECT_NEAR(properties.centroid.y(), offset.y(), 1e-5);
  const double moment = regular_polygon_polar_moment(sides, radius);
  EXPECT_NEAR(properties.polar_moment, moment, 1e-8 * moment);
}

TEST(Polygon, FewerThanThreeVerticesThrow) {
  const std::vector<Vec2> two = {{0, 0}, {1, 1}};
  EXPECT_THROW(mink::area_properties(std::vector<Vec2>{}), mink::DegenerateInputError);
  EXPECT_THROW(mink::area_properties(std::vector<Vec2>{{1, 2}}), mink::DegenerateInputError);
  EXPECT_THROW(mink::area_properties(two), mink::DegenerateInputError);
  EXPECT_THROW(mink::centroid(two), mink::DegenerateInputError);
  EXPECT_EQ(mink::signed_area(two), 0.0);
  try {
    mink::area_properties(two);
  } catch (const mink::DegenerateInputError& error) {
    EXPECT_NE(std::string(error.what()).find("at least 3 vertices"), std::string::npos)
        << error.what();
  }
}

TEST(Polygon, ZeroAreaPolygonsThrow) {
  const std::vector<std::vector<Vec2>> degenerate = {
      {{0, 0}, {1, 1}, {2, 2}},         {{0, 0}, {2, 2}, {1, 1}, {3, 3}},
      {{5, 5}, {5, 5}, {5, 5}, {5, 5}}, {{0, -1}, {0, 7}, {0, 3}},
      {{0, 0}, {1, 0}, {1, 0}, {0, 0}}, {{0x1p52 + 1, 3}, {0x1p52 + 3, 7}, {0x1p52 + 2, 5}},
  };
  for (const auto& polygon : degenerate) {
    EXPECT_THROW(mink::area_properties(polygon), mink::DegenerateInputError)
        << format_points(polygon);
    EXPECT_THROW(mink::centroid(polygon), mink::DegenerateInputError) << format_points(polygon);
    EXPECT_EQ(mink::signed_area(polygon), 0.0) << format_points(polygon);
  }
}

TEST(Polygon, ExactlyCollinearPolygonWithInexactDifferencesThrows) {
  // p, 2p and 4p lie exactly on the line through the origin and p (doubling is exact), so the
  // area is exactly zero; but 4p - p is rounded, so a shoelace sum about the first vertex
  // comes out as about 1e-16 for this p.
  const Vec2 p(-0.7312715117751976, 0.6948674738744653);
  const std::vector<Vec2> polygon = {p, 2 * p, 4 * p};
  ASSERT_EQ(mink::orient2d(polygon[0], polygon[1], polygon[2]), 0);
  EXPECT_THROW(mink::area_properties(polygon), mink::DegenerateInputError)
      << format_points(polygon);
}

}  // namespace
