#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mink/engine/scene.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::add_box;
using test::add_ground;

Real kinetic_energy(const World& world) {
  Real energy = 0;
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) != BodyType::dynamic) continue;
    energy += 0.5 * world.mass(id) * world.linear_velocity(id).squaredNorm() +
              0.5 * world.rotational_inertia(id) * std::pow(world.angular_velocity(id), 2);
  }
  return energy;
}

Real total_energy(const World& world) {
  Real energy = kinetic_energy(world);
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) != BodyType::dynamic) continue;
    energy -= world.mass(id) * world.def().gravity.dot(world.world_center(id));
  }
  return energy;
}

TEST(Behaviour, BoxComesToRestOnTheGround) {
  World world;
  add_ground(world);
  const BodyId box = add_box(world, {0, 2}, 0.5, 0.3);
  for (int i = 0; i < 240; ++i) world.step();
  EXPECT_LT(world.linear_velocity(box).norm(), 0.01);
  EXPECT_LT(std::abs(world.angular_velocity(box)), 0.01);
  EXPECT_NEAR(world.world_center(box).y(), 0.5, 0.01);
  // Landed on a face, not balanced on a corner.
  const Real a = std::remainder(world.angle(box), std::numbers::pi / 2);
  EXPECT_NEAR(a, 0, 0.01);
  EXPECT_FALSE(world.is_awake(box));  // at rest long enough to sleep
}

TEST(Behaviour, MomentumIsConservedInZeroGravityCollisions) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  const BodyId a = add_box(world, {-3, 0.2}, 0.5, 0.1, 0.5, 0, 1);
  const BodyId b = add_box(world, {3, -0.1}, 0.7, 0.6, 0.5, 0, 3);
  const BodyId c = add_box(world, {0, 4}, 0.4, 0.0, 0.5, 0, 2);
  world.set_linear_velocity(a, Vec2(4, 0.5));
  world.set_angular_velocity(a, 2);
  world.set_linear_velocity(b, Vec2(-3, 0));
  world.set_linear_velocity(c, Vec2(0.2, -5));
  const auto momentum = [&] {
    Vec2 p(0, 0);
    Real l = 0;
    for (const BodyId id : {a, b, c}) {
      const Vec2 v = world.linear_velocity(id), x = world.world_center(id);
      p += world.mass(id) * v;
      l += world.rotational_inertia(id) * world.angular_velocity(id) +
           world.mass(id) * (x.x() * v.y() - x.y() * v.x());
    }
    return std::pair{p, l};
  };
  const auto [p0, l0] = momentum();
  std::size_t touching_steps = 0;
  for (int i = 0; i < 180; ++i) {
    world.step();
    touching_steps += world.counters().touching_contacts > 0 ? 1 : 0;
  }
  ASSERT_GT(touching_steps, 0u) << "the bodies never collided";
  const auto [p1, l1] = momentum();
  // Equal and opposite impulses: linear momentum to rounding (the solver's velocities are
  // single precision).
  EXPECT_NEAR(p1.x(), p0.x(), 1e-6 * (1 + p0.norm()));
  EXPECT_NEAR(p1.y(), p0.y(), 1e-6 * (1 + p0.norm()));
  // Angular momentum too, up to the anchors being fixed over a step.
  EXPECT_NEAR(l1, l0, 1e-2 * (1 + std::abs(l0)));
}

TEST(Behaviour, EnergyNeverGrowsWithoutRestitution) {
  World world;
  add_ground(world, 20, 0.3);
  for (int i = 0; i < 30; ++i) {
    add_box(world, {-6 + 1.2 * (i % 10), 1 + 1.3 * (i / 10) + 0.1 * (i % 3)}, 0.4, 0.2 * i, 0.3);
  }
  const Real initial = total_energy(world);
  const Real scale = std::abs(initial) + 1;
  Real previous = initial;
  Real worst_gain = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const Real energy = total_energy(world);
    ASSERT_LE(energy, initial) << "step " << i;
    worst_gain = std::max(worst_gain, energy - previous);
    previous = energy;
  }
  // Step to step, the soft contacts may push a landed box out of the overlap they allowed,
  // which is within the linear slop: at most one box's weight lifted by it (0.032 J here; the
  // largest gain seen is 0.008 J, as a box lands at step 81), never more.
  const Real box_weight = 0.8 * 0.8 * 10;  // 0.8 m square of density 1 under 10 m/s^2
  EXPECT_LE(worst_gain, box_weight * world.def().linear_slop);
  EXPECT_LT(previous, initial - 0.1 * scale);  // the boxes fell and settled
}

