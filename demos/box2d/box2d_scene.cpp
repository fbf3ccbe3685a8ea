#include "box2d_scene.hpp"

#include <box2d/box2d.h>

#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "box2d_distance.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/error.hpp"

namespace mink::interop {

namespace {

// Thin enough to stay within a few millimetres of the capsule, thick enough that
// b2PolygonShape::Set does not weld the rectangle's corners (it welds within half a slop).
constexpr double kCapsuleCoreHalfThickness = b2_linearSlop;

std::string body_name(const SceneDef& scene, std::size_t i) {
  const BodyDef& body = scene.bodies[i].body;
  return "body " + std::to_string(i) + " (" + std::string(to_string(body.type)) + ", at " +
         std::to_string(body.position.x()) + ", " + std::to_string(body.position.y()) + ")";
}

// What 2.4.1 cannot hold of one shape, or an empty string.
std::string shape_refusal(const ShapeDef& shape, const ConvexHull* hull) {
  if (hull != nullptr && hull->size() > b2_maxPolygonVertices) {
    return "has " + std::to_string(hull->size()) +
           " hull vertices; a Box2D polygon holds at most " +
           std::to_string(b2_maxPolygonVertices) + " and hulls are never truncated";
  }
  if (shape.type == ShapeType::capsule && shape.radius <= kCapsuleCoreHalfThickness) {
    return "is a capsule of radius " + std::to_string(shape.radius) +
           "; Box2D 2.4.1 has no capsule, and its rounded-polygon stand-in needs a radius above " +
           std::to_string(kCapsuleCoreHalfThickness) + " m";
  }
  // Box2D's filter is 16 bits wide; masks need only the bits some category uses.
  if (shape.filter.category > 0xFFFF) {
    return "has filter categories beyond the 16 bits of Box2D 2.4.1's b2Filter";
  }
  if (shape.filter.group < std::numeric_limits<std::int16_t>::min() ||
      shape.filter.group > std::numeric_limits<std::int16_t>::max()) {
    return "has filter group " + std::to_string(shape.filter.group) +
           ", outside Box2D 2.4.1's 16-bit groupIndex";
  }
  return {};
}

// What 2.4.1 cannot do of one joint, or an empty string.
std::string joint_refusal(const JointDef& def) {
  return std::visit(
      [](const auto& d) -> std::string {
        using Def = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<Def, RevoluteJointDef> ||
                      std::is_same_v<Def, PrismaticJointDef>) {
          if (d.spring.enabled) return "has a spring; Box2D 2.4.1's has none";
        } else if constexpr (std::is_same_v<Def, DistanceJointDef>) {
          if (d.motor.enabled) return "has a motor; Box2D 2.4.1's has none";
          if (d.spring.enabled && d.spring.hertz <= 0) {
            return "has a spring of 0 hertz; Box2D 2.4.1's springs need a stiffness";
          }
        } else if constexpr (std::is_same_v<Def, WheelJointDef>) {
          if (d.spring.enabled && d.spring.hertz <= 0) {
            return "has a spring of 0 hertz; Box2D 2.4.1's springs need a stiffness";
          }
          if (d.spring.enabled && d.spring.target != 0) {
            return "has a spring target of " + std::to_string(d.spring.target) +
                   "; Box2D 2.4.1's wheel spring rests at 0";
          }
        } else if constexpr (std::is_same_v<Def, WeldJointDef>) {
          if (d.linear_hertz > 0) return "has a linear spring; Box2D 2.4.1's weld has none";
        }
        return {};
      },
      def);
}

void check_translatable(const SceneDef& scene, std::vector<std::vector<ConvexHull>>& hulls) {
  hulls.resize(scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const std::vector<ShapeDef>& shapes = scene.bodies[i].shapes;
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      if (shapes[k].type == ShapeType::polygon) hulls[i].push_back(make_shape_hull(shapes[k]));
      const ConvexHull* hull = shapes[k].type == ShapeType::polygon ? &hulls[i].back() : nullptr;
      const std::string refusal = shape_refusal(shapes[k], hull);
      if (!refusal.empty()) {
        throw InvalidArgumentError(body_name(scene, i) + " shape " + std::to_string(k) + " " +
                                   refusal);
      }
    }
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const std::string refusal = joint_refusal(scene.joints[i].def);
    if (!refusal.empty()) {
      throw InvalidArgumentError("joints[" + std::to_string(i) + "] is a " +
                                 std::string(to_string(joint_type(scene.joints[i].def))) +
                                 " joint that " + refusal +
                                 " (the comparison translates only what Box2D 2.4.1 can hold)");
    }
  }
}

