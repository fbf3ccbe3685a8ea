// Revolute, prismatic, wheel, weld and motor joints against closed-form physics: limits holding a
// load (and the force and torque they report), motor speeds and stalls (a too-weak motor lets its
// load fall at g - F/m), spring periods and sags, a cantilever's sag, a motor joint's drag;
// and motors switched off, which must stop driving (the revolute's too).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::free_world;
using test::kGravity;
constexpr Real kPi = std::numbers::pi;

using test::add_ball;

// Steps `seconds` and returns the mean time between upward zero crossings of `value`
// (interpolated within the step), or 0 with fewer than two.
Real measured_period(World& world, const std::function<Real()>& value, Real seconds) {
  std::vector<Real> crossings;
  Real previous = value();
  const int steps = static_cast<int>(seconds / world.def().time_step);
  for (int i = 0; i < steps; ++i) {
    world.step();
    const Real x = value();
    if (previous < 0 && x >= 0) {
      crossings.push_back(world.time() - world.def().time_step * x / (x - previous));
    }
    previous = x;
  }
  if (crossings.size() < 2) return 0;
  return (crossings.back() - crossings.front()) / static_cast<Real>(crossings.size() - 1);
}

void step_for(World& world, Real seconds) {
  const int steps = static_cast<int>(std::round(seconds / world.def().time_step));
  for (int i = 0; i < steps; ++i) world.step();
}

// A box joined to the ground by the joint `make_def` gives, with a spring of 1.5 Hz towards
// 0.4 on its coordinate and no gravity: its coordinate swings about the target at that hertz.
template <typename MakeDef>
void expect_spring_period(MakeDef make_def) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 0));
  const Real hertz = 1.5, target = 0.4;
  auto def = make_def(world, ground, box);
  def.spring = {true, hertz, 0, target};
  const JointId joint = world.create_joint(def);
  const Real period = measured_period(
      world, [&] { return world.joint_coordinate(joint) - target; }, 6);
  EXPECT_NEAR(period, 1 / hertz, 0.03 / hertz);
  testing::Test::RecordProperty("period", std::to_string(period));
}

// ---- revolute ---------------------------------------------------------------------------------

// A 1 m arm of mass m pinned at one end, as in the pendulum tests: its centre of mass 0.5 m out
// along its angle.
BodyId add_arm(World& world) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(0.5, 0);
  const BodyId arm = world.create_body(def);
  world.create_shape(arm, ShapeDef::box(0.5, 0.05));
  return arm;
}

TEST(Revolute, ASpringTurnsABodyAtItsHertz) {
  expect_spring_period([](World& world, BodyId ground, BodyId box) {
    return revolute_joint_at(world, ground, box, Vec2(0, 0));
  });
}

// Released level, the arm falls until its lower limit takes it, and rests there: the limit's
// torque carries the weight's, m g (L / 2) cos(lower). The speculative limit lets it arrive at
// the bound without passing it.
TEST(Revolute, ALowerLimitHoldsAFallingArm) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId arm = add_arm(world);
  RevoluteJointDef def = revolute_joint_at(world, ground, arm, Vec2(0, 0));
  const Real lower = -0.3;
  def.limit = {true, lower, 0.3};
  const JointId joint = world.create_joint(def);
  Real lowest = 0;
  for (int i = 0; i < 180; ++i) {
    world.step();
    lowest = std::min(lowest, world.joint_coordinate(joint));
  }
  const Real m = world.mass(arm);
  EXPECT_NEAR(world.joint_coordinate(joint), lower, 0.005);
  EXPECT_GT(lowest, lower - 0.01);
  EXPECT_NEAR(world.joint_speed(joint), 0, 1e-3);
  const Real weight_torque = m * kGravity * 0.5 * std::cos(lower);
  EXPECT_NEAR(world.joint_torque(joint), weight_torque, 0.01 * weight_torque);
  EXPECT_NEAR(world.joint_force(joint).y(), m * kGravity, 0.01 * m * kGravity);
  RecordProperty("lowest", std::to_string(lowest));
}

