// Joints against closed-form physics: pendulum periods, motor speeds and stalls, limits,
// ropes and gears; and their life cycle (destroyed with their bodies, sleeping and waking).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "joint_common.hpp"
#include "mink/engine/stale_id_error.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::kGravity;

using test::add_ball;
using test::free_world;

// The joint rows' arc tangent against the C library's in double precision: within 4e-7 rad
// over random directions of every octant and scale, and within 3e-7 of the angle relative to it
// for small angles (a limit or spring near zero), about two ulps of single precision (glibc's
// atan2f: 2.5e-7 and 1.1e-7); exact at the axes, NaN for NaN.
TEST(JointAngle, SolverArcTangentAgreesWithTheLibrarysInDoublePrecision) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1, 1);
  std::uniform_real_distribution<float> exponent(-30, 30);
  double worst = 0;
  for (int i = 0; i < 1000000; ++i) {
    const float scale = std::exp2(exponent(random));
    const float y = unit(random) * scale, x = unit(random) * scale;
    const double exact = std::atan2(double{y}, double{x});
    worst = std::max(worst, std::abs(double{detail::solver_atan2(y, x)} - exact));
  }
  EXPECT_LT(worst, 4e-7);
  double worst_relative = 0;
  for (int i = 0; i < 100000; ++i) {
    const double angle = std::exp2(-24 + 24 * (unit(random) + 1) / 2) * (i % 2 ? 1 : -1);
    const auto y = static_cast<float>(std::sin(angle)), x = static_cast<float>(std::cos(angle));
    const double exact = std::atan2(double{y}, double{x});
    worst_relative = std::max(
        worst_relative, std::abs(double{detail::solver_atan2(y, x)} - exact) / std::abs(exact));
  }
  EXPECT_LT(worst_relative, 3e-7);
  EXPECT_EQ(detail::solver_atan2(0, 1), 0);
  EXPECT_EQ(detail::solver_atan2(0, 0), 0);
  EXPECT_FLOAT_EQ(detail::solver_atan2(1, 0), std::numbers::pi_v<float> / 2);
  EXPECT_FLOAT_EQ(detail::solver_atan2(-1, 0), -std::numbers::pi_v<float> / 2);
  EXPECT_FLOAT_EQ(detail::solver_atan2(0, -1), std::numbers::pi_v<float>);
  EXPECT_TRUE(std::isnan(detail::solver_atan2(std::numeric_limits<float>::quiet_NaN(), 1)));
  EXPECT_TRUE(std::isnan(detail::solver_atan2(1, std::numeric_limits<float>::quiet_NaN())));
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

