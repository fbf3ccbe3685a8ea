// Large worlds: positions are doubles and the solver works on deltas from them, so a scene
// 10^7 m from the origin must behave as it does at the origin.
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

// The scene at the origin, moved by 10^3 m and by 10^7 m (as a user would build it there,
// every body placed at its shifted position), stepped side by side until all three sleep.
// Far away it must fall asleep within 2 steps of the origin's run, and end as close to the
// origin's run as the nearby copy does: these scenes are sensitive (a perfectly aligned
// pyramid's touching faces, ragdolls tumbling onto each other), so a change of position in the
// last bit (1e-13 m at 10^3 m) already moves the settled bodies by far more than that; what is
// asked of 10^7 m, where doubles are 1.9e-9 m apart, is to be no worse than that.
void expect_same_far_away(const std::string& name, const SceneDef& scene, int max_steps) {
  const std::vector<Vec2> offsets = {Vec2(0, 0), Vec2(1e3, 1e3), Vec2(1e7, 1e7)};
  std::vector<World> worlds;
  for (const Vec2& offset : offsets) {
    SceneDef shifted = scene;
    shift_scene(shifted, offset);
    worlds.push_back(build_world(shifted));
  }
  std::vector<int> sleep_steps(offsets.size(), -1);
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
  ASSERT_GT(sleep_steps[2], 0) << name << " never slept at (1e7, 1e7)";
  EXPECT_LE(std::abs(sleep_steps[2] - sleep_steps[0]), 2)
      << name << ": asleep after " << sleep_steps[2] << " steps far away, " << sleep_steps[0]
      << " at the origin";
  const Real near = largest_difference(worlds[1], offsets[1], worlds[0]);
  const Real far = largest_difference(worlds[2], offsets[2], worlds[0]);
  // A settling stack amplifies a last-bit change in position: 10^7 m out a position's last bit
  // is 1.9e-9 m, a thousand times what it is at 10^3 m, and the settled bodies carry that to
  // anything up to a millimetre or so, as the near copy shows they already do at 10^3 m. The
  // far run may differ from the origin's by twice what the near one does, or by the linear
  // slop (the depth to which the contacts themselves let bodies rest into each other).
  EXPECT_LE(far, std::max(2 * near, worlds[0].def().linear_slop)) << name;
  std::cout << name << ": asleep after " << sleep_steps[0] << " steps at the origin, "
            << sleep_steps[1] << " at (1e3, 1e3), " << sleep_steps[2]
            << " at (1e7, 1e7); largest position difference from the origin's run " << near
            << " m at (1e3, 1e3), " << far << " m at (1e7, 1e7)\n";
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