// A motor lifting the arm against its weight stops at the upper limit, which then holds what
// the motor's torque exceeds the weight's by; a spring at the arm's angle does nothing.
TEST(Revolute, AMotorDrivesTheArmIntoItsUpperLimit) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId arm = add_arm(world);
  RevoluteJointDef def = revolute_joint_at(world, ground, arm, Vec2(0, 0));
  const Real upper = 0.6, max_torque = 1;
  def.limit = {true, -0.5, upper};
  def.motor = {true, 2, max_torque};
  const JointId joint = world.create_joint(def);
  step_for(world, 2);
  const Real m = world.mass(arm);
  EXPECT_NEAR(world.joint_coordinate(joint), upper, 0.005);
  EXPECT_NEAR(world.joint_speed(joint), 0, 1e-3);
  // Motor and limit together carry the weight's torque, the motor at its bound.
  const Real weight_torque = m * kGravity * 0.5 * std::cos(upper);
  EXPECT_NEAR(world.joint_torque(joint), weight_torque, 0.01 * weight_torque);
  EXPECT_GT(max_torque, weight_torque);
}

// ---- prismatic --------------------------------------------------------------------------------

// A 1 kg box slides down a vertical axis anchored half a metre to the side of its centre: the
// lower limit takes its weight there, so the joint must also hold a torque of m g / 2.
TEST(Prismatic, ALowerLimitHoldsAFallingBodyWithoutTurningIt) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5));
  PrismaticJointDef def = prismatic_joint_at(world, ground, box, Vec2(0.5, 5), Vec2(0, 1));
  def.limit = {true, -2, 1};
  const JointId joint = world.create_joint(def);
  step_for(world, 3);
  const Real m = world.mass(box);
  EXPECT_NEAR(world.joint_coordinate(joint), -2, 0.005);
  EXPECT_NEAR(world.position(box).y(), 3, 0.005);
  EXPECT_NEAR(world.position(box).x(), 0, 0.005);
  EXPECT_NEAR(world.angle(box), 0, 1e-3);
  EXPECT_NEAR(world.joint_speed(joint), 0, 1e-3);
  // The limit pushes up at the anchor; the angle row cancels that push's turn about the centre.
  EXPECT_NEAR(world.joint_force(joint).y(), m * kGravity, 0.01 * m * kGravity);
  EXPECT_NEAR(world.joint_force(joint).x(), 0, 1e-3);
  EXPECT_NEAR(world.joint_torque(joint), -0.5 * m * kGravity, 0.01 * m * kGravity);
  RecordProperty("coordinate", std::to_string(world.joint_coordinate(joint)));
  RecordProperty("angle", std::to_string(world.angle(box)));
}

TEST(Prismatic, AnUpperLimitStopsAMotorOnATiltedAxis) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5));
  const Vec2 axis = Vec2(1, 1).normalized();
  PrismaticJointDef def = prismatic_joint_at(world, ground, box, Vec2(0, 5), axis);
  def.limit = {true, -1, 1.5};
  def.motor = {true, 3, 100};
  const JointId joint = world.create_joint(def);
  step_for(world, 3);
  EXPECT_NEAR(world.joint_coordinate(joint), 1.5, 0.005);
  const Vec2 expected = Vec2(0, 5) + 1.5 * axis;
  EXPECT_NEAR((world.position(box) - expected).norm(), 0, 0.005);
  EXPECT_NEAR(world.angle(box), 0, 1e-3);
}

TEST(Prismatic, AMotorReachesItsSpeed) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5));
  PrismaticJointDef def = prismatic_joint_at(world, ground, box, Vec2(0, 5), Vec2(0, 1));
  def.motor = {true, 1.5, 50};
  const JointId joint = world.create_joint(def);
  step_for(world, 2);
  EXPECT_NEAR(world.joint_speed(joint), 1.5, 0.015);
  EXPECT_NEAR(world.linear_velocity(box).y(), 1.5, 0.015);
  // At constant speed the motor carries the weight.
  const Real weight = world.mass(box) * kGravity;
  EXPECT_NEAR(world.joint_force(joint).y(), weight, 0.01 * weight);
  RecordProperty("speed", std::to_string(world.joint_speed(joint)));
}

