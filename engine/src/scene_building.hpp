#pragma once

// The pieces the built-in scenes are made of: bodies with shapes and joints given at world
// points, appended to a SceneDef.

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "mink/engine/scene.hpp"

namespace mink::detail {

// Appends a body with these shapes; returns its index.
inline std::size_t add_body(SceneDef& scene, BodyType type, const Vec2& position,
                            std::vector<ShapeDef> shapes, Real angle = 0) {
  SceneBody body;
  body.body.type = type;
  body.body.position = position;
  body.body.angle = angle;
  body.shapes = std::move(shapes);
  scene.bodies.push_back(std::move(body));
  return scene.bodies.size() - 1;
}

// A static body at `center` with one box of half extents (hx, hy).
inline SceneBody static_box(const Vec2& center, Real hx, Real hy) {
  SceneBody ground;
  ground.body.type = BodyType::static_body;
  ground.body.position = center;
  ground.shapes.push_back(ShapeDef::box(hx, hy));
  return ground;
}

// Appends a joint of `def`'s kind between bodies a and b of the scene at world points (one
// point twice for kinds with one anchor), holding the bodies as they are defined.
template <class Def>
SceneJoint& add_joint(SceneDef& scene, std::size_t a, std::size_t b, const Vec2& anchor_a,
                      const Vec2& anchor_b, Def def = {}) {
  def.local_anchor_a = scene_body_pose(scene, a).apply_inverse(anchor_a);
  def.local_anchor_b = scene_body_pose(scene, b).apply_inverse(anchor_b);
  if constexpr (requires { def.reference_angle; }) {
    def.reference_angle = scene.bodies[b].body.angle - scene.bodies[a].body.angle;
  }
  if constexpr (std::is_same_v<Def, DistanceJointDef>) def.length = (anchor_b - anchor_a).norm();
  SceneJoint joint;
  joint.def = def;
  joint.body_a = a;
  joint.body_b = b;
  scene.joints.push_back(std::move(joint));
  return scene.joints.back();
}

}  // namespace mink::detail
