// Gear and pulley joints against their kinematics: geared coordinates keep their combination
// (through full turns, with shared bodies, rack and pinion), pulleys balance and accelerate as
// Atwood's machine; and a gear dies with its joints.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::kGravity;

using test::add_ball;
using test::add_body;
using test::free_world;

// Two wheels pinned to the ground, the first driven at 1 rad/s; geared with ratio 2 after the
// first has turned, so the held combination is not 0; run past a full turn (angles count turns).
TEST(GearJoint, TwoRevoluteJointsTurnInRatio) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel1 = add_ball(world, {0, 0}, 1);
  const BodyId wheel2 = add_ball(world, {3, 0}, 1);
  RevoluteJointDef driven = revolute_joint_at(world, ground, wheel1, {0, 0});
  driven.motor = {true, 1, 1000};
  const JointId joint1 = world.create_joint(driven);
  const JointId joint2 = world.create_joint(revolute_joint_at(world, ground, wheel2, {3, 0}));
  for (int i = 0; i < 30; ++i) world.step();
  const Real start1 = world.joint_coordinate(joint1), start2 = world.joint_coordinate(joint2);
  ASSERT_GT(start1, 0.4);
  GearJointDef gear_def;
  gear_def.joint1 = joint1;
  gear_def.joint2 = joint2;
  gear_def.ratio = 2;
  const JointId gear = world.create_joint(gear_def);
  const Real held = start1 + 2 * start2;
  EXPECT_NEAR(world.joint_coordinate(gear), held, 1e-12);
  for (int i = 0; i < 480; ++i) world.step();
  const Real angle1 = world.joint_coordinate(joint1), angle2 = world.joint_coordinate(joint2);
  EXPECT_GT(angle1, 2 * 3.14159);  // past a full turn
  const Real turned1 = angle1 - start1, turned2 = angle2 - start2;
  EXPECT_NEAR(turned2, -turned1 / 2, 0.01 * turned1 / 2);
  EXPECT_NEAR(angle1 + 2 * angle2, held, 1e-3);
  // The gear reports the combination its joints have.
  EXPECT_NEAR(world.joint_coordinate(gear), angle1 + 2 * angle2, 1e-9);
  EXPECT_NEAR(world.angular_velocity(wheel2), -world.angular_velocity(wheel1) / 2, 1e-3);
  RecordProperty("turned1", std::to_string(turned1));
  RecordProperty("turned2", std::to_string(turned2));
  RecordProperty("drift", std::to_string(angle1 + 2 * angle2 - held));
}

// A wheel pinned to the ground spinning at 230 rad/s (under the solver's cap of an eighth of a
// turn per substep) turns more than half a turn a step: its joint's angle still counts every
// turn, which the poses alone cannot tell. Each substep turns the rotation by atan(h w) (its
// integration: q += h w perp(q), renormalised), the closed form the angle is checked against.
TEST(GearJoint, FastRevoluteAngleCountsTurns) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel = add_ball(world, {0, 0}, 0.5);
  const JointId joint = world.create_joint(revolute_joint_at(world, ground, wheel, {0, 0}));
  const Real speed = 230;
  world.set_angular_velocity(wheel, speed);
  const Real h = world.def().time_step / world.def().substeps;
  const Real per_step = world.def().substeps * std::atan(h * speed);
  ASSERT_GT(per_step, 3.14159);
  const int steps = 30;
  for (int i = 0; i < steps; ++i) world.step();
  EXPECT_NEAR(world.angular_velocity(wheel), speed, 1e-3 * speed);
  EXPECT_NEAR(world.joint_coordinate(joint), steps * per_step, 1e-4 * steps * per_step);
}

