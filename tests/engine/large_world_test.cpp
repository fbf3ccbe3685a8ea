// Large worlds: positions are doubles on a grid the step keeps them on (world_grid.hpp), and
// everything else is measured from them, so a scene 10^7 m from the origin must behave as it
// does at the origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <variant>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace {

using namespace mink;

bool all_asleep(const World& world) {
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic && world.is_awake(id)) return false;
  }
  return true;
}

// The largest distance between body i of `world` less `offset` and body i of `origin`.
Real largest_difference(const World& world, const Vec2& offset, const World& origin) {
  const std::vector<BodyId> ours = world.bodies();
  const std::vector<BodyId> theirs = origin.bodies();
  Real worst = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    worst = std::max(worst, (world.position(ours[i]) - offset - origin.position(theirs[i])).norm());
  }
  return worst;
}

// The largest difference of angle between body i of `world` and body i of `origin`.
Real largest_turn(const World& world, const World& origin) {
  const std::vector<BodyId> ours = world.bodies();
  const std::vector<BodyId> theirs = origin.bodies();
  Real worst = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    worst = std::max(worst, std::abs(world.angle(ours[i]) - origin.angle(theirs[i])));
  }
  return worst;
}

// The scene at the origin and moved by 10^7 m (as a user would build it there, every body
// placed at its shifted position), stepped side by side until both sleep: far away it must fall
// asleep within 2 steps of the origin's run and end within 1e-6 m of it, body by body.
//
// These scenes are sensitive (a perfectly aligned pyramid's touching faces, ragdolls tumbling
// onto each other): a last-bit change of one position already moves the settled bodies by a
// tenth of a millimetre. So the origin's run starts from the positions the shifted one can hold
// (10^7 m out doubles are 1.9e-9 m apart: each position is moved out and back first), or the
// two would be different scenes from their first step on.
void expect_same_far_away(const std::string& name, SceneDef scene, int max_steps) {
  const Vec2 offset(1e7, 1e7);
  shift_scene(scene, offset);
  shift_scene(scene, -offset);
  std::vector<World> worlds;
  worlds.push_back(build_world(scene));
  shift_scene(scene, offset);
  worlds.push_back(build_world(scene));
  std::vector<int> sleep_steps(worlds.size(), -1);
  for (int step = 1; step <= max_steps; ++step) {
    bool all = true;
    for (std::size_t i = 0; i < worlds.size(); ++i) {
      worlds[i].step();
      if (sleep_steps[i] < 0 && all_asleep(worlds[i])) sleep_steps[i] = step;
      all = all && sleep_steps[i] >= 0;
    }
    if (all) break;
  }
  for (const World& world : worlds) {
    for (const BodyId id : world.bodies()) ASSERT_TRUE(test::finite_state(world, id)) << name;
  }
  ASSERT_GT(sleep_steps[0], 0) << name << " never slept at the origin";
  ASSERT_GT(sleep_steps[1], 0) << name << " never slept at (1e7, 1e7)";
  EXPECT_LE(std::abs(sleep_steps[1] - sleep_steps[0]), 2)
      << name << ": asleep after " << sleep_steps[1] << " steps far away, " << sleep_steps[0]
      << " at the origin";
  const Real far = largest_difference(worlds[1], offset, worlds[0]);
  const Real turn = largest_turn(worlds[1], worlds[0]);
  EXPECT_LE(far, 1e-6) << name;
  EXPECT_LE(turn, 1e-6) << name;
  std::cout << name << ": asleep after " << sleep_steps[0] << " steps at the origin, "
            << sleep_steps[1] << " at (1e7, 1e7); largest difference from the origin's run " << far
            << " m in position, " << turn << " rad in angle\n";
}

TEST(LargeWorld, RagdollsSettleFarFromTheOriginAsAtIt) {
  expect_same_far_away("ragdolls", builtin_scene("ragdolls"), 3000);
}

// Box2D v3's large_pyramid (5050 boxes) runs with sleeping off; here it is on, so that the
// pyramid's settling ends. Under the sanitizers, the same pyramid with 40 rows.
TEST(LargeWorld, LargePyramidSettlesFarFromTheOriginAsAtIt) {
  SceneDef scene = builtin_scene("large_pyramid");
#ifdef MINK_SANITIZED_BUILD
  scene.bodies.resize(1);
  add_pyramid(scene, 40, Vec2(0, 0));
#endif
  scene.world.enable_sleep = true;
  expect_same_far_away("large_pyramid", scene, 3000);
}

TEST(LargeWorld, ShiftSceneMovesBodiesAndPulleyAnchors) {
  SceneDef scene = builtin_scene("ragdolls");
  const SceneDef before = scene;
  shift_scene(scene, Vec2(3, -4));
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    EXPECT_EQ(scene.bodies[i].body.position, before.bodies[i].body.position + Vec2(3, -4));
    EXPECT_EQ(scene.bodies[i].body.angle, before.bodies[i].body.angle);
  }
  SceneJoint pulley;
  PulleyJointDef def;
  def.ground_anchor_a = Vec2(1, 2);
  def.ground_anchor_b = Vec2(5, 2);
  pulley.def = def;
  scene.joints.push_back(pulley);
  shift_scene(scene, Vec2(10, 20));
  const auto& moved = std::get<PulleyJointDef>(scene.joints.back().def);
  EXPECT_EQ(moved.ground_anchor_a, Vec2(11, 22));
  EXPECT_EQ(moved.ground_anchor_b, Vec2(15, 22));
  EXPECT_THROW(shift_scene(scene, Vec2(NAN, 0)), InvalidArgumentError);
  SceneDef rain = builtin_scene("rain");
  EXPECT_THROW(shift_scene(rain, Vec2(1, 0)), InvalidArgumentError);
}

}  // namespace