TEST(Behaviour, EnergyNeverGrowsInZeroGravityCollisions) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  for (int i = 0; i < 12; ++i) {
    const BodyId b = add_box(world, {1.2 * (i % 4), 1.2 * (i / 4)}, 0.4, 0.3 * i, 0.4);
    world.set_linear_velocity(b, Vec2(std::cos(i * 1.7), std::sin(i * 2.3)) * 3);
  }
  Real previous = kinetic_energy(world);
  for (int i = 0; i < 400; ++i) {
    world.step();
    const Real energy = kinetic_energy(world);
    // Never more than the rounding of single-precision solver velocities.
    EXPECT_LE(energy, previous * (1 + 1e-6) + 1e-12) << "step " << i;
    previous = energy;
  }
}

// A box on a 20 degree ramp: friction 0.6 exceeds tan(20 deg) = 0.36 and holds it, 0.1 does
// not.
Real slide_distance(Real friction) {
  World world;
  const Real slope = 20 * std::numbers::pi / 180;
  const BodyId ramp = world.create_body({});
  ShapeDef ramp_shape = ShapeDef::box(30, 0.5, Vec2(0, -0.5));
  ramp_shape.friction = friction;
  world.create_shape(ramp, ramp_shape);
  world.set_transform(ramp, Vec2(0, 0), -slope);
  // Resting on the ramp surface (the line through the origin at -20 degrees).
  const Vec2 along(std::cos(slope), -std::sin(slope)), up(std::sin(slope), std::cos(slope));
  const Vec2 start = -5 * along + 0.5 * up;
  const BodyId box = add_box(world, start, 0.5, -slope, friction);
  for (int i = 0; i < 120; ++i) world.step();
  return (world.position(box) - start).dot(along);
}

TEST(Behaviour, BoxStaysOnATwentyDegreeSlopeWithFrictionPointSix) {
  EXPECT_LT(std::abs(slide_distance(0.6)), 0.02);
}

TEST(Behaviour, BoxSlidesDownATwentyDegreeSlopeWithFrictionPointOne) {
  // a = g (sin 20 - 0.1 cos 20) = 2.48 m/s^2: 4.96 m in 2 s.
  EXPECT_NEAR(slide_distance(0.1), 4.96, 0.3);
}

TEST(Behaviour, RestitutionOneBouncesBackNearItsHeight) {
  World world;
  const BodyId ground = add_ground(world);
  world.create_shape(ground, [] {
    ShapeDef s = ShapeDef::box(1, 0.1, Vec2(0, -0.1));
    s.restitution = 1;
    return s;
  }());
  const Real drop = 3;
  const BodyId box = add_box(world, {0, 0.5 + drop}, 0.5, 0, 0.6, 1);
  bool bounced = false;
  Real apex = 0;
  for (int i = 0; i < 150; ++i) {
    world.step();
    const Real vy = world.linear_velocity(box).y();
    if (vy > 0) bounced = true;
    if (bounced) apex = std::max(apex, world.position(box).y() - 0.5);
  }
  ASSERT_TRUE(bounced);
  EXPECT_GT(apex, 0.9 * drop);
  EXPECT_LT(apex, 1.02 * drop);  // and no energy from nowhere
}

TEST(Behaviour, RestitutionBelowThresholdDoesNotBounce) {
  World world;
  add_ground(world);
  const BodyId box = add_box(world, {0, 0.52}, 0.5, 0, 0.6, 1);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_LT(world.linear_velocity(box).norm(), 0.05);
}

TEST(Behaviour, RainGivesNoNanAndNothingBelowTheFloor) {
  const int steps = test::long_run(10000, 1000);
  World world = build_world(rain_scene(120, 3));
  const std::vector<BodyId> bodies = world.bodies();
  for (int i = 0; i < steps; ++i) {
    world.step();
    if (i % 50 != 49 && i != steps - 1) continue;
    for (const BodyId id : bodies) {
      ASSERT_TRUE(test::finite_state(world, id)) << "step " << i;
      if (world.body_type(id) != BodyType::dynamic) continue;
      ASSERT_GT(world.world_center(id).y(), 0) << "step " << i;
      for (const ShapeId s : world.body_shapes(id)) {
        ASSERT_GT(world.shape_aabb(s).lower.y(), -0.05) << "step " << i;
      }
    }
  }
}