// A motor with less than the load's weight: the load sinks at g - F / m, from rest.
TEST(Prismatic, AMotorWeakerThanItsLoadStallsAndTheLoadSinks) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5));
  const Real m = world.mass(box), max_force = 0.6 * m * kGravity;
  PrismaticJointDef def = prismatic_joint_at(world, ground, box, Vec2(0, 5), Vec2(0, 1));
  def.motor = {true, 1, max_force};
  const JointId joint = world.create_joint(def);
  step_for(world, 1);
  const Real expected = -(kGravity - max_force / m) * 1.0;
  EXPECT_LT(world.position(box).y(), 5);
  EXPECT_NEAR(world.joint_speed(joint), expected, 0.01 * std::abs(expected));
  RecordProperty("speed", std::to_string(world.joint_speed(joint)));
}

// Between two free 1 kg boxes the motor pushes both: equal and opposite, so they part at the
// motor's speed, each at half of it, and the pair's momentum stays zero.
TEST(Prismatic, AMotorBetweenTwoFreeBodiesPushesBothApart) {
  World world(free_world(false));
  const BodyId left = test::add_box(world, Vec2(0, 0));
  const BodyId right = test::add_box(world, Vec2(2, 0));
  PrismaticJointDef def = prismatic_joint_at(world, left, right, Vec2(1, 0), Vec2(1, 0));
  def.motor = {true, 1, 10};
  const JointId joint = world.create_joint(def);
  step_for(world, 1);
  EXPECT_NEAR(world.joint_speed(joint), 1, 0.01);
  EXPECT_NEAR(world.linear_velocity(left).x(), -0.5, 0.005);
  EXPECT_NEAR(world.linear_velocity(right).x(), 0.5, 0.005);
  EXPECT_NEAR((world.linear_velocity(left) + world.linear_velocity(right)).norm(), 0, 1e-9);
  EXPECT_NEAR(world.angle(left), 0, 1e-3);
  EXPECT_NEAR(world.angle(right), 0, 1e-3);
  EXPECT_NEAR(world.position(right).y(), 0, 0.005);
}

TEST(Prismatic, ASpringOscillatesAtItsHertz) {
  expect_spring_period([](World& world, BodyId ground, BodyId box) {
    return prismatic_joint_at(world, ground, box, Vec2(0, 0), Vec2(1, 0));
  });
}

// ---- wheel ------------------------------------------------------------------------------------

TEST(Wheel, TheSuspensionOscillatesAtItsHertzAndTheWheelSpinsFreely) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId wheel = add_ball(world, Vec2(0, 1), 0.4);
  const Real hertz = 2, target = 0.3, spin = 7;
  WheelJointDef def = wheel_joint_at(world, ground, wheel, Vec2(0, 1), Vec2(0, 1));
  def.spring = {true, hertz, 0, target};
  const JointId joint = world.create_joint(def);
  world.set_angular_velocity(wheel, spin);
  const Real period = measured_period(
      world, [&] { return world.joint_coordinate(joint) - target; }, 5);
  EXPECT_NEAR(period, 1 / hertz, 0.03 / hertz);
  EXPECT_NEAR(world.angular_velocity(wheel), spin, 1e-6);
  EXPECT_NEAR(world.position(wheel).x(), 0, 0.005);  // on the axis
  RecordProperty("period", std::to_string(period));
  RecordProperty("spin", std::to_string(world.angular_velocity(wheel)));
}

// A damped suspension settles where the spring carries the weight: g / omega^2 below its target.
TEST(Wheel, TheSuspensionSagsByGOverOmegaSquared) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel = add_ball(world, Vec2(0, 1), 0.4);
  const Real hertz = 2;
  WheelJointDef def = wheel_joint_at(world, ground, wheel, Vec2(0, 1), Vec2(0, 1));
  def.spring = {true, hertz, 1, 0};
  const JointId joint = world.create_joint(def);
  step_for(world, 5);
  const Real omega = 2 * kPi * hertz, expected = -kGravity / (omega * omega);
  EXPECT_NEAR(world.joint_coordinate(joint), expected, 0.01 * std::abs(expected));
  RecordProperty("sag", std::to_string(world.joint_coordinate(joint)));
}