b2PolygonShape capsule_polygon(const ShapeDef& capsule) {
  const Vec2 c1 = capsule.points[0], c2 = capsule.points[1];
  const Vec2 along = (c2 - c1).normalized();
  const Vec2 across = kCapsuleCoreHalfThickness * Vec2(-along.y(), along.x());
  // Lengthened by the half-thickness too, so that the ends are never short of the capsule's.
  const Vec2 out = kCapsuleCoreHalfThickness * along;
  const Vec2 corners[] = {c1 - out - across, c2 + out - across, c2 + out + across,
                          c1 - out + across};
  const std::vector<b2Vec2> vertices = to_float(corners);
  b2PolygonShape polygon;
  polygon.Set(vertices.data(), static_cast<int32>(vertices.size()));
  polygon.m_radius = static_cast<float>(capsule.radius - kCapsuleCoreHalfThickness);
  return polygon;
}

// An open chain's end ghost: a right angle towards the chain's back (the left of its end
// segment, running along the chain), as our chains have.
b2Vec2 end_ghost(const Vec2& end, const Vec2& segment) {
  return to_float(end + Vec2(-segment.y(), segment.x()));
}

void add_fixture(b2Body& body, const ShapeDef& shape, const ConvexHull* hull) {
  b2FixtureDef fixture;
  fixture.density = static_cast<float>(shape.density);
  fixture.friction = static_cast<float>(shape.friction);
  fixture.restitution = static_cast<float>(shape.restitution);
  fixture.isSensor = shape.is_sensor;
  fixture.filter.categoryBits = static_cast<uint16>(shape.filter.category);
  fixture.filter.maskBits = static_cast<uint16>(shape.filter.mask & 0xFFFF);
  fixture.filter.groupIndex = static_cast<int16>(shape.filter.group);
  b2PolygonShape polygon;
  b2CircleShape circle;
  b2EdgeShape edge;
  b2ChainShape chain;
  switch (shape.type) {
    case ShapeType::polygon: {
      const std::vector<b2Vec2> vertices = to_float(hull->vertices());
      polygon.Set(vertices.data(), static_cast<int32>(vertices.size()));
      if (shape.radius > 0) polygon.m_radius = static_cast<float>(shape.radius);
      fixture.shape = &polygon;
      break;
    }
    case ShapeType::circle:
      circle.m_p = to_float(shape.points[0]);
      circle.m_radius = static_cast<float>(shape.radius);
      fixture.shape = &circle;
      break;
    case ShapeType::capsule:
      polygon = capsule_polygon(shape);
      fixture.shape = &polygon;
      break;
    case ShapeType::segment:
      edge.SetTwoSided(to_float(shape.points[0]), to_float(shape.points[1]));
      fixture.shape = &edge;
      break;
    case ShapeType::chain: {
      const std::vector<Vec2>& p = shape.points;
      const std::vector<b2Vec2> vertices = to_float(p);
      if (shape.loop) {
        chain.CreateLoop(vertices.data(), static_cast<int32>(vertices.size()));
      } else {
        chain.CreateChain(vertices.data(), static_cast<int32>(vertices.size()),
                          end_ghost(p.front(), p[1] - p.front()),
                          end_ghost(p.back(), p.back() - p[p.size() - 2]));
      }
      fixture.shape = &chain;
      break;
    }
  }
  body.CreateFixture(&fixture);
}

// Our mass properties; Box2D takes the inertia about the body origin.
void set_mass(b2Body& body, const MassData& mass, const Vec2& velocity) {
  b2MassData data;
  data.mass = static_cast<float>(mass.mass);
  data.center = to_float(mass.center);
  // No rotational inertia (fixed rotation, or no massive shape) stays none.
  data.I = mass.rotational_inertia > 0
               ? static_cast<float>(mass.rotational_inertia + mass.mass * mass.center.squaredNorm())
               : 0.0f;
  body.SetMassData(&data);
  // Box2D moved the centre's velocity with the centre; the scene gives the centre's.
  body.SetLinearVelocity(to_float(velocity));
}