namespace mink {
namespace {

// A disk pinned at its centre, driven by a revolute motor against a steady opposing torque.
struct MotorRig {
  World world{free_world()};
  BodyId disk;
  JointId joint;
  MotorRig(Real speed, Real max_torque) {
    const BodyId ground = world.create_body({});
    disk = add_ball(world, Vec2(0, 5), 0.5);
    RevoluteJointDef def = revolute_joint_at(world, ground, disk, Vec2(0, 5));
    def.motor = {true, speed, max_torque};
    joint = world.create_joint(def);
  }
  void run(Real seconds, Real load) {
    const int steps = static_cast<int>(seconds / world.def().time_step);
    for (int i = 0; i < steps; ++i) {
      world.apply_torque(disk, -load);
      world.step();
    }
  }
};

TEST(RevoluteMotor, ReachesItsSpeedAndHoldsItUnderALoadBelowItsMaxTorque) {
  MotorRig rig(3, 10);
  rig.run(1, 0);
  EXPECT_NEAR(rig.world.joint_speed(rig.joint), 3, 0.03);
  rig.run(2, 8);  // 80% of the motor's torque
  EXPECT_NEAR(rig.world.joint_speed(rig.joint), 3, 0.03);
  // The motor's torque balances the load.
  EXPECT_NEAR(rig.world.joint_torque(rig.joint), 8, 0.08);
}

TEST(RevoluteMotor, StallsUnderALoadAboveItsMaxTorque) {
  MotorRig rig(3, 10);
  rig.run(1, 0);
  rig.run(2, 12);  // the net torque 10 - 12 turns the disk backwards
  const Real inertia = rig.world.rotational_inertia(rig.disk);
  // Decelerating at (12 - 10) / I from 3 rad/s for 2 s.
  const Real expected = 3 - 2 * (12 - 10) / inertia;
  EXPECT_LT(rig.world.joint_speed(rig.joint), 0);
  EXPECT_NEAR(rig.world.joint_speed(rig.joint), expected, 0.02 * std::abs(expected));
  // At its bound, to the rows' single precision.
  EXPECT_NEAR(rig.world.joint_torque(rig.joint), 10, 10 * 1e-6);
}

TEST(Rope, ADistanceJointWithAMaxLengthNeverStretchesBeyondTheLinearSlop) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const Vec2 pivot(0, 10);
  const Real rope = 3;
  // Released beside the pivot with the rope slack: it falls, the rope snaps taut, it swings.
  const BodyId bob = add_ball(world, pivot + Vec2(1.5, 0), 0.1, 5);
  DistanceJointDef def = distance_joint_at(world, ground, bob, pivot, world.world_center(bob));
  def.length = rope;
  def.limit = {true, 0, rope};
  world.create_joint(def);
  Real longest = 0, shortest = rope;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const Real length = (world.world_center(bob) - pivot).norm();
    longest = std::max(longest, length);
    shortest = std::min(shortest, length);
  }
  EXPECT_LE(longest, rope + world.def().linear_slop);
  EXPECT_GT(longest, rope - 0.01);  // it did go taut
  EXPECT_LT(shortest, 1.6);         // and was slack at first
  RecordProperty("longest", std::to_string(longest));
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// A chain of `links` capsules (each `link` long, light) pinned at the top to a static body,
// starting horizontal, with a ball `ratio` times a link's mass hanging from its end.
// Box2D's own scheme as well, one joint at a time, for comparison.
WorldDef chain_world(bool direct) {
  WorldDef def = free_world();
  def.direct_joint_chains = direct;
  return def;
}

Vec2 direction_at(Real degrees) {
  return {std::cos(degrees * std::numbers::pi / 180), std::sin(degrees * std::numbers::pi / 180)};
}

struct HangingChain {
  World world;
  std::vector<JointId> joints;
  Real length = 0;
  // `direction` is the unit vector the chain is laid out along from its pin.
  HangingChain(int links, Real ratio, const Vec2& direction, bool direct = true, Real link = 0.5)
      : world(chain_world(direct)) {
    const BodyId ground = world.create_body({});
    const Real radius = 0.05;
    BodyId previous = ground;
    const Vec2 top(0, 20);
    const Real angle = std::atan2(direction.y(), direction.x());
    ShapeDef capsule = ShapeDef::capsule(Vec2(-0.5 * link, 0), Vec2(0.5 * link, 0), radius);
    for (int i = 0; i < links; ++i) {
      BodyDef def;
      def.type = BodyType::dynamic;
      def.position = top + (i + 0.5) * link * direction;
      def.angle = angle;
      const BodyId body = world.create_body(def);
      world.create_shape(body, capsule);
      joints.push_back(
          world.create_joint(revolute_joint_at(world, previous, body, top + i * link * direction)));
      previous = body;
    }
    const Real link_mass = world.mass(previous);
    BodyDef def;
    def.type = BodyType::dynamic;
    def.position = top + (links * link + 0.25) * direction;
    const BodyId weight = world.create_body(def);
    ShapeDef ball = ShapeDef::circle(0.25);
    ball.density = ratio * link_mass / (std::numbers::pi * 0.25 * 0.25);
    world.create_shape(weight, ball);
    joints.push_back(world.create_joint(
        revolute_joint_at(world, previous, weight, top + links * link * direction)));
    length = links * link;
  }
  // How far the joints have come apart, summed: the chain's stretch.
  Real stretch() const {
    Real gap = 0;
    for (const JointId j : joints)
      gap += (world.joint_anchor_b(j) - world.joint_anchor_a(j)).norm();
    return gap;
  }
  Real run(Real seconds) {
    Real worst = 0;
    const int steps = static_cast<int>(seconds / world.def().time_step);
    for (int i = 0; i < steps; ++i) {
      world.step();
      worst = std::max(worst, stretch());
    }
    return worst;
  }
};

// Laid out horizontally and let fall: the weight swings the chain through its lowest point.
TEST(MassRatio, AThirtyLinkChainHoldsAHundredTimesALinksMassWithinOnePercent) {
  HangingChain chain(30, 100, direction_at(0));
  const Real worst = chain.run(10);
  std::printf("30 links, 100:1: stretch after 10 s %.4f m, worst %.4f m of %.1f m\n",
              chain.stretch(), worst, chain.length);
  EXPECT_LE(chain.stretch(), 0.01 * chain.length);
  EXPECT_LE(worst, 0.01 * chain.length);
}

// From 45 degrees below the horizontal (a straight horizontal chain cannot hold a weight at
// all: the tension it would need grows without bound).
TEST(MassRatio, ATenLinkChainHoldsAThousandTimesALinksMassWithinFivePercent) {
  HangingChain chain(10, 1000, direction_at(-45));
  const Real worst = chain.run(10);
  std::printf("10 links, 1000:1: stretch after 10 s %.4f m, worst %.4f m of %.1f m\n",
              chain.stretch(), worst, chain.length);
  EXPECT_LE(chain.stretch(), 0.05 * chain.length);
  EXPECT_LE(worst, 0.05 * chain.length);
}

// The same chains one joint at a time stretch far more: the reason for the direct solve.
TEST(MassRatio, OneJointAtATimeTheSameChainsStretch) {
  HangingChain thirty(30, 100, direction_at(0), false);
  HangingChain ten(10, 1000, direction_at(-45), false);
  thirty.run(10);
  ten.run(10);
  std::printf("one joint at a time: 30 links, 100:1 stretch %.4f m; 10 links, 1000:1 %.4f m\n",
              thirty.stretch(), ten.stretch());
  EXPECT_GT(thirty.stretch(), 0.01 * thirty.length);
  EXPECT_GT(ten.stretch(), 0.05 * ten.length);
}

// At rest every joint carries the weight of what hangs below it, whichever way it is solved.
TEST(MassRatio, AHangingChainsJointForcesAreTheWeightBelowThem) {
  for (const bool direct : {true, false}) {
    HangingChain chain(8, 20, direction_at(-90), direct);
    chain.run(3);
    const std::vector<BodyId> bodies = chain.world.bodies();
    for (std::size_t k = 0; k < chain.joints.size(); ++k) {
      Real below = 0;
      for (std::size_t b = k + 1; b < bodies.size(); ++b) below += chain.world.mass(bodies[b]);
      const Vec2 force = chain.world.joint_force(chain.joints[k]);
      // The joint pulls body B (below) up.
      EXPECT_NEAR(force.y(), kGravity * below, 0.01 * kGravity * below)
          << "joint " << k << (direct ? " (direct)" : " (one at a time)");
      EXPECT_NEAR(force.x(), 0, 1e-3 * kGravity * below);
    }
  }
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

TEST(JointLife, DestroyingABodyDestroysItsJointsAndTheirGears) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId a = add_ball(world, Vec2(0, 0), 0.5);
  const BodyId b = add_ball(world, Vec2(2, 0), 0.5);
  const JointId ja = world.create_joint(revolute_joint_at(world, ground, a, Vec2(0, 0)));
  const JointId jb = world.create_joint(revolute_joint_at(world, ground, b, Vec2(2, 0)));
  GearJointDef gear;
  gear.joint1 = ja;
  gear.joint2 = jb;
  const JointId jg = world.create_joint(gear);
  EXPECT_EQ(world.joint_count(), 3u);
  EXPECT_EQ(world.body_joints(ground).size(), 3u);  // the gear acts on the ground too
  world.destroy_body(a);
  EXPECT_FALSE(world.is_valid(ja));
  EXPECT_FALSE(world.is_valid(jg));
  EXPECT_TRUE(world.is_valid(jb));
  EXPECT_EQ(world.joint_count(), 1u);
  EXPECT_EQ(world.body_joints(ground), std::vector<JointId>{jb});
  EXPECT_THROW(world.joint_type(ja), StaleIdError);
  for (int i = 0; i < 10; ++i) world.step();
  EXPECT_TRUE(test::finite_state(world, b));
}

TEST(JointLife, JointedBodiesDoNotCollideUnlessAsked) {
  for (const bool collide : {false, true}) {
    World world(free_world());
    test::add_ground(world);
    // Two overlapping boxes pinned together at their common centre.
    const BodyId a = test::add_box(world, Vec2(0, 3));
    const BodyId b = test::add_box(world, Vec2(0.3, 3));
    RevoluteJointDef def = revolute_joint_at(world, a, b, Vec2(0.15, 3));
    def.collide_connected = collide;
    world.create_joint(def);
    world.step();
    bool touching = false;
    for (const ContactData& c : world.body_contacts(a)) {
      touching = touching || world.shape_body(c.shape_b) == b || world.shape_body(c.shape_a) == b;
    }
    EXPECT_EQ(touching, collide);
  }
}

TEST(JointLife, AHangingChainSleepsAndWakesWhenTouched) {
  World world;  // sleeping on
  const BodyId ground = world.create_body({});
  BodyId previous = ground;
  std::vector<BodyId> links;
  for (int i = 0; i < 5; ++i) {
    const BodyId link = add_ball(world, Vec2(0, 10 - 0.5 * (i + 1)), 0.2);
    world.create_joint(revolute_joint_at(world, previous, link, Vec2(0, 10 - 0.5 * i - 0.25)));
    links.push_back(link);
    previous = link;
  }
  for (int i = 0; i < 300; ++i) world.step();
  for (const BodyId link : links) EXPECT_FALSE(world.is_awake(link));
  // A ball dropped on the last link wakes the whole chain through its joints.
  const BodyId ball = add_ball(world, Vec2(0, 8), 0.1);
  bool woke = false;
  for (int i = 0; i < 60 && !woke; ++i) {
    world.step();
    woke = world.is_awake(links.front());
  }
  EXPECT_TRUE(woke);
  EXPECT_TRUE(world.is_awake(ball));
}

TEST(JointLife, ABreakThresholdReportsAnEventEachStepItIsExceeded) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId heavy = add_ball(world, Vec2(0, 5), 0.5, 10);  // about 7.85 kg: 78.5 N
  RevoluteJointDef def = revolute_joint_at(world, ground, heavy, Vec2(0, 5));
  def.break_force = 50;
  def.user_data = 7;
  const JointId joint = world.create_joint(def);
  world.step();
  world.step();
  ASSERT_EQ(world.joint_break_events().size(), 1u);
  EXPECT_EQ(world.joint_break_events()[0].joint, joint);
  EXPECT_EQ(world.joint_break_events()[0].user_data, 7u);
  EXPECT_NEAR(world.joint_break_events()[0].force.y(), kGravity * world.mass(heavy), 0.5);
  world.set_joint_break(joint, 100, std::numeric_limits<Real>::infinity());
  world.step();
  EXPECT_TRUE(world.joint_break_events().empty());
  EXPECT_TRUE(world.is_valid(joint));  // reported, not destroyed
}