TEST(Wheel, ALimitStopsTheSuspension) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId wheel = add_ball(world, Vec2(0, 1), 0.4);
  WheelJointDef def = wheel_joint_at(world, ground, wheel, Vec2(0, 1), Vec2(0, 1));
  def.spring = {true, 0.5, 0.2, 0};  // soft: alone it would sag by about a metre
  def.limit = {true, -0.1, 0.1};
  const JointId joint = world.create_joint(def);
  step_for(world, 3);
  EXPECT_NEAR(world.joint_coordinate(joint), -0.1, 0.005);
}

// The motor spins the wheel up at torque / inertia until it reaches its speed.
TEST(Wheel, TheMotorReachesItsSpeedWithinItsTorque) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId fast = add_ball(world, Vec2(0, 1), 0.4);
  const BodyId slow = add_ball(world, Vec2(3, 1), 0.4);
  WheelJointDef def = wheel_joint_at(world, ground, fast, Vec2(0, 1), Vec2(0, 1));
  def.motor = {true, -10, 5};
  const JointId fast_joint = world.create_joint(def);
  def = wheel_joint_at(world, ground, slow, Vec2(3, 1), Vec2(0, 1));
  const Real torque = 0.01;
  def.motor = {true, -10, torque};
  world.create_joint(def);
  step_for(world, 1);
  EXPECT_NEAR(world.angular_velocity(fast), -10, 0.1);
  // At speed, nothing to overcome (to the solver's single precision).
  EXPECT_NEAR(world.joint_torque(fast_joint), 0, 1e-5);
  const Real expected = -torque / world.rotational_inertia(slow) * 1.0;
  EXPECT_NEAR(world.angular_velocity(slow), expected, 0.01 * std::abs(expected));
  RecordProperty("fast", std::to_string(world.angular_velocity(fast)));
  RecordProperty("slow", std::to_string(world.angular_velocity(slow)));
}

// A car: a box on two sprung wheels with driven motors, on the ground. Once the wheels turn at
// the motor's speed and roll without slipping, the car moves at speed * radius.
TEST(Wheel, ACarRollsAtTheMotorSpeedTimesTheWheelRadius) {
  World world(free_world());
  test::add_ground(world);
  const Real radius = 0.4, spin = -10;
  BodyDef body;
  body.type = BodyType::dynamic;
  body.position = Vec2(0, 1.2);
  const BodyId chassis = world.create_body(body);
  world.create_shape(chassis, ShapeDef::box(1, 0.25));
  for (const Real x : {-0.8, 0.8}) {
    const BodyId wheel = add_ball(world, Vec2(x, radius), radius);
    WheelJointDef def = wheel_joint_at(world, chassis, wheel, Vec2(x, radius), Vec2(0, 1));
    def.spring = {true, 4, 0.7, 0};
    def.limit = {true, -0.3, 0.3};
    def.motor = {true, spin, 20};
    world.create_joint(def);
  }
  step_for(world, 4);
  const Real expected = -spin * radius;
  EXPECT_NEAR(world.linear_velocity(chassis).x(), expected, 0.03 * expected);
  EXPECT_NEAR(world.angle(chassis), 0, 0.02);
  EXPECT_GT(world.position(chassis).y(), radius);  // riding on its wheels
  RecordProperty("speed", std::to_string(world.linear_velocity(chassis).x()));
}

// ---- weld -------------------------------------------------------------------------------------

// A 1 m square box welded by its left edge to a static body: the weld carries its weight and
// the moment of it, m g at the anchor and m g / 2 about the box's centre.
TEST(Weld, ARigidWeldHoldsACantilever) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0.5, 5));
  const JointId joint = world.create_joint(weld_joint_at(world, ground, box, Vec2(0, 5)));
  step_for(world, 3);
  const Real sag = 5 - world.pose(box).apply(Vec2(0.5, 0)).y();
  EXPECT_LT(std::abs(sag), 0.01);
  EXPECT_NEAR(world.angle(box), 0, 0.01);
  const Real weight = world.mass(box) * kGravity;
  EXPECT_NEAR(world.joint_force(joint).y(), weight, 0.01 * weight);
  EXPECT_NEAR(world.joint_torque(joint), 0.5 * weight, 0.01 * weight);
  RecordProperty("sag", std::to_string(sag));
}