// What the kinds share: the bodies, collide_connected, and the anchors, reference angle and
// axis where the kind has them.
template <class B2Def, class Def>
void set_common(B2Def& def, const Def& d, const Box2dScene& result, const SceneJoint& joint) {
  def.bodyA = result.bodies.at(joint.body_a);
  def.bodyB = result.bodies.at(joint.body_b);
  def.collideConnected = d.collide_connected;
  if constexpr (requires { d.local_anchor_a; }) {
    def.localAnchorA = to_float(d.local_anchor_a);
    def.localAnchorB = to_float(d.local_anchor_b);
  }
  if constexpr (requires { d.reference_angle; }) {
    def.referenceAngle = static_cast<float>(d.reference_angle);
  }
  if constexpr (requires { d.local_axis_a; }) def.localAxisA = to_float(d.local_axis_a);
}

// A limit and a motor; 2.4.1 names the bounds and the motor's bound by kind.
template <class B2Def>
void set_limit_and_motor(B2Def& def, float B2Def::*lower, float B2Def::*upper,
                         float B2Def::*max_motor, const JointLimit& limit,
                         const JointMotor& motor) {
  def.enableLimit = limit.enabled;
  def.*lower = static_cast<float>(limit.lower);
  def.*upper = static_cast<float>(limit.upper);
  def.enableMotor = motor.enabled;
  def.motorSpeed = static_cast<float>(motor.speed);
  def.*max_motor = static_cast<float>(motor.max_force);
}

// A spring's frequency and damping ratio as 2.4.1's stiffness and damping, from the bodies'
// masses (set before the joints); none leaves the stiffness 0, no spring.
template <class B2Def>
void set_linear_spring(B2Def& def, const JointSpring& spring) {
  if (!spring.enabled) return;
  b2LinearStiffness(def.stiffness, def.damping, static_cast<float>(spring.hertz),
                    static_cast<float>(spring.damping_ratio), def.bodyA, def.bodyB);
}

