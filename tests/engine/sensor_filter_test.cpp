// Sensors, filters and the events of the engine core: what passes through what, who is told,
// and that a change at run time takes effect within one step.

#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <vector>

#include "mink/engine/stale_id_error.hpp"
#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

BodyId add_ball(World& world, const Vec2& position, Real radius = 0.25, const Filter& filter = {},
                const Vec2& velocity = {0, 0}) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  def.linear_velocity = velocity;
  const BodyId body = world.create_body(def);
  ShapeDef shape = ShapeDef::circle(radius);
  shape.filter = filter;
  world.create_shape(body, shape);
  return body;
}

struct SensorCount {
  int begins = 0, ends = 0;
};

// Counts the sensor events naming `sensor` and the shape of `visitor`, step by step.
SensorCount run_counting(World& world, ShapeId sensor, BodyId visitor, int steps) {
  SensorCount count;
  const ShapeId visitor_shape = world.body_shapes(visitor)[0];
  for (int i = 0; i < steps; ++i) {
    world.step();
    for (const SensorBeginEvent& e : world.sensor_begin_events()) {
      if (e.sensor == sensor && e.visitor == visitor_shape) ++count.begins;
    }
    for (const SensorEndEvent& e : world.sensor_end_events()) {
      if (e.sensor == sensor && e.visitor == visitor_shape) ++count.ends;
    }
  }
  return count;
}

TEST(Sensors, ABodyFallingThroughASensorGetsExactlyOneBeginAndOneEnd) {
  World world;
  const BodyId zone = world.create_body({});
  ShapeDef sensor_def = ShapeDef::box(2, 0.5, Vec2(0, 5));
  sensor_def.is_sensor = true;
  const ShapeId sensor = world.create_shape(zone, sensor_def);
  const BodyId ball = add_ball(world, {0, 10});
  const SensorCount count = run_counting(world, sensor, ball, 120);  // falls past y = 0
  EXPECT_LT(world.position(ball).y(), 0);
  EXPECT_EQ(count.begins, 1);
  EXPECT_EQ(count.ends, 1);
  // It never pushed: the ball fell freely, y = 10 - g t^2 / 2 (semi-implicit Euler: a little
  // further).
  const Real t = 120 * world.def().time_step;
  EXPECT_NEAR(world.position(ball).y(), 10 - 5 * t * t, 0.15);
}

TEST(Sensors, SensorsOnMovingBodiesSeeStaticShapesAndReportInSlotOrder) {
  World world;
  test::add_ground(world);
  BodyDef def;
  def.type = BodyType::kinematic;
  def.position = Vec2(-5, 0.25);  // the sensor dips into the ground
  def.linear_velocity = Vec2(5, 0);
  const BodyId mover = world.create_body(def);
  ShapeDef sensor_def = ShapeDef::circle(0.3);
  sensor_def.is_sensor = true;
  const ShapeId sensor = world.create_shape(mover, sensor_def);
  std::vector<BodyId> boxes;
  for (int i = 0; i < 3; ++i) boxes.push_back(test::add_box(world, Vec2(-2 + 2 * i, 0.5), 0.4));
  std::vector<ShapeId> seen;
  for (int i = 0; i < 120; ++i) {
    world.step();
    for (const SensorBeginEvent& e : world.sensor_begin_events()) {
      ASSERT_EQ(e.sensor, sensor);
      seen.push_back(e.visitor);
    }
  }
  // The ground first (it is under the sensor from the start), then each box as it passes.
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(world.shape_body(seen[0]), world.bodies()[0]);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(world.shape_body(seen[1 + i]), boxes[i]);
}

TEST(Filters, ShapesInFilteredOutCategoriesPassThroughEachOther) {
  World world;
  const Filter red{0x1, ~std::uint64_t{0x2}, 0};   // does not collide with blue
  const Filter blue{0x2, ~std::uint64_t{0x1}, 0};  // nor blue with red
  const BodyId ground = world.create_body({});
  ShapeDef floor = ShapeDef::box(20, 0.5, Vec2(0, -0.5));
  floor.filter = blue;
  world.create_shape(ground, floor);
  const BodyId red_ball = add_ball(world, {-1, 2}, 0.25, red);
  const BodyId blue_ball = add_ball(world, {1, 2}, 0.25, blue);
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_LT(world.position(red_ball).y(), -5);             // fell through the blue floor
  EXPECT_NEAR(world.position(blue_ball).y(), 0.25, 0.02);  // rests on it
}

TEST(Filters, GroupsOverrideCategoriesBothWays) {
  const Filter never_a{0x1, 0x1, -3};
  EXPECT_FALSE(should_collide(never_a, never_a));
  const Filter always{0x1, 0x0, 4};  // masks say no, the group says yes
  EXPECT_TRUE(should_collide(always, always));
  EXPECT_FALSE(should_collide(always, Filter{0x1, 0x1, 5}));
  EXPECT_TRUE(should_collide(Filter{}, Filter{}));
}

