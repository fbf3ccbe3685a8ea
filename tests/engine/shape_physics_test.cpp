// Every shape kind in motion, against closed-form results: rolling without slipping, coming to
// rest on a chain, and sliding across the seams of tiled floors and chains.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

TEST(ShapePhysics, ADiskRollsDownASlopeWithoutSlippingAtTwoThirdsGSinTheta) {
  WorldDef def;
  def.enable_sleep = false;
  World world(def);
  const Real theta = std::numbers::pi / 6;  // 30 degrees, downhill towards +x
  const Vec2 down_slope(std::cos(theta), -std::sin(theta));
  const Vec2 slope_normal(std::sin(theta), std::cos(theta));
  const BodyId slope = world.create_body({});
  ShapeDef plane = ShapeDef::box(100, 1, -1 * slope_normal, -theta);
  plane.friction = 0.6;
  world.create_shape(slope, plane);

  const Real radius = 0.5;
  BodyDef disk_def;
  disk_def.type = BodyType::dynamic;
  disk_def.position = radius * slope_normal;
  const BodyId disk = world.create_body(disk_def);
  ShapeDef disk_shape = ShapeDef::circle(radius);
  disk_shape.friction = 0.6;
  world.create_shape(disk, disk_shape);

  // Skip the first steps, where the contact settles, then measure over one second.
  for (int i = 0; i < 15; ++i) world.step();
  const Real v0 = world.linear_velocity(disk).dot(down_slope);
  for (int i = 0; i < 60; ++i) world.step();
  const Real v1 = world.linear_velocity(disk).dot(down_slope);
  const Real acceleration = (v1 - v0) / (60 * def.time_step);
  const Real expected = 2.0 / 3.0 * 10 * std::sin(theta);
  EXPECT_NEAR(acceleration, expected, 0.02 * expected);
  // Rolling, not sliding: the contact point is at rest, v = -w r.
  EXPECT_NEAR(-world.angular_velocity(disk) * radius, v1, 0.02 * v1);
  RecordProperty("acceleration", std::to_string(acceleration));
}

// A chain terrain whose right side faces up: points from right to left.
std::vector<Vec2> wavy_terrain(int segments, Real width) {
  std::vector<Vec2> points;
  for (int i = segments; i >= 0; --i) {
    const Real x = -width / 2 + width * i / segments;
    points.emplace_back(x, 0.3 * std::sin(0.5 * x));
  }
  return points;
}

TEST(ShapePhysics, ACapsuleAndACircleDroppedOnAChainComeToRest) {
  World world;
  const BodyId ground = world.create_body({});
  const std::vector<ShapeId> segments =
      world.create_chain(ground, ShapeDef::chain(wavy_terrain(40, 40)));
  EXPECT_EQ(segments.size(), 40u);

  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(-2, 3);
  def.angle = 0.4;
  const BodyId capsule = world.create_body(def);
  world.create_shape(capsule, ShapeDef::capsule(Vec2(-0.5, 0), Vec2(0.5, 0), 0.25));
  def.position = Vec2(3, 4);
  const BodyId ball = world.create_body(def);
  world.create_shape(ball, ShapeDef::circle(0.4));

  for (int i = 0; i < 600; ++i) world.step();
  for (const BodyId body : {capsule, ball}) {
    EXPECT_TRUE(test::finite_state(world, body));
    EXPECT_FALSE(world.is_awake(body)) << "still moving at " << world.linear_velocity(body).norm();
    // Resting above the terrain, not fallen through it.
    const Vec2 p = world.world_center(body);
    EXPECT_GT(p.y(), 0.3 * std::sin(0.5 * p.x()) - 0.05);
    EXPECT_LT(p.y(), 1.5);
  }
}

enum class Floor { one_box, tiled_boxes, chain };

// A box pushed along a floor by a constant force from rest; its speed after `steps`.
Real pushed_speed(Floor floor, int steps) {
  WorldDef def;
  def.enable_sleep = false;
  World world(def);
  const BodyId ground = world.create_body({});
  const Real friction = 0.2;
  const int tiles = 100;
  switch (floor) {
    case Floor::one_box: {
      ShapeDef box = ShapeDef::box(tiles / 2.0, 0.5, Vec2(0, -0.5));
      box.friction = friction;
      world.create_shape(ground, box);
      break;
    }
    case Floor::tiled_boxes:
      for (int i = 0; i < tiles; ++i) {
        ShapeDef box = ShapeDef::box(0.5, 0.5, Vec2(-tiles / 2.0 + 0.5 + i, -0.5));
        box.friction = friction;
        world.create_shape(ground, box);
      }
      break;
    case Floor::chain: {
      std::vector<Vec2> points;
      for (int i = tiles; i >= 0; --i) points.emplace_back(-tiles / 2.0 + i, 0);
      ShapeDef chain = ShapeDef::chain(points);
      chain.friction = friction;
      world.create_chain(ground, chain);
      break;
    }
  }
  const BodyId box = test::add_box(world, Vec2(-45.3, 0.25), 0.25, 0, friction);
  const Real weight = world.mass(box) * 10;
  for (int i = 0; i < steps; ++i) {
    // Friction plus 1 m/s^2 of acceleration.
    world.apply_force(box, Vec2(friction * weight + world.mass(box), 0), world.world_center(box));
    world.step();
  }
  EXPECT_LT(std::abs(world.angle(box)), 0.01);
  return world.linear_velocity(box).x();
}

TEST(ShapePhysics, ABoxPushedAcrossTiledBoxesAndAChainNeverCatchesOnASeam) {
  const int steps = 300;  // 5 s: about 12 m, a dozen seams
  const Real reference = pushed_speed(Floor::one_box, steps);
  EXPECT_NEAR(reference, 5.0, 0.05);
  const Real tiled = pushed_speed(Floor::tiled_boxes, steps);
  const Real chain = pushed_speed(Floor::chain, steps);
  EXPECT_NEAR(tiled, reference, 0.01 * reference);
  EXPECT_NEAR(chain, reference, 0.01 * reference);
  RecordProperty("speeds", std::to_string(reference) + " " + std::to_string(tiled) + " " +
                               std::to_string(chain));
}

}  // namespace
}  // namespace mink