TEST(JointErrors, BadDefinitionsAreRefusedNamingTheField) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId ball = add_ball(world, Vec2(0, 0), 0.5);
  const auto message = [&](const JointDef& def) {
    try {
      world.create_joint(def);
    } catch (const InvalidArgumentError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  RevoluteJointDef same = revolute_joint_at(world, ball, ball, Vec2(0, 0));
  EXPECT_NE(message(same).find("body_a and body_b must differ"), std::string::npos);
  RevoluteJointDef limits = revolute_joint_at(world, ground, ball, Vec2(0, 0));
  limits.limit = {true, 1, -1};
  EXPECT_NE(message(limits).find("revolute joint.limit.lower must not exceed"), std::string::npos);
  RevoluteJointDef motor = revolute_joint_at(world, ground, ball, Vec2(0, 0));
  motor.motor = {true, 1, -5};
  EXPECT_NE(message(motor).find("motor.max_force"), std::string::npos);
  DistanceJointDef length = distance_joint_at(world, ground, ball, Vec2(0, 1), Vec2(0, 0));
  length.length = std::nan("");
  EXPECT_NE(message(length).find("distance joint.length"), std::string::npos);
  GearJointDef gear;
  gear.joint1 = world.create_joint(distance_joint_at(world, ground, ball, Vec2(0, 1), Vec2(0, 0)));
  gear.joint2 = world.create_joint(revolute_joint_at(world, ground, ball, Vec2(0, 0)));
  EXPECT_NE(message(gear).find("must be revolute or prismatic, got distance"), std::string::npos);
  // Setters check too, and name the joint.
  const JointId weld = world.create_joint(weld_joint_at(world, ground, ball, Vec2(0, 0)));
  EXPECT_THROW(world.set_joint_motor(weld, {true, 1, 1}), InvalidArgumentError);
  EXPECT_THROW(world.set_joint_limit(gear.joint2, {true, 2, 1}), InvalidArgumentError);
  // An id from another world is refused.
  World other(free_world());
  EXPECT_THROW(other.joint_type(gear.joint2), StaleIdError);
  EXPECT_EQ(world.joint_count(), 3u);  // nothing half-made
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// A distance joint with play winds a ball up against gravity with its motor; switched off,
// the ball falls freely.
TEST(DistanceMotor, SwitchedOffItStopsDriving) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId ball = add_ball(world, Vec2(0, -5), 0.1);
  DistanceJointDef joint = distance_joint_at(world, ground, ball, Vec2(0, 0), Vec2(0, -5));
  joint.limit = {true, 0.5, 100};
  joint.motor = {true, -1, 1000};
  const JointId id = world.create_joint(joint);
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_NEAR(world.joint_speed(id), -1, 1e-6);
  EXPECT_NEAR(world.joint_force(id).y(), kGravity * world.mass(ball), 1e-6);
  world.set_joint_motor(id, {false, -1, 1000});
  const Real before = world.linear_velocity(ball).y();
  for (int i = 0; i < 30; ++i) world.step();
  // Half a second of free fall (to the solver's single precision).
  EXPECT_NEAR(world.linear_velocity(ball).y() - before, -0.5 * kGravity, 1e-5);
  EXPECT_NEAR(world.joint_force(id).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace mink