// Two wheels pinned to the ground and geared (ratio 2), the first spinning at 230 rad/s
// (more than half a turn a step), beside a stopped kinematic bar pressed 1 cm into it. The
// gear holds its combination through the fast turns (a lost turn in a joint's angle would be
// an error of a whole turn, pushed out at the joint stiffness), and the pair gains no energy.
TEST(GearJoint, FastGearedWheelsHoldTheirCombinationAndGainNoEnergy) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel1 = add_ball(world, {0, 5}, 0.5);
  const BodyId wheel2 = add_ball(world, {3, 5}, 0.5);
  BodyDef bar_def;
  bar_def.type = BodyType::kinematic;
  bar_def.position = Vec2(0, 4.2);
  world.create_shape(world.create_body(bar_def), ShapeDef::box(1, 0.31));
  const JointId joint1 = world.create_joint(revolute_joint_at(world, ground, wheel1, {0, 5}));
  const JointId joint2 = world.create_joint(revolute_joint_at(world, ground, wheel2, {3, 5}));
  GearJointDef gear_def;
  gear_def.joint1 = joint1;
  gear_def.joint2 = joint2;
  gear_def.ratio = 2;
  world.create_joint(gear_def);
  world.set_angular_velocity(wheel1, 230);
  world.set_angular_velocity(wheel2, -115);
  const auto energy = [&] {
    Real e = 0;
    for (const BodyId body : {wheel1, wheel2}) {
      const Real w = world.angular_velocity(body);
      e += 0.5 * world.mass(body) * world.linear_velocity(body).squaredNorm() +
           0.5 * world.rotational_inertia(body) * w * w -
           world.mass(body) * world.def().gravity.dot(world.world_center(body));
    }
    return e;
  };
  const Real start = energy();
  Real highest = start, worst_drift = 0;
  for (int i = 0; i < 60; ++i) {
    world.step();
    highest = std::max(highest, energy());
    const Real drift = world.joint_coordinate(joint1) + 2 * world.joint_coordinate(joint2);
    worst_drift = std::max(worst_drift, std::abs(drift));
  }
  EXPECT_LE(highest, start + 1e-3 * start) << "energy rose from " << start;
  // The substeps' turns, atan(h w), are not in the ratio of the speeds: a fraction of a
  // radian of drift, held by the gear's soft row; a lost turn would be 2 pi.
  EXPECT_LT(worst_drift, 1);
  EXPECT_NEAR(world.angular_velocity(wheel2), -world.angular_velocity(wheel1) / 2, 1e-2);
  RecordProperty("worst_drift", std::to_string(worst_drift));
}

// Two wheels on one free chassis (both joints' A is the same moving body): the gear's row has
// the chassis once with both joints' coefficients, so one step leaves its rate at 0.
TEST(GearJoint, WheelsOnOneChassisShareItsTerm) {
  WorldDef def = free_world();
  def.gravity = {0, 0};
  World world(def);
  const BodyId chassis = add_body(world, {0, 0}, ShapeDef::box(2, 0.25));
  const BodyId wheel1 = add_ball(world, {-2, 0}, 0.5);
  const BodyId wheel2 = add_ball(world, {2, 0}, 0.5);
  const JointId joint1 = world.create_joint(revolute_joint_at(world, chassis, wheel1, {-2, 0}));
  const JointId joint2 = world.create_joint(revolute_joint_at(world, chassis, wheel2, {2, 0}));
  GearJointDef gear_def;
  gear_def.joint1 = joint1;
  gear_def.joint2 = joint2;
  world.create_joint(gear_def);
  world.set_angular_velocity(wheel1, 5);
  world.step();
  const Real w1 = world.angular_velocity(wheel1), w2 = world.angular_velocity(wheel2);
  const Real wc = world.angular_velocity(chassis);
  EXPECT_GT(std::abs(w1), 0.5);
  EXPECT_NEAR((w1 - wc) + (w2 - wc), 0, 1e-6);  // the solver's single precision
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_NEAR(world.joint_coordinate(joint1) + world.joint_coordinate(joint2), 0, 1e-3);
  RecordProperty("rate", std::to_string((w1 - wc) + (w2 - wc)));
}

// A pinion driven at 1 rad/s moves a rack on a prismatic joint: translation + ratio * angle
// stays 0, so the rack moves -ratio * angle.
TEST(GearJoint, RackAndPinion) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId pinion = add_ball(world, {0, 0}, 1);
  const BodyId rack = add_body(world, {0, -3}, ShapeDef::box(2, 0.25));
  const JointId slide =
      world.create_joint(prismatic_joint_at(world, ground, rack, {0, -3}, {1, 0}));
  RevoluteJointDef driven = revolute_joint_at(world, ground, pinion, {0, 0});
  driven.motor = {true, 1, 1000};
  const JointId turn = world.create_joint(driven);
  GearJointDef gear_def;
  gear_def.joint1 = slide;
  gear_def.joint2 = turn;
  gear_def.ratio = 0.5;
  world.create_joint(gear_def);
  for (int i = 0; i < 120; ++i) world.step();
  const Real angle = world.joint_coordinate(turn);
  const Real translation = world.position(rack).x();  // the axis is x, from x = 0
  EXPECT_GT(angle, 1.5);
  EXPECT_NEAR(translation, -0.5 * angle, 0.01 * 0.5 * angle);
  EXPECT_NEAR(world.position(rack).y(), -3, 1e-3);
  RecordProperty("angle", std::to_string(angle));
  RecordProperty("translation", std::to_string(translation));
}