// Welded at its centre (so the point row does not couple with the turn), a box on a soft
// angular weld turns as a torsion pendulum of the weld's hertz.
TEST(Weld, ASoftAngularWeldOscillatesAtItsHertz) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 0));
  WeldJointDef def = weld_joint_at(world, ground, box, Vec2(0, 0));
  const Real hertz = 1.5;
  def.angular_hertz = hertz;
  world.create_joint(def);
  world.set_angular_velocity(box, 1);
  const Real period = measured_period(
      world, [&] { return world.angle(box); }, 6);
  EXPECT_NEAR(period, 1 / hertz, 0.03 / hertz);
  EXPECT_NEAR(world.position(box).norm(), 0, 0.005);  // the point stays rigid
  RecordProperty("period", std::to_string(period));
}

TEST(Weld, ASoftLinearWeldOscillatesAtItsHertz) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 0));
  WeldJointDef def = weld_joint_at(world, ground, box, Vec2(0, 0));
  const Real hertz = 2;
  def.linear_hertz = hertz;
  world.create_joint(def);
  world.set_linear_velocity(box, Vec2(1, 0));
  const Real period = measured_period(
      world, [&] { return world.position(box).x(); }, 5);
  EXPECT_NEAR(period, 1 / hertz, 0.03 / hertz);
  EXPECT_NEAR(world.angle(box), 0, 1e-3);  // the angle stays rigid
  RecordProperty("period", std::to_string(period));
}

// Two free boxes welded side by side, one spinning, the other still: the weld makes them one
// body at once, which keeps the pair's angular momentum, L / I about their common centre.
TEST(Weld, TwoWeldedBodiesTurnAsOneAndKeepTheirAngularMomentum) {
  World world(free_world(false));
  const BodyId left = test::add_box(world, Vec2(0, 0));
  const BodyId right = test::add_box(world, Vec2(1, 0));
  world.create_joint(weld_joint_at(world, left, right, Vec2(0.5, 0)));
  const Real spin = 2;
  world.set_angular_velocity(left, spin);
  const Real m = world.mass(left), inertia = world.rotational_inertia(left);
  // About the pair's centre (0.5, 0): the spinning box's own spin only.
  const Real expected = inertia * spin / (2 * (inertia + m * 0.25));
  step_for(world, 2);
  EXPECT_NEAR(world.angular_velocity(left), expected, 0.01 * expected);
  EXPECT_NEAR(world.angular_velocity(right), expected, 0.01 * expected);
  EXPECT_NEAR((world.world_center(right) - world.world_center(left)).norm(), 1, 0.005);
  EXPECT_NEAR(std::remainder(world.angle(right) - world.angle(left), 2 * kPi), 0, 1e-3);
  EXPECT_NEAR(((world.world_center(right) + world.world_center(left)) / 2).norm(), 0.5, 0.005);
  RecordProperty("spin", std::to_string(world.angular_velocity(left)));
}

// ---- motor joint ------------------------------------------------------------------------------

TEST(MotorJoint, DragsABoxToItsTargetAndHoldsItThere) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5));
  MotorJointDef def = motor_joint_at(world, ground, box);
  def.linear_offset = Vec2(3, 7);
  def.angular_offset = 0.5;
  def.max_force = 50;
  def.max_torque = 20;
  const JointId joint = world.create_joint(def);
  // It brakes in time: never further along the way than the target.
  const Vec2 start = world.position(box), way = (Vec2(3, 7) - start).normalized();
  Real furthest = 0;
  for (int i = 0; i < 240; ++i) {
    world.step();
    furthest = std::max(furthest, (world.position(box) - start).dot(way));
  }
  EXPECT_LT(furthest, (Vec2(3, 7) - start).norm() + 0.01);
  EXPECT_NEAR((world.position(box) - Vec2(3, 7)).norm(), 0, 0.01);
  EXPECT_NEAR(world.angle(box), 0.5, 0.01);
  EXPECT_LT(world.linear_velocity(box).norm(), 0.01);
  EXPECT_LT(std::abs(world.angular_velocity(box)), 0.01);
  // Holding it there against gravity.
  const Real weight = world.mass(box) * kGravity;
  EXPECT_NEAR(world.joint_force(joint).y(), weight, 0.01 * weight);
  RecordProperty("error", std::to_string((world.position(box) - Vec2(3, 7)).norm()));
  RecordProperty("overshoot", std::to_string(furthest - (Vec2(3, 7) - start).norm()));
}

