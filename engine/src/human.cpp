#include "human.hpp"

#include <array>
#include <numbers>
#include <utility>
#include <variant>
#include <vector>

#include "scene_building.hpp"

namespace mink::detail {

namespace {

// One bone of the 1.8 m human whose feet are at the origin: a capsule along the body's y axis
// and the revolute joint to its parent.
struct Bone {
  int parent;                // -1 for the hip
  Real y;                    // the body's height
  Real bottom, top, radius;  // the capsule, along the body's y axis
  Real damping;              // linear damping (the head and forearms swing less)
  Real pivot;                // the joint's height
  Real lower, upper;         // limits, in turns of pi
  Real friction;             // share of the joint friction torque
  Real frame;                // the joint's frame on the parent, turned by this many pi
};
constexpr std::array<Bone, 11> kHuman = {{
    {-1, 0.95, -0.02, 0.02, 0.095, 0, 0, 0, 0, 0, 0},                 // hip
    {0, 1.2, -0.135, 0.135, 0.09, 0, 1.0, -0.25, 0, 0.5, 0},          // torso
    {1, 1.475, -0.038, 0.039, 0.075, 0.1, 1.4, -0.3, 0.1, 0.25, 0},   // head
    {0, 0.775, -0.125, 0.125, 0.06, 0, 0.9, -0.05, 0.4, 1, 0},        // upper legs
    {3, 0.475, -0.155, 0.125, 0.045, 0, 0.625, -0.5, -0.02, 0.5, 0},  // lower legs (feet)
    {0, 0.775, -0.125, 0.125, 0.06, 0, 0.9, -0.05, 0.4, 1, 0},
    {5, 0.475, -0.155, 0.125, 0.045, 0, 0.625, -0.5, -0.02, 0.5, 0},
    {1, 1.225, -0.125, 0.125, 0.035, 0, 1.35, -0.1, 0.8, 0.5, 0},  // upper arms
    // Forearms: the elbow's zero is bent by a quarter turn of pi, so they start outside their
    // limits and fold in, as Box2D v3's do.
    {7, 0.975, -0.125, 0.125, 0.03, 0.1, 1.1, -0.2, 0.3, 0.1, 0.25},
    {1, 1.225, -0.125, 0.125, 0.035, 0, 1.35, -0.1, 0.8, 0.5, 0},
    {9, 0.975, -0.125, 0.125, 0.03, 0.1, 1.1, -0.2, 0.3, 0.1, 0.25},
}};

constexpr Real kJointFriction = 0.05;  // N m, times each bone's share
constexpr std::uint64_t kBodyBits = 2, kGroundBits = 1;

}  // namespace

void add_human(SceneDef& scene, const Vec2& feet, std::int32_t group) {
  const std::size_t first = scene.bodies.size();
  for (const Bone& bone : kHuman) {
    ShapeDef capsule = ShapeDef::capsule(Vec2(0, bone.bottom), Vec2(0, bone.top), bone.radius);
    capsule.friction = 0.2;
    capsule.filter = {kBodyBits, kBodyBits | kGroundBits, group};
    std::vector<ShapeDef> shapes = {std::move(capsule)};
    if (bone.parent == 3 || bone.parent == 5) {
      ShapeDef foot;
      foot.points = {{-0.03, -0.185}, {0.11, -0.185}, {0.11, -0.16}, {-0.03, -0.14}};
      foot.radius = 0.015;
      foot.friction = 0.05;
      foot.filter = {kBodyBits, kGroundBits, group};  // feet do not catch on other humans
      shapes.push_back(std::move(foot));
    }
    const std::size_t body =
        add_body(scene, BodyType::dynamic, feet + Vec2(0, bone.y), std::move(shapes));
    scene.bodies[body].body.linear_damping = bone.damping;
    if (bone.parent < 0) continue;
    RevoluteJointDef def;
    def.limit = {true, bone.lower * std::numbers::pi, bone.upper * std::numbers::pi};
    def.motor = {true, 0, kJointFriction * bone.friction};
    def.spring = {true, 5, 0.5, 0};
    const Vec2 pivot = feet + Vec2(0, bone.pivot);
    SceneJoint& joint =
        add_joint(scene, first + static_cast<std::size_t>(bone.parent), body, pivot, pivot, def);
    std::get<RevoluteJointDef>(joint.def).reference_angle += bone.frame * std::numbers::pi;
  }
}

}  // namespace mink::detail
