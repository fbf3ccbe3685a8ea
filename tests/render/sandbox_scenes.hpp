#pragma once

// Scenes the sandbox tests drag bodies and make joints in, headless and in the window.

#include "mink/engine/scene.hpp"

namespace mink_test {

// Index in the scene's bodies (and in World::bodies() of a world built from it).
enum StackBody : std::size_t { kGround, kBottom, kMiddle, kTop, kHeavy };

// A ground, a stack of three unit boxes resting on it at x = 0 (kBottom, kMiddle, kTop) and,
// at x = 5, one unit box 1000 times as dense (kHeavy).
inline mink::SceneDef stack_scene() {
  mink::SceneDef scene;
  mink::SceneBody ground;
  ground.body.position = mink::Vec2(0, -0.5);
  ground.shapes.push_back(mink::ShapeDef::box(10, 0.5));
  scene.bodies.push_back(ground);
  const auto box = [&](const mink::Vec2& at, mink::Real density) {
    mink::SceneBody body;
    body.body.type = mink::BodyType::dynamic;
    body.body.position = at;
    body.shapes.push_back(mink::ShapeDef::box(0.5, 0.5));
    body.shapes.back().density = density;
    scene.bodies.push_back(body);
  };
  for (int level = 0; level < 3; ++level) box(mink::Vec2(0, 0.5 + level), 1);
  box(mink::Vec2(5, 0.5), 1000);
  return scene;
}

}  // namespace mink_test