TEST(Filters, AFilterChangedAtRunTimeTakesEffectWithinOneStep) {
  World world;
  const BodyId ground = world.create_body({});
  const ShapeId floor = world.create_shape(ground, ShapeDef::box(20, 0.5, Vec2(0, -0.5)));
  const BodyId box = test::add_box(world, {0, 0.5});
  for (int i = 0; i < 30; ++i) world.step();
  ASSERT_EQ(world.body_contacts(box).size(), 1u);
  world.set_shape_filter(floor, Filter{0x1, 0x0, 0});  // collides with nothing now
  ASSERT_EQ(world.contact_end_events().size(), 1u);    // the touching contact ended at once
  world.step();
  EXPECT_TRUE(world.body_contacts(box).empty());
  EXPECT_LT(world.linear_velocity(box).y(), -0.1);  // falling within that one step
  // And back: the pair is found again within one step, and the box is caught.
  world.set_shape_filter(floor, Filter{});
  world.step();
  EXPECT_EQ(world.body_contacts(box).size(), 1u);
}

TEST(Events, BeginEventsCarryTheManifoldAndHitsTheApproachSpeed) {
  World world;
  const BodyId ground = world.create_body({});
  ShapeDef floor = ShapeDef::box(20, 0.5, Vec2(0, -0.5));
  floor.enable_hit_events = true;
  world.create_shape(ground, floor);
  add_ball(world, {0, 0.6}, 0.25, {}, {0, -6});
  bool began = false, hit = false;
  for (int i = 0; i < 30 && !(began && hit); ++i) {
    world.step();
    for (const ContactBeginEvent& e : world.contact_begin_events()) {
      began = true;
      ASSERT_EQ(e.manifold.point_count, 1);
      // Normal from A to B: vertical either way, the point at the bottom of the ball.
      EXPECT_NEAR(std::abs(e.manifold.normal.y()), 1, 1e-9);
      EXPECT_NEAR(e.manifold.points[0].point.y(), 0, 0.05);
    }
    for (const ContactHitEvent& e : world.contact_hit_events()) {
      hit = true;
      EXPECT_GT(e.approach_speed, 5.9);  // it met the floor at about 6 m/s plus what g added
      EXPECT_LT(e.approach_speed, 7);
      EXPECT_NEAR(e.point.y(), 0, 0.05);
    }
  }
  EXPECT_TRUE(began);
  EXPECT_TRUE(hit);
}

TEST(Events, ContactEventsCanBeTurnedOffPerShape) {
  World world;
  const BodyId ground = world.create_body({});
  ShapeDef floor = ShapeDef::box(20, 0.5, Vec2(0, -0.5));
  floor.enable_contact_events = false;
  world.create_shape(ground, floor);
  add_ball(world, {0, 0.3});
  for (int i = 0; i < 20; ++i) {
    world.step();
    EXPECT_TRUE(world.contact_begin_events().empty());
  }
}

TEST(Events, MoveEventsListTheBodiesThatMovedAndTheOnesThatFellAsleep) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 0.5});
  const BodyId falling = add_ball(world, {5, 50});
  world.step();
  ASSERT_EQ(world.body_move_events().size(), 2u);
  EXPECT_EQ(world.body_move_events()[0].body, box);
  EXPECT_EQ(world.body_move_events()[1].body, falling);
  bool fell_asleep = false;
  for (int i = 0; i < 200 && !fell_asleep; ++i) {
    world.step();
    for (const BodyMoveEvent& e : world.body_move_events()) {
      if (e.body == box && e.fell_asleep) fell_asleep = true;
    }
  }
  EXPECT_TRUE(fell_asleep);
  EXPECT_FALSE(world.is_awake(box));
  world.step();
  for (const BodyMoveEvent& e : world.body_move_events()) EXPECT_NE(e.body, box);
}

// Resting boxes fall asleep at slots between falling balls, in advances of three steps: each
// step's events are one run in slot order, the sleepers' merged into the movers'.
TEST(Events, MoveEventsOfSleepersMergeInSlotOrderStepByStep) {
  World world;
  test::add_ground(world);
  std::vector<BodyId> boxes;
  for (int i = 0; i < 6; ++i) {
    boxes.push_back(test::add_box(world, {-10.0 + 4 * i, 0.5}));
    add_ball(world, {-8.0 + 4 * i, 200});  // the last slot: every step ends with a ball
  }
  int advances_with_sleepers = 0;
  for (int i = 0; i < 70; ++i) {
    const AdvanceResult result = world.advance(3 * WorldDef{}.time_step);
    const std::span<const BodyMoveEvent> events = world.body_move_events();
    int runs = events.empty() ? 0 : 1;
    bool sleeper_between_movers = false;
    for (std::size_t k = 1; k < events.size(); ++k) {
      if (!(events[k - 1].body.index < events[k].body.index)) ++runs;
      if (events[k - 1].fell_asleep && !events[k].fell_asleep) sleeper_between_movers = true;
    }
    ASSERT_EQ(runs, result.steps) << "advance " << i;
    if (sleeper_between_movers) ++advances_with_sleepers;
  }
  EXPECT_GT(advances_with_sleepers, 0);
  for (const BodyId box : boxes) EXPECT_FALSE(world.is_awake(box));
}

TEST(Ids, AnIdFromAnotherWorldIsRefused) {
  World first, second;
  const BodyId a = first.create_body({});
  const BodyId b = second.create_body({});
  ASSERT_EQ(a.index, b.index);
  EXPECT_FALSE(second.is_valid(a));
  EXPECT_THROW(second.position(a), StaleIdError);
  try {
    second.destroy_body(a);
    FAIL() << "no error";
  } catch (const StaleIdError& e) {
    EXPECT_NE(std::string(e.what()).find(to_string(a)), std::string::npos);
  }
}

}  // namespace
}  // namespace mink