TEST(MotorJoint, ATargetMovedByTheApiIsFollowed) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 0));
  MotorJointDef def = motor_joint_at(world, ground, box);
  def.max_force = 100;
  def.max_torque = 100;
  const JointId joint = world.create_joint(def);
  world.set_motor_target(joint, Vec2(-2, 1), -1);
  step_for(world, 3);
  EXPECT_NEAR((world.position(box) - Vec2(-2, 1)).norm(), 0, 0.01);
  EXPECT_NEAR(world.angle(box), -1, 0.01);
}

// A motor joint too weak for its load: the box sinks at g - F / m while the target is above.
TEST(MotorJoint, ATinyMaxForceCannotLiftAHeavyBox) {
  World world(free_world());
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, Vec2(0, 5), 0.5, 0, 0.6, 0, 4);
  const Real m = world.mass(box), max_force = 0.25 * m * kGravity;
  MotorJointDef def = motor_joint_at(world, ground, box);
  def.linear_offset = Vec2(0, 8);
  def.max_force = max_force;
  world.create_joint(def);
  step_for(world, 1);
  const Real expected = -(kGravity - max_force / m) * 1.0;
  EXPECT_LT(world.position(box).y(), 5);
  EXPECT_NEAR(world.linear_velocity(box).y(), expected, 0.01 * std::abs(expected));
  RecordProperty("velocity", std::to_string(world.linear_velocity(box).y()));
}

// ---- switching parts off ----------------------------------------------------------------------

// A motor switched off stops driving at once: its last impulse must not be warm started on.
// Without gravity the driven body then keeps the speed it had.
TEST(JointMotors, AMotorSwitchedOffStopsDriving) {
  World world(free_world(false));
  const BodyId ground = world.create_body({});
  const BodyId spun = add_ball(world, Vec2(0, 0), 0.4);
  const BodyId slid = test::add_box(world, Vec2(3, 0));
  const BodyId wheel = add_ball(world, Vec2(6, 0), 0.4);
  const JointMotor on{true, 10, 0.5}, off{false, 10, 0.5};
  RevoluteJointDef revolute = revolute_joint_at(world, ground, spun, Vec2(0, 0));
  revolute.motor = on;
  PrismaticJointDef prismatic = prismatic_joint_at(world, ground, slid, Vec2(3, 0), Vec2(1, 0));
  prismatic.motor = on;
  WheelJointDef wheel_def = wheel_joint_at(world, ground, wheel, Vec2(6, 0), Vec2(0, 1));
  wheel_def.motor = on;
  const std::vector<JointId> joints = {world.create_joint(revolute), world.create_joint(prismatic),
                                       world.create_joint(wheel_def)};
  step_for(world, 0.2);
  const std::vector<Real> before = {world.angular_velocity(spun), world.linear_velocity(slid).x(),
                                    world.angular_velocity(wheel)};
  for (const Real speed : before) EXPECT_GT(speed, 0.05);  // the motors were driving
  for (const JointId j : joints) world.set_joint_motor(j, off);
  step_for(world, 1);
  EXPECT_NEAR(world.angular_velocity(spun), before[0], 1e-6);
  EXPECT_NEAR(world.linear_velocity(slid).x(), before[1], 1e-6);
  EXPECT_NEAR(world.angular_velocity(wheel), before[2], 1e-6);
}

}  // namespace
}  // namespace mink