TEST(Behaviour, FastBoxDoesNotTunnelThroughAThinWall) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  const BodyId wall = world.create_body({});
  world.create_shape(wall, ShapeDef::box(0.025, 2, Vec2(5, 0)));
  const BodyId bullet = add_box(world, {0, 0}, 0.1);
  world.set_linear_velocity(bullet, Vec2(120, 0));  // 2 m per step, forty times the wall
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_LT(world.position(bullet).x(), 5 - 0.025);
}

TEST(Behaviour, FastBoxDoesNotTunnelThroughAThinFloor) {
  World world;
  const BodyId floor = world.create_body({});
  world.create_shape(floor, ShapeDef::box(5, 0.02));
  const BodyId box = add_box(world, {0, 10}, 0.25);
  world.set_linear_velocity(box, Vec2(0, -60));
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_GT(world.position(box).y(), 0);
  EXPECT_NEAR(world.position(box).y(), 0.27, 0.02);
}

TEST(Behaviour, KinematicBodyMovesAtItsVelocityAndPushes) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  BodyDef pusher_def;
  pusher_def.type = BodyType::kinematic;
  pusher_def.linear_velocity = Vec2(2, 0);
  const BodyId pusher = world.create_body(pusher_def);
  world.create_shape(pusher, ShapeDef::box(0.5, 1));
  const BodyId box = add_box(world, {2, 0}, 0.5);
  for (int i = 0; i < 60; ++i) world.step();
  // Each step's motion is rounded to the position grid.
  EXPECT_NEAR(world.position(pusher).x(), 2, 60 * position_grid_step);
  EXPECT_NEAR(world.linear_velocity(pusher).x(), 2, 1e-12);
  EXPECT_GT(world.position(box).x(), 2.9);  // pushed ahead, not overlapped
}

TEST(Behaviour, DestroyingBodiesMidContactIsSafe) {
  World world;
  const BodyId ground = add_ground(world);
  std::vector<BodyId> boxes;
  for (int row = 0; row < 5; ++row) {
    for (int i = 0; i < 5; ++i) boxes.push_back(add_box(world, {i * 1.0 - 2, 0.5 + row}, 0.5));
  }
  for (int i = 0; i < 30; ++i) world.step();
  ASSERT_GT(world.counters().touching_contacts, 20u);
  // Destroy a supporting box, a shape of another, then step and destroy more mid-stack.
  const ShapeId ground_shape = world.body_shapes(ground)[0];
  const ShapeId below = world.body_shapes(boxes[2])[0];   // bottom row, middle
  const ShapeId above = world.body_shapes(boxes[7])[0];   // on top of it
  const ShapeId third = world.body_shapes(boxes[12])[0];  // on top of that
  world.destroy_body(boxes[2]);
  world.destroy_shape(above);
  // The touching contacts of both at once end, each with an event naming the gone shape.
  const auto end_events = world.contact_end_events();
  const auto ended = [&](ShapeId a, ShapeId b) {
    return std::any_of(end_events.begin(), end_events.end(), [&](const ContactEndEvent& e) {
      return (e.shape_a == a && e.shape_b == b) || (e.shape_a == b && e.shape_b == a);
    });
  };
  for (const ContactEndEvent& e : end_events) {
    EXPECT_TRUE(e.shape_a == below || e.shape_b == below || e.shape_a == above ||
                e.shape_b == above);
  }
  EXPECT_TRUE(ended(below, ground_shape));
  EXPECT_TRUE(ended(below, above));
  EXPECT_TRUE(ended(above, third));
  std::size_t ends = end_events.size();
  for (int i = 0; i < 10; ++i) world.step();
  world.destroy_body(boxes[12]);
  ends += world.contact_end_events().size();
  // New bodies take the freed slots.
  const BodyId fresh = add_box(world, {0, 8}, 0.5);
  for (int i = 0; i < 120; ++i) {
    world.step();
    if (i == 5) world.destroy_body(boxes[17]);
  }
  EXPECT_GT(ends, 0u);
  for (const BodyId id : world.bodies()) EXPECT_TRUE(test::finite_state(world, id));
  EXPECT_TRUE(world.is_valid(fresh));
  EXPECT_FALSE(world.is_valid(boxes[2]));
  // A body without shapes is fine too; it falls freely.
  EXPECT_TRUE(world.is_valid(boxes[7]));
  EXPECT_LT(world.position(boxes[7]).y(), -5);
}

}  // namespace
}  // namespace mink
