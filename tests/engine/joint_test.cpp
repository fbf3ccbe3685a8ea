// Joints against closed-form physics: pendulum periods, motor speeds and stalls, limits,
// ropes and gears; and their life cycle (destroyed with their bodies, sleeping and waking).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

constexpr Real kGravity = 10;

WorldDef free_world() {
  WorldDef def;
  def.enable_sleep = false;
  return def;
}

BodyId add_ball(World& world, const Vec2& position, Real radius, Real density = 1) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  const BodyId body = world.create_body(def);
  ShapeDef shape = ShapeDef::circle(radius);
  shape.density = density;
  world.create_shape(body, shape);
  return body;
}

// Times between upward zero crossings of x (the bob passing the bottom moving right), averaged.
Real measured_period(World& world, BodyId bob, Real pivot_x, Real seconds) {
  std::vector<Real> crossings;
  Real previous = world.world_center(bob).x() - pivot_x;
  const int steps = static_cast<int>(seconds / world.def().time_step);
  for (int i = 0; i < steps; ++i) {
    world.step();
    const Real x = world.world_center(bob).x() - pivot_x;
    if (previous < 0 && x >= 0) {
      // Linear interpolation of the crossing time within the step.
      const Real t = world.time() - world.def().time_step * x / (x - previous);
      crossings.push_back(t);
    }
    previous = x;
  }
  if (crossings.size() < 2) return 0;
  return (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
}

// A small bob on a light rod of length L, released at 5 degrees: T = 2 pi sqrt(L / g) (the
// finite amplitude lengthens it by 0.05%, the bob's own inertia by (2/5)(r/L)^2 / 2).
TEST(Pendulum, ARevoluteJointSwingsWithTheSimplePendulumPeriod) {
  World world(free_world());
  const Real length = 2, amplitude = 5 * std::numbers::pi / 180;
  const BodyId ground = world.create_body({});
  const Vec2 pivot(0, 10);
  // The rod: a light, thin body from the pivot to the bob, welded to the bob by shape.
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = pivot + length * Vec2(std::sin(amplitude), -std::cos(amplitude));
  const BodyId bob = world.create_body(def);
  world.create_shape(bob, ShapeDef::circle(0.05));
  world.create_joint(revolute_joint_at(world, ground, bob, pivot));
  const Real period = measured_period(world, bob, pivot.x(), 20);
  const Real expected = 2 * std::numbers::pi * std::sqrt(length / kGravity);
  EXPECT_NEAR(period, expected, 0.01 * expected);
  RecordProperty("period", std::to_string(period));
}

TEST(Pendulum, ADistanceJointSwingsWithTheSimplePendulumPeriod) {
  World world(free_world());
  const Real length = 2, amplitude = 5 * std::numbers::pi / 180;
  const BodyId ground = world.create_body({});
  const Vec2 pivot(0, 10);
  const BodyId bob =
      add_ball(world, pivot + length * Vec2(std::sin(amplitude), -std::cos(amplitude)), 0.05);
  world.create_joint(distance_joint_at(world, ground, bob, pivot, world.world_center(bob)));
  const Real period = measured_period(world, bob, pivot.x(), 20);
  const Real expected = 2 * std::numbers::pi * std::sqrt(length / kGravity);
  EXPECT_NEAR(period, expected, 0.01 * expected);
  RecordProperty("period", std::to_string(period));
}

}  // namespace
}  // namespace mink
