#include <gtest/gtest.h>

#include <vector>

#include "test_worlds.hpp"

namespace mink {
namespace {

using test::add_box;
using test::add_ground;

std::vector<BodyId> stack(World& world, int height, Real x = 0) {
  std::vector<BodyId> boxes;
  for (int i = 0; i < height; ++i) boxes.push_back(add_box(world, {x, 0.5 + i}));
  return boxes;
}

TEST(Sleep, ARestingStackSleepsAsOneIslandAndStopsMoving) {
  World world;
  add_ground(world);
  const std::vector<BodyId> boxes = stack(world, 5);
  for (int i = 0; i < 180; ++i) world.step();
  for (const BodyId b : boxes) EXPECT_FALSE(world.is_awake(b));
  EXPECT_EQ(world.counters().awake_bodies, 0u);
  EXPECT_EQ(world.counters().islands, 0u);
  const Vec2 before = world.position(boxes.back());
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_EQ(world.position(boxes.back()), before);  // asleep: not integrated at all
}

// While no body has rested long enough to sleep, islands are counted without being walked:
// stacks standing apart are islands of their own, and a plank laid across two joins them.
TEST(Sleep, IslandsAreCountedWhileEveryBodyMoves) {
  World world;
  add_ground(world);
  stack(world, 3, 0);
  stack(world, 3, 3);
  stack(world, 3, 6);
  for (int i = 0; i < 10; ++i) world.step();
  EXPECT_EQ(world.counters().islands, 3u);
  BodyDef plank;
  plank.type = BodyType::dynamic;
  plank.position = Vec2(1.5, 3.15);  // across the first two stacks
  world.create_shape(world.create_body(plank), ShapeDef::box(2.5, 0.1));
  for (int i = 0; i < 15; ++i) world.step();
  EXPECT_EQ(world.counters().islands, 2u);
}

TEST(Sleep, TouchingThroughTheApiWakesTheWholeIsland) {
  World world;
  add_ground(world);
  const std::vector<BodyId> boxes = stack(world, 4);
  const std::vector<BodyId> other = stack(world, 2, 5);
  for (int i = 0; i < 180; ++i) world.step();
  ASSERT_FALSE(world.is_awake(boxes[0]));
  world.apply_linear_impulse(boxes[3], Vec2(0.5, 0), world.world_center(boxes[3]));
  EXPECT_TRUE(world.is_awake(boxes[3]));
  world.step();
  for (const BodyId b : boxes) EXPECT_TRUE(world.is_awake(b));
  for (const BodyId b : other) EXPECT_FALSE(world.is_awake(b));  // a separate island
  EXPECT_EQ(world.counters().islands, 1u);
}

TEST(Sleep, AnAwakeBodyHittingASleepingStackWakesIt) {
  World world;
  add_ground(world);
  const std::vector<BodyId> boxes = stack(world, 3);
  for (int i = 0; i < 180; ++i) world.step();
  ASSERT_FALSE(world.is_awake(boxes[0]));
  const BodyId falling = add_box(world, {0.3, 6});
  const ShapeId falling_shape = world.body_shapes(falling)[0];
  const ShapeId top_shape = world.body_shapes(boxes.back())[0];
  // The stack sleeps until the falling box comes within contact range of its top box (its
  // contact gets points, speculative ones first) and wakes in that very step, before they
  // touch: it meets the box as a moving stack, not as a static one.
  bool woke = false;
  bool hit = false;
  for (int i = 0; i < 120 && !woke; ++i) {
    const Real reach =
        4 * world.def().linear_slop + world.def().time_step * world.linear_velocity(falling).norm();
    const Real gap_before =
        world.position(falling).y() - 0.5 - (world.position(boxes.back()).y() + 0.5);
    world.step();
    for (const ContactBeginEvent& e : world.contact_begin_events()) {
      hit = hit || (e.shape_a == falling_shape && e.shape_b == top_shape) ||
            (e.shape_a == top_shape && e.shape_b == falling_shape);
    }
    woke = world.is_awake(boxes[0]);
    if (hit) {
      EXPECT_TRUE(woke) << "step " << world.step_count();
    }
    if (woke) {
      EXPECT_LT(gap_before, reach + 0.05) << "woke too early, step " << world.step_count();
    }
  }
  EXPECT_TRUE(woke);
  for (const BodyId b : boxes) EXPECT_TRUE(world.is_awake(b));
}

TEST(Sleep, SleepingOffKeepsEveryBodyAwake) {
  WorldDef def;
  def.enable_sleep = false;
  World world(def);
  add_ground(world);
  const std::vector<BodyId> boxes = stack(world, 3);
  for (int i = 0; i < 180; ++i) world.step();
  for (const BodyId b : boxes) EXPECT_TRUE(world.is_awake(b));
  EXPECT_EQ(world.counters().awake_bodies, 3u);
}

TEST(Sleep, BodiesThatMayNotSleepKeepTheirIslandAwake) {
  World world;
  add_ground(world);
  const std::vector<BodyId> boxes = stack(world, 2);
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(0, 2.5);
  def.allow_sleep = false;
  const BodyId restless = world.create_body(def);
  world.create_shape(restless, ShapeDef::box(0.5, 0.5));
  for (int i = 0; i < 180; ++i) world.step();
  EXPECT_TRUE(world.is_awake(restless));
  EXPECT_TRUE(world.is_awake(boxes[0]));
}

TEST(Sleep, PuttingABodyToSleepThroughTheApi) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  const BodyId box = add_box(world, {0, 0});
  world.set_linear_velocity(box, Vec2(1, 0));
  world.set_awake(box, false);
  EXPECT_FALSE(world.is_awake(box));
  EXPECT_EQ(world.linear_velocity(box), Vec2(0, 0));
  world.step();
  EXPECT_EQ(world.position(box), Vec2(0, 0));
  world.set_awake(box, true);
  world.set_linear_velocity(box, Vec2(1, 0));
  world.step();
  EXPECT_GT(world.position(box).x(), 0);
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// A sleeping island costs nothing: once a large world sleeps, a step visits no body and no
// contact (the sleep benchmark, bench/run_sleep.sh, shows what that saves in time).
TEST(SleepCost, ASleepingWorldStepsWithoutVisitingItsBodiesOrContacts) {
  World world = build_world(many_pyramids_scene(3, 4, 6));
  int steps = 0;
  do {
    world.step();
  } while (world.counters().awake_bodies > 0 && ++steps < 1000);
  ASSERT_EQ(world.counters().awake_bodies, 0u);
  const std::size_t contacts = world.counters().contacts;
  EXPECT_GT(contacts, 200u);
  for (int i = 0; i < 5; ++i) {
    world.step();
    EXPECT_EQ(world.counters().collided_contacts, 0u);
    EXPECT_EQ(world.counters().awake_bodies, 0u);
    EXPECT_TRUE(world.body_move_events().empty());
    EXPECT_EQ(world.counters().contacts, contacts);  // kept, not thrown away
  }
  // Touching one box wakes its pyramid, and only its pyramid's contacts are visited.
  const BodyId top = world.bodies().back();
  world.apply_linear_impulse(top, Vec2(0.1, 0), world.world_center(top));
  world.step();
  EXPECT_GT(world.counters().collided_contacts, 0u);
  EXPECT_LT(world.counters().collided_contacts, contacts / 4);
}

}  // namespace
}  // namespace mink
