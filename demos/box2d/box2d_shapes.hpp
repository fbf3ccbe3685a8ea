#pragma once

#include <span>

#include "mink/geometry/types.hpp"

namespace mink::interop {

// Box2D 2.4.1's contact manifold for one pair, both shapes given in world coordinates (identity
// transforms), coordinates rounded to float: how many points, and the smallest separation of
// b2WorldManifold (surface to surface, radii included; negative when penetrating).
struct Box2dContact {
  int point_count = 0;
  double min_separation = 0;
};

// The skin Box2D puts around polygons and edges (b2_polygonRadius): its polygons are our
// rounded polygons of this radius, its edges our capsules of it. The functions below take the
// skin to use (b2_polygonRadius, or 0 for sharp polygons and edges that are plain segments).
double box2d_skin();

// Vertex count Box2D keeps of `polygon` (b2PolygonShape::Set welds close points and takes the
// hull); a caller comparing shapes needs it equal to polygon.size(). Box2D asserts (aborts) when
// fewer than 3 vertices survive, so `polygon` must have vertices well apart.
int box2d_polygon_count(std::span<const Vec2> polygon);

// b2CollideCircles.
Box2dContact box2d_circles(const Vec2& center_a, double radius_a, const Vec2& center_b,
                           double radius_b);
// b2CollidePolygonAndCircle.
Box2dContact box2d_polygon_circle(std::span<const Vec2> polygon, double skin, const Vec2& center,
                                  double radius);
// b2CollideEdgeAndCircle, two-sided edge.
Box2dContact box2d_edge_circle(const Vec2& p1, const Vec2& p2, double skin, const Vec2& center,
                               double radius);
// b2CollideEdgeAndPolygon, two-sided edge.
Box2dContact box2d_edge_polygon(const Vec2& p1, const Vec2& p2, std::span<const Vec2> polygon,
                                double skin);

}  // namespace mink::interop
