#include "box2d_shapes.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <vector>

#include "box2d_distance.hpp"

namespace mink::interop {

namespace {

b2CircleShape circle(const Vec2& center, double radius) {
  b2CircleShape c;
  c.m_p = to_float(center);
  c.m_radius = static_cast<float>(radius);
  return c;
}

b2PolygonShape polygon_shape(std::span<const Vec2> polygon, double skin = b2_polygonRadius) {
  const std::vector<b2Vec2> v = to_float(polygon);
  b2PolygonShape p;
  p.Set(v.data(), static_cast<int32>(v.size()));
  p.m_radius = static_cast<float>(skin);
  return p;
}

b2EdgeShape edge(const Vec2& p1, const Vec2& p2, double skin) {
  b2EdgeShape e;
  e.SetTwoSided(to_float(p1), to_float(p2));
  e.m_radius = static_cast<float>(skin);
  return e;
}

// The world separations of the manifold (identity transforms).
Box2dContact read(const b2Manifold& m, float radius_a, float radius_b) {
  Box2dContact c;
  c.point_count = m.pointCount;
  if (m.pointCount == 0) return c;
  b2Transform identity;
  identity.SetIdentity();
  b2WorldManifold world;
  world.Initialize(&m, identity, radius_a, identity, radius_b);
  c.min_separation = world.separations[0];
  for (int i = 1; i < m.pointCount; ++i)
    c.min_separation = std::min<double>(c.min_separation, world.separations[i]);
  return c;
}

b2Transform identity_transform() {
  b2Transform t;
  t.SetIdentity();
  return t;
}

}  // namespace

double box2d_skin() {
  return b2_polygonRadius;
}

int box2d_polygon_count(std::span<const Vec2> polygon) {
  return polygon_shape(polygon).m_count;
}

Box2dContact box2d_circles(const Vec2& center_a, double radius_a, const Vec2& center_b,
                           double radius_b) {
  const b2CircleShape a = circle(center_a, radius_a);
  const b2CircleShape b = circle(center_b, radius_b);
  b2Manifold m;
  b2CollideCircles(&m, &a, identity_transform(), &b, identity_transform());
  return read(m, a.m_radius, b.m_radius);
}

Box2dContact box2d_polygon_circle(std::span<const Vec2> polygon, double skin, const Vec2& center,
                                  double radius) {
  const b2PolygonShape a = polygon_shape(polygon, skin);
  const b2CircleShape b = circle(center, radius);
  b2Manifold m;
  b2CollidePolygonAndCircle(&m, &a, identity_transform(), &b, identity_transform());
  return read(m, a.m_radius, b.m_radius);
}

Box2dContact box2d_edge_circle(const Vec2& p1, const Vec2& p2, double skin, const Vec2& center,
                               double radius) {
  const b2EdgeShape a = edge(p1, p2, skin);
  const b2CircleShape b = circle(center, radius);
  b2Manifold m;
  b2CollideEdgeAndCircle(&m, &a, identity_transform(), &b, identity_transform());
  return read(m, a.m_radius, b.m_radius);
}

Box2dContact box2d_edge_polygon(const Vec2& p1, const Vec2& p2, std::span<const Vec2> polygon,
                                double skin) {
  const b2EdgeShape a = edge(p1, p2, skin);
  const b2PolygonShape b = polygon_shape(polygon, skin);
  b2Manifold m;
  b2CollideEdgeAndPolygon(&m, &a, identity_transform(), &b, identity_transform());
  return read(m, a.m_radius, b.m_radius);
}

}  // namespace mink::interop
