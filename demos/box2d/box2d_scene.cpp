#include "box2d_scene.hpp"

#include <box2d/box2d.h>

#include <string>
#include <variant>
#include <vector>

#include "box2d_distance.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/error.hpp"

namespace mink::interop {

Box2dScene build_box2d_world(const SceneDef& scene) {
  // Every hull first, so a refused scene makes no Box2D world at all.
  std::vector<std::vector<ConvexHull>> hulls(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const SceneBody& body = scene.bodies[i];
    for (std::size_t k = 0; k < body.shapes.size(); ++k) {
      hulls[i].push_back(make_shape_hull(body.shapes[k]));
      if (hulls[i].back().size() > b2_maxPolygonVertices) {
        throw InvalidArgumentError(
            "body " + std::to_string(i) + " (" + std::string(to_string(body.body.type)) + ", at " +
            std::to_string(body.body.position.x()) + ", " + std::to_string(body.body.position.y()) +
            ") shape " + std::to_string(k) + " has " + std::to_string(hulls[i].back().size()) +
            " hull vertices; a Box2D polygon holds at most " +
            std::to_string(b2_maxPolygonVertices) + " and hulls are never truncated");
      }
    }
  }
  // Joints: only what the comparison's scenes need (tumbler_400's motor) is translated.
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const auto* revolute = std::get_if<RevoluteJointDef>(&scene.joints[i].def);
    if (revolute == nullptr || revolute->spring.enabled) {
      throw InvalidArgumentError("joint " + std::to_string(i) + " is a " +
                                 std::string(to_string(joint_type(scene.joints[i].def))) +
                                 (revolute != nullptr ? " joint with a spring" : " joint") +
                                 "; the Box2D scene takes revolute joints without springs only");
    }
  }
  Box2dScene result;
  result.world = std::make_unique<b2World>(b2Vec2(static_cast<float>(scene.world.gravity.x()),
                                                  static_cast<float>(scene.world.gravity.y())));
  result.world->SetAllowSleeping(scene.world.enable_sleep);
  float top_y = -1e30f;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const SceneBody& body = scene.bodies[i];
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
    result.bodies.push_back(b);
    for (std::size_t k = 0; k < body.shapes.size(); ++k) {
      const ShapeDef& shape = body.shapes[k];
      const ConvexHull& hull = hulls[i][k];
      const std::vector<b2Vec2> vertices = to_float(hull.vertices());
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
  for (const SceneJoint& joint : scene.joints) {
    const auto& revolute = std::get<RevoluteJointDef>(joint.def);
    b2RevoluteJointDef def;
    def.bodyA = result.bodies.at(joint.body_a);
    def.bodyB = result.bodies.at(joint.body_b);
    def.collideConnected = revolute.collide_connected;
    def.localAnchorA = to_float(revolute.local_anchor_a);
    def.localAnchorB = to_float(revolute.local_anchor_b);
    def.referenceAngle = static_cast<float>(revolute.reference_angle);
    def.enableLimit = revolute.limit.enabled;
    def.lowerAngle = static_cast<float>(revolute.limit.lower);
    def.upperAngle = static_cast<float>(revolute.limit.upper);
    def.enableMotor = revolute.motor.enabled;
    def.motorSpeed = static_cast<float>(revolute.motor.speed);
    def.maxMotorTorque = static_cast<float>(revolute.motor.max_force);
    result.world->CreateJoint(&def);
  }
  return result;
}

}  // namespace mink::interop