b2Joint* make_joint(const SceneJoint& joint, const Box2dScene& result) {
  b2World& world = *result.world;
  return std::visit(
      [&](const auto& d) -> b2Joint* {
        using Def = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<Def, RevoluteJointDef>) {
          b2RevoluteJointDef def;
          set_common(def, d, result, joint);
          set_limit_and_motor(def, &b2RevoluteJointDef::lowerAngle, &b2RevoluteJointDef::upperAngle,
                              &b2RevoluteJointDef::maxMotorTorque, d.limit, d.motor);
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, PrismaticJointDef>) {
          b2PrismaticJointDef def;
          set_common(def, d, result, joint);
          set_limit_and_motor(def, &b2PrismaticJointDef::lowerTranslation,
                              &b2PrismaticJointDef::upperTranslation,
                              &b2PrismaticJointDef::maxMotorForce, d.limit, d.motor);
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, DistanceJointDef>) {
          b2DistanceJointDef def;
          set_common(def, d, result, joint);
          def.length = static_cast<float>(d.length);
          // 2.4.1 is rigid when min == max, else free between them (sprung when stiff); ours
          // heeds its limits only when they leave play.
          const bool play = d.limit.enabled && d.limit.lower < d.limit.upper;
          if (d.spring.enabled || play) {
            def.minLength = play ? static_cast<float>(d.limit.lower) : 0.0f;
            def.maxLength =
                play ? static_cast<float>(d.limit.upper) : std::numeric_limits<float>::max();
          } else {
            def.minLength = def.maxLength =
                d.limit.enabled ? static_cast<float>(d.limit.lower) : def.length;
            def.length = def.minLength;
          }
          set_linear_spring(def, d.spring);
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, WeldJointDef>) {
          b2WeldJointDef def;
          set_common(def, d, result, joint);
          if (d.angular_hertz > 0) {
            b2AngularStiffness(def.stiffness, def.damping, static_cast<float>(d.angular_hertz),
                               static_cast<float>(d.angular_damping_ratio), def.bodyA, def.bodyB);
          }
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, WheelJointDef>) {
          b2WheelJointDef def;
          set_common(def, d, result, joint);
          set_limit_and_motor(def, &b2WheelJointDef::lowerTranslation,
                              &b2WheelJointDef::upperTranslation, &b2WheelJointDef::maxMotorTorque,
                              d.limit, d.motor);
          set_linear_spring(def, d.spring);  // none: the suspension runs free, as ours
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, MotorJointDef>) {
          b2MotorJointDef def;
          set_common(def, d, result, joint);
          def.linearOffset = to_float(d.linear_offset);
          def.angularOffset = static_cast<float>(d.angular_offset);
          def.maxForce = static_cast<float>(d.max_force);
          def.maxTorque = static_cast<float>(d.max_torque);
          def.correctionFactor = static_cast<float>(d.correction_factor);
          return world.CreateJoint(&def);
        } else if constexpr (std::is_same_v<Def, GearJointDef>) {
          b2GearJointDef def;
          def.joint1 = result.joints.at(joint.joint1);
          def.joint2 = result.joints.at(joint.joint2);
          // Box2D's gear moves B of each joint, as ours.
          def.bodyA = def.joint1->GetBodyB();
          def.bodyB = def.joint2->GetBodyB();
          def.collideConnected = d.collide_connected;
          def.ratio = static_cast<float>(d.ratio);
          return world.CreateJoint(&def);
        } else {
          static_assert(std::is_same_v<Def, PulleyJointDef>);
          b2PulleyJointDef def;
          set_common(def, d, result, joint);
          def.groundAnchorA = to_float(d.ground_anchor_a);
          def.groundAnchorB = to_float(d.ground_anchor_b);
          def.lengthA = static_cast<float>(d.length_a);
          def.lengthB = static_cast<float>(d.length_b);
          def.ratio = static_cast<float>(d.ratio);
          return world.CreateJoint(&def);
        }
      },
      joint.def);
}

}  // namespace

Box2dScene build_box2d_world(const SceneDef& scene) {
  // Everything is checked first, so a refused scene makes no Box2D world at all.
  std::vector<std::vector<ConvexHull>> hulls;
  check_translatable(scene, hulls);
  const World ours = build_world(scene);
  const std::vector<BodyId> our_bodies = ours.bodies();
  Box2dScene result;
  result.world = std::make_unique<b2World>(to_float(scene.world.gravity));
  result.world->SetAllowSleeping(scene.world.enable_sleep);
  float top_y = -1e30f;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const SceneBody& body = scene.bodies[i];
    b2BodyDef def;
    def.type = body.body.type == BodyType::dynamic     ? b2_dynamicBody
               : body.body.type == BodyType::kinematic ? b2_kinematicBody
                                                       : b2_staticBody;
    def.position = to_float(body.body.position);
    def.angle = static_cast<float>(body.body.angle);
    def.linearVelocity = to_float(body.body.linear_velocity);
    def.angularVelocity = static_cast<float>(body.body.angular_velocity);
    def.linearDamping = static_cast<float>(body.body.linear_damping);
    def.angularDamping = static_cast<float>(body.body.angular_damping);
    def.gravityScale = static_cast<float>(body.body.gravity_scale);
    def.allowSleep = body.body.allow_sleep;
    def.awake = body.body.awake;
    def.enabled = body.body.enabled;
    def.fixedRotation = body.body.fixed_rotation;
    def.bullet = body.body.bullet;
    b2Body* b = result.world->CreateBody(&def);
    result.bodies.push_back(b);
    std::size_t polygon = 0;
    for (const ShapeDef& shape : body.shapes) {
      add_fixture(*b, shape, shape.type == ShapeType::polygon ? &hulls[i][polygon++] : nullptr);
    }
    if (def.type == b2_dynamicBody) {
      set_mass(*b, ours.mass_data(our_bodies[i]), body.body.linear_velocity);
      if (def.position.y > top_y) {
        top_y = def.position.y;
        result.top = b;
      }
    }
  }
  for (const SceneJoint& joint : scene.joints) result.joints.push_back(make_joint(joint, result));
  return result;
}

}  // namespace mink::interop
