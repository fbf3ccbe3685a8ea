#include "box2d_scene.hpp"

#include <box2d/box2d.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "mink/engine/shape_def.hpp"

namespace mink::bench {

Box2dScene build_box2d_world(const SceneDef& scene) {
  Box2dScene result;
  result.world = std::make_unique<b2World>(b2Vec2(static_cast<float>(scene.world.gravity.x()),
                                                  static_cast<float>(scene.world.gravity.y())));
  result.world->SetAllowSleeping(scene.world.enable_sleep);
  float top_y = -1e30f;
  for (const SceneBody& body : scene.bodies) {
    b2BodyDef def;
    def.type = body.body.type == BodyType::dynamic     ? b2_dynamicBody
               : body.body.type == BodyType::kinematic ? b2_kinematicBody
                                                       : b2_staticBody;
    def.position.Set(static_cast<float>(body.body.position.x()),
                     static_cast<float>(body.body.position.y()));
    def.angle = static_cast<float>(body.body.angle);
    def.linearVelocity.Set(static_cast<float>(body.body.linear_velocity.x()),
                           static_cast<float>(body.body.linear_velocity.y()));
    def.angularVelocity = static_cast<float>(body.body.angular_velocity);
    def.linearDamping = static_cast<float>(body.body.linear_damping);
    def.angularDamping = static_cast<float>(body.body.angular_damping);
    def.gravityScale = static_cast<float>(body.body.gravity_scale);
    def.allowSleep = body.body.allow_sleep;
    b2Body* b = result.world->CreateBody(&def);
    for (const ShapeDef& shape : body.shapes) {
      const ConvexHull hull = make_shape_hull(shape);
      if (hull.size() > b2_maxPolygonVertices) {
        throw std::invalid_argument("Box2D polygons have at most " +
                                    std::to_string(b2_maxPolygonVertices) + " vertices, got " +
                                    std::to_string(hull.size()));
      }
      std::vector<b2Vec2> vertices;
      for (const Vec2& v : hull.vertices()) {
        vertices.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()));
      }
      b2PolygonShape polygon;
      polygon.Set(vertices.data(), static_cast<int32>(vertices.size()));
      b2FixtureDef fixture;
      fixture.shape = &polygon;
      fixture.density = static_cast<float>(shape.density);
      fixture.friction = static_cast<float>(shape.friction);
      fixture.restitution = static_cast<float>(shape.restitution);
      b->CreateFixture(&fixture);
    }
    if (def.type == b2_dynamicBody && def.position.y > top_y) {
      top_y = def.position.y;
      result.top = b;
    }
  }
  return result;
}

}  // namespace mink::bench