TEST(GearJoint, DestroyingOneOfItsJointsDestroysTheGear) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel1 = add_ball(world, {0, 0}, 1);
  const BodyId wheel2 = add_ball(world, {3, 0}, 1);
  const JointId joint1 = world.create_joint(revolute_joint_at(world, ground, wheel1, {0, 0}));
  const JointId joint2 = world.create_joint(revolute_joint_at(world, ground, wheel2, {3, 0}));
  GearJointDef gear_def;
  gear_def.joint1 = joint1;
  gear_def.joint2 = joint2;
  const JointId gear = world.create_joint(gear_def);
  world.step();
  ASSERT_TRUE(world.is_valid(gear));
  world.destroy_joint(joint2);
  EXPECT_FALSE(world.is_valid(gear));
  EXPECT_TRUE(world.is_valid(joint1));
  EXPECT_EQ(world.joint_count(), 1u);
  // Wheel 1 is free of the gear: spun, it keeps its speed.
  world.set_angular_velocity(wheel1, 2);
  world.step();
  EXPECT_NEAR(world.angular_velocity(wheel1), 2, 1e-9);
}

// Two balls on ropes over ground points 4 m apart, the ropes vertical.
struct Atwood {
  World world{free_world()};
  BodyId a, b;
  JointId pulley;
  Atwood(Real density_a, Real density_b, Real ratio = 1) {
    a = add_ball(world, {-2, 5}, 0.5, density_a);
    b = add_ball(world, {2, 5}, 0.5, density_b);
    pulley =
        world.create_joint(pulley_joint_at(world, a, b, {-2, 10}, {2, 10}, {-2, 5}, {2, 5}, ratio));
  }
};

TEST(PulleyJoint, EqualMassesStayInEquilibrium) {
  Atwood atwood(1, 1);
  World& world = atwood.world;
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_NEAR(world.position(atwood.a).y(), 5, 1e-3);
  EXPECT_NEAR(world.position(atwood.b).y(), 5, 1e-3);
  EXPECT_NEAR(world.linear_velocity(atwood.b).y(), 0, 1e-3);
  // Each rope carries its ball's weight.
  EXPECT_NEAR(world.joint_force(atwood.pulley).y(), world.mass(atwood.b) * kGravity,
              0.01 * world.mass(atwood.b) * kGravity);
}

// With ratio 2, B's rope pulls twice as hard as A's: B of twice A's mass balances.
TEST(PulleyJoint, ARatioOfTwoBalancesTwiceTheMass) {
  Atwood atwood(1, 2, 2);
  World& world = atwood.world;
  for (int i = 0; i < 120; ++i) world.step();
  EXPECT_NEAR(world.position(atwood.a).y(), 5, 1e-3);
  EXPECT_NEAR(world.position(atwood.b).y(), 5, 1e-3);
  EXPECT_NEAR(world.joint_coordinate(atwood.pulley), 15, 1e-3);
}

// Atwood's machine: masses m and 2m accelerate at g (2m - m) / 3m = g / 3; the rope tension
// is 4 m g / 3.
TEST(PulleyJoint, HeavierSideAcceleratesAtAThirdOfG) {
  Atwood atwood(1, 2);
  World& world = atwood.world;
  const Real held = world.joint_coordinate(atwood.pulley);
  EXPECT_NEAR(held, 10, 1e-12);
  Real drift = 0, v0 = 0, t0 = 0;
  const int steps = 42;  // 0.7 s: from 0.2 s to 0.7 s measured
  for (int i = 0; i < steps; ++i) {
    world.step();
    drift = std::max(drift, std::abs(world.joint_coordinate(atwood.pulley) - held));
    if (i == 11) {
      v0 = world.linear_velocity(atwood.b).y();
      t0 = world.time();
    }
  }
  const Real acceleration = -(world.linear_velocity(atwood.b).y() - v0) / (world.time() - t0);
  EXPECT_NEAR(acceleration, kGravity / 3, 0.02 * kGravity / 3);
  EXPECT_NEAR(world.linear_velocity(atwood.a).y(), -world.linear_velocity(atwood.b).y(), 1e-3);
  EXPECT_LT(drift, 1e-3);
  const Real m = world.mass(atwood.a);
  EXPECT_NEAR(world.joint_force(atwood.pulley).y(), 4 * m * kGravity / 3,
              0.02 * 4 * m * kGravity / 3);
  RecordProperty("acceleration", std::to_string(acceleration));
  RecordProperty("drift", std::to_string(drift));
}

}  // namespace
}  // namespace mink
