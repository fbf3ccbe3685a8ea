// What the fuzz harnesses of fuzz/ found in the engine, each as the smallest case that showed
// it (the failing inputs themselves are in fuzz/corpus/).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "mink/byte_stream.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::all_finite;

// Steps `world` `steps` times; fails at the first step that leaves a state non-finite.
void expect_steps_finite(World& world, int steps) {
  for (int i = 0; i < steps; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
}

// A spinning box given a rotational inertia of 4.9e-324 (the smallest double) had an infinite
// inverse inertia in the solver: the next step made its state NaN, and the broadphase threw
// from inside step(). Such mass data is now refused, and the world left as it was.
TEST(FuzzFindings, SetMassDataRefusesInertiaTooSmallToInvert) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 0.6});
  world.set_angular_velocity(box, -1.76);
  const MassData before = world.mass_data(box);
  const Real denormal = std::numeric_limits<Real>::denorm_min();
  const std::string error = test::error_of<InvalidArgumentError>([&] {
    world.set_mass_data(box, MassData{1.5, Vec2(0, 0), denormal});
  });
  EXPECT_NE(error.find("set_mass_data"), std::string::npos) << error;
  EXPECT_NE(error.find("min_mass_property"), std::string::npos) << error;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_mass_data(box, MassData{1e-40, Vec2(0, 0), 1});
            }),
            "no error");
  EXPECT_EQ(world.mass_data(box).mass, before.mass);
  EXPECT_EQ(world.mass_data(box).rotational_inertia, before.rotational_inertia);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_TRUE(all_finite(world));
}

// The smallest mass and inertia allowed keep the solver finite: a box that light and that
// easy to turn lands on the ground, spinning and sliding, without NaN.
TEST(FuzzFindings, SmallestMassPropertiesStayFinite) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 0.6}, 0.5, 0.3);
  world.set_mass_data(box, MassData{min_mass_property, Vec2(0.1, 0), min_mass_property});
  world.set_linear_velocity(box, {3, -2});
  world.set_angular_velocity(box, 5);
  const BodyId heavy = test::add_box(world, {0.2, 2});
  world.set_linear_velocity(heavy, {0, -5});
  expect_steps_finite(world, 120);
}

// A density so small that the shape's mass (density times area) is below min_mass_property
// gave the same infinite inverse; create_shape and set_shape_density refuse it.
TEST(FuzzFindings, ShapeMassTooSmallToInvertIsRefused) {
  World world;
  BodyDef def;
  def.type = BodyType::dynamic;
  const BodyId body = world.create_body(def);
  ShapeDef light = ShapeDef::box(0.5, 0.5);
  light.density = 1e-35;
  const std::string error =
      test::error_of<InvalidArgumentError>([&] { world.create_shape(body, light); });
  EXPECT_NE(error.find("create_shape"), std::string::npos) << error;
  EXPECT_NE(error.find("min_mass_property"), std::string::npos) << error;
  EXPECT_EQ(world.shape_count(), 0u);

  const ShapeId shape = world.create_shape(body, ShapeDef::box(0.5, 0.5));
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] { world.set_shape_density(shape, 1e-35); }),
            "no error");
  EXPECT_EQ(world.shape_density(shape), 1);
  EXPECT_EQ(world.mass(body), 1);
  // Density 0 stays allowed (a massless shape), and so does a light but invertible one.
  world.set_shape_density(shape, 0);
  world.set_shape_density(shape, 1e-20);
  EXPECT_NEAR(world.mass(body), 1e-20, 1e-32);
}

// The scene reader refuses the same densities, at the density's key, so that a scene it
// accepts never fails to build.
TEST(FuzzFindings, SceneReaderRefusesAShapeMassTooSmallToInvert) {
  const std::string scene = R"({"bodies": [{"type": "dynamic", "shapes": [
      {"circle": {"radius": 0.5}, "density": 1e-35}]}]})";
  try {
    (void)parse_scene_json(scene);
    FAIL() << "accepted";
  } catch (const SceneFileError& error) {
    EXPECT_EQ(error.json_path(), "bodies[0].shapes[0].density") << error.what();
    EXPECT_NE(std::string(error.what()).find("min_mass_property"), std::string::npos);
  }
  const std::string light = R"({"bodies": [{"type": "dynamic", "shapes": [
      {"circle": {"radius": 0.5}, "density": 1e-20}]}]})";
  const World world = build_world(parse_scene_json(light));
  EXPECT_NEAR(world.mass(world.bodies().at(0)), 1e-20 * std::numbers::pi * 0.25, 1e-32);
}

// A polygon cast from inside another came back at fraction 0 with a zero normal, where
// ShapeCastHit promised a unit one: there is no separating direction for overlapping cores,
// so the zero normal is what the documentation now says; from outside the normal is unit.
TEST(FuzzFindings, CastShapeNormalIsZeroOnlyForAStartInside) {
  World world;
  const BodyId ground = test::add_ground(world);
  const ShapeDef box = ShapeDef::box(0.5, 0.5);
  const auto inside = world.cast_shape(box, Pose{{0, -0.5}, {}}, {1, 1});
  ASSERT_TRUE(inside.has_value());
  EXPECT_EQ(world.shape_body(inside->shape), ground);
  EXPECT_EQ(inside->fraction, 0);
  EXPECT_EQ(inside->normal, Vec2(0, 0));
  const auto above = world.cast_shape(box, Pose{{0, 3}, {}}, {0, -4});
  ASSERT_TRUE(above.has_value());
  EXPECT_GT(above->fraction, 0);
  EXPECT_NEAR(above->normal.x(), 0, 1e-9);
  EXPECT_NEAR(above->normal.y(), 1, 1e-9);
}

// Capsules hung from a static body, the first by two pins at different points. The direct
// solve for revolute chains took both pins as one chain through the first link: four rows on
// its three freedoms, whose pivot vanished but for rounding; inverted, it turned the chain NaN
// within three steps. A body pinned twice to one body (or to two fixed ones) now ends a chain.
TEST(FuzzFindings, AChainLinkPinnedTwiceStaysFinite) {
  const Real step = 0.25 * std::numbers::sqrt2 / 2;  // a link's half length along each axis
  std::string json = R"({"format": "minkowski-scene", "version": 1,
    "world": {"enable_sleep": false}, "bodies": [{"type": "static", "position": [0, 20], "shapes": []})";
  for (int k = 1; k <= 11; ++k) {
    const Real c = step * (2 * k - 1);
    json += R"(, {"type": "dynamic", "position": [)" + std::to_string(c) + ", " +
            std::to_string(20 - c) + R"(], "angle": -0.7853981633974483, "shapes": [{"capsule":
            {"center1": [-0.25, 0], "center2": [0.25, 0], "radius": 0.05}}]})";
  }
  json += R"(], "joints": [)";
  const auto pin = [&](int a, int b, int at) {
    const Real p = step * 2 * at;
    return R"({"type": "revolute", "body_a": )" + std::to_string(a) + R"(, "body_b": )" +
           std::to_string(b) + R"(, "anchor": [)" + std::to_string(p) + ", " +
           std::to_string(20 - p) + "]}";
  };
  // The links joined as the fuzzed scene had them: some pins swapped or skipped, so the
  // chains the direct solve finds run through the doubly pinned link.
  json += pin(0, 1, 0) + ", " + pin(0, 1, 1) + ", " + pin(2, 3, 2) + ", " + pin(3, 4, 3) + ", " +
          pin(8, 5, 4) + ", " + pin(5, 6, 5) + ", " + pin(6, 4, 6) + ", " + pin(7, 8, 7) + ", " +
          pin(8, 9, 8) + ", " + pin(9, 10, 9) + ", " + pin(10, 11, 10) + "]}";
  World world = build_world(parse_scene_json(json));
  ASSERT_TRUE(world.def().direct_joint_chains);
  const BodyId first = world.bodies()[1];
  const Vec2 start = world.position(first);
  expect_steps_finite(world, 300);
  // Pinned at two points, the first link cannot move.
  EXPECT_LT((world.position(first) - start).norm(), 0.01);
}

// The same chain with one link moved to x = 2.2e17 m: its pins' anchors lay 2.2e17 m from its
// origin, and the single-precision solver's squared lever arms overflowed, turning the chain NaN
// in one step (a query then threw from inside step()). Such an anchor is now refused when the
// joint is made, and the scene reader refuses the scene, naming the joint.
TEST(FuzzFindings, AJointAnchorBeyondItsReachIsRefused) {
  World world;
  const BodyId ground = world.create_body({});
  // (The body itself now lies within max_world_coordinate, as a body at 2.2e17 m is refused.)
  const BodyId far = test::add_box(world, {1e9, 17});
  const std::string error = test::error_of<InvalidArgumentError>(
      [&] { world.create_joint(revolute_joint_at(world, ground, far, Vec2(2.5, 17.5))); });
  EXPECT_NE(error.find("local_anchor_b"), std::string::npos) << error;
  EXPECT_NE(error.find("1000000"), std::string::npos) << error;
  EXPECT_EQ(world.joint_count(), 0u);
  // Within reach, the same joint is made.
  const BodyId near = test::add_box(world, {2.2e5, 17});
  world.create_joint(revolute_joint_at(world, ground, near, Vec2(2.5, 17.5)));
  EXPECT_EQ(world.joint_count(), 1u);

  const std::string scene = R"({"format": "minkowski-scene", "version": 1, "bodies": [
      {"type": "static", "position": [0, 20], "shapes": []},
      {"type": "dynamic", "position": [1e9, 17], "shapes": [{"circle":
      {"radius": 0.25}}]}], "joints": [{"type": "revolute", "body_a": 0, "body_b": 1,
      "anchor": [2.5, 17.5]}]})";
  const std::string scene_error =
      test::error_of<SceneFileError>([&] { (void)parse_scene_json(scene); });
  EXPECT_NE(scene_error.find("joints[0]"), std::string::npos) << scene_error;
  EXPECT_NE(scene_error.find("local_anchor_b"), std::string::npos) << scene_error;
}

// The World API harness, with its extreme values, found a weld spring of 1e300 hertz: its
// softness overflowed to NaN in the joint's state, and the world's own snapshot was refused.
// Spring frequencies and damping ratios (weld springs and the driven kinds' springs) and motor
// speeds now stay within max_setting_magnitude, refused otherwise, on creation, through the
// setters and in scene files.
TEST(FuzzFindings, JointRatesAndMotorSpeedsBeyondTheSettingLimitAreRefused) {
  World world;
  const BodyId ground = world.create_body({});
  const BodyId box = test::add_box(world, {0, 2});
  WeldJointDef weld;
  weld.body_a = ground;
  weld.body_b = box;
  weld.local_anchor_a = Vec2(0, 2);
  weld.linear_hertz = 1e300;
  std::string error = test::error_of<InvalidArgumentError>([&] { world.create_joint(weld); });
  EXPECT_NE(error.find("linear_hertz"), std::string::npos) << error;
  EXPECT_NE(error.find("max_setting_magnitude"), std::string::npos) << error;
  weld.linear_hertz = max_setting_magnitude;
  weld.angular_damping_ratio = max_setting_magnitude;
  const JointId welded = world.create_joint(weld);
  error =
      test::error_of<InvalidArgumentError>([&] { world.set_weld_springs(welded, 1, 1, 2e9, 1); });
  EXPECT_NE(error.find("angular_hertz"), std::string::npos) << error;
  EXPECT_EQ(std::get<WeldJointDef>(world.joint_def(welded)).angular_hertz, 0);
  // At the limit, the world steps finite and its snapshot restores; so it does with an
  // undamped spring of the smallest frequency, whose softness took omega / 0 (h omega
  // underflowed) and held an infinite rate in the joint's state.
  const BodyId soft = test::add_box(world, {-3, 2});
  WeldJointDef slow = weld;
  slow.body_b = soft;
  slow.local_anchor_a = Vec2(-3, 2);
  slow.linear_hertz = std::numeric_limits<Real>::denorm_min();
  slow.angular_damping_ratio = 0;
  world.create_joint(slow);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_TRUE(all_finite(world));
  EXPECT_EQ(World::from_snapshot(world.snapshot()).state_hash(), world.state_hash());

  RevoluteJointDef hinge;
  hinge.body_a = ground;
  hinge.body_b = test::add_box(world, {3, 2});
  hinge.local_anchor_a = Vec2(3, 2);
  hinge.spring = {true, 1e10, 0.5, 0};
  error = test::error_of<InvalidArgumentError>([&] { world.create_joint(hinge); });
  EXPECT_NE(error.find("spring.hertz"), std::string::npos) << error;
  hinge.spring = {true, 5, 1e300, 0};
  error = test::error_of<InvalidArgumentError>([&] { world.create_joint(hinge); });
  EXPECT_NE(error.find("spring.damping_ratio"), std::string::npos) << error;
  hinge.spring = {};
  hinge.motor = {true, -2e9, 10};
  error = test::error_of<InvalidArgumentError>([&] { world.create_joint(hinge); });
  EXPECT_NE(error.find("motor.speed"), std::string::npos) << error;
  hinge.motor = {true, -max_setting_magnitude, 10};
  const JointId hinged = world.create_joint(hinge);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_joint_spring(hinged, {true, 1e300, 1, 0});
            }),
            "no error");
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_joint_motor(hinged, {true, 1e300, 1});
            }),
            "no error");

  const std::string scene = R"({"format": "minkowski-scene", "version": 1, "bodies": [
      {"type": "static", "position": [0, 0], "shapes": []},
      {"type": "dynamic", "position": [0, 2], "shapes": [{"circle": {"radius": 0.25}}]}],
      "joints": [{"type": "weld", "body_a": 0, "body_b": 1, "anchor": [0, 2],
      "linear_hertz": 1e300}]})";
  const std::string scene_error =
      test::error_of<SceneFileError>([&] { (void)parse_scene_json(scene); });
  EXPECT_NE(scene_error.find("joints[0]"), std::string::npos) << scene_error;
  EXPECT_NE(scene_error.find("linear_hertz"), std::string::npos) << scene_error;
}

// The scene reader fuzzer found a scene without joints whose body moved at 7.8e74 m/s: read,
// then refused by create_body when built (the reader checked bodies in the engine only with
// joints). The reader now refuses what create_body refuses, naming the body.
TEST(FuzzFindings, TheSceneReaderRefusesTheBodiesCreateBodyRefuses) {
  const std::string scene = R"({"format": "minkowski-scene", "version": 1, "bodies": [
      {"type": "dynamic", "position": [0, 2], "shapes": [{"circle": {"radius": 0.25}}]},
      {"type": "dynamic", "position": [0, 5], "linear_velocity": [0, 7.8e74],
       "shapes": [{"circle": {"radius": 0.25}}]}]})";
  const std::string error = test::error_of<SceneFileError>([&] { (void)parse_scene_json(scene); });
  EXPECT_NE(error.find("bodies[1]"), std::string::npos) << error;
  EXPECT_NE(error.find("linear_velocity"), std::string::npos) << error;
  EXPECT_NE(error.find("max_setting_magnitude"), std::string::npos) << error;
}

// The snapshot-restore fuzzer found a world whose gravity was 1e175 m/s^2: finite, so taken,
// but the single-precision solver turned it infinite and the world NaN in one step. Gravity,
// the other world settings and a body's gravity scale now stay within max_setting_magnitude
// (and the time step above its inverse), refused otherwise; at that limit the world stays finite.
TEST(FuzzFindings, SettingsBeyondTheSolversRangeAreRefused) {
  WorldDef def;
  def.gravity = Vec2(1e175, 0);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] { World world(def); }).find("gravity"),
            std::string::npos);
  def = {};
  def.time_step = 1e-300;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] { World world(def); }).find("time_step"),
            std::string::npos);
  def = {};
  def.contact_hertz = 1e300;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] { World world(def); }).find("contact_hertz"),
            std::string::npos);

  // The snapshot-restore fuzzer's next find: 10^8 substeps, which asked for gigabytes.
  def = {};
  def.substeps = 100'000'000;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] { World world(def); }).find("substeps"),
            std::string::npos);

  World world;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.step(1.0 / 60, 100'000'000);
            }).find("max_substeps"),
            std::string::npos);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_gravity(Vec2(0, -2 * max_setting_magnitude));
            }).find("gravity"),
            std::string::npos);
  BodyDef heavy;
  heavy.type = BodyType::dynamic;
  heavy.gravity_scale = 1e300;
  EXPECT_NE(
      test::error_of<InvalidArgumentError>([&] { world.create_body(heavy); }).find("gravity_scale"),
      std::string::npos);
  EXPECT_EQ(world.body_count(), 0u);

  def = {};
  def.gravity = Vec2(max_setting_magnitude, -max_setting_magnitude);
  def.max_linear_speed = max_setting_magnitude;
  def.contact_hertz = max_setting_magnitude;
  World extreme(def);
  test::add_ground(extreme);
  test::add_box(extreme, {0, 0.6});
  heavy.gravity_scale = -max_setting_magnitude;
  heavy.position = Vec2(0, 3);
  extreme.create_shape(extreme.create_body(heavy), ShapeDef::circle(0.25));
  expect_steps_finite(extreme, 60);
}

// The snapshot-restore fuzzer found a body at -2e306 m: finite, but sums of coordinates there
// overflow and the world turned NaN in a step. Bodies and shape points now stay within
// max_world_coordinate, refused beyond; at that distance a body still steps finite.
TEST(FuzzFindings, CoordinatesBeyondTheWorldAreRefused) {
  World world;
  BodyDef far;
  far.type = BodyType::dynamic;
  far.position = Vec2(0, -2e306);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.create_body(far);
            }).find("max_world_coordinate"),
            std::string::npos);
  far.position = Vec2(max_world_coordinate, 10 - max_world_coordinate);
  const BodyId body = world.create_body(far);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_transform(body, Vec2(2 * max_world_coordinate, 0), 0);
            }).find("max_world_coordinate"),
            std::string::npos);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.create_shape(body, ShapeDef::circle(0.5, Vec2(0, 1e300)));
            }).find("points[0]"),
            std::string::npos);
  world.create_shape(body, ShapeDef::box(0.5, 0.5));
  BodyDef ground;
  ground.position = Vec2(max_world_coordinate, 8 - max_world_coordinate);
  world.create_shape(world.create_body(ground), ShapeDef::box(5, 0.5));
  expect_steps_finite(world, 60);
}

// The World API fuzzer found a polygon whose points were within max_world_coordinate of its
// body's origin until ShapeDef.scale took them to 1e18 m; its body's centre went there too,
// and the world's own snapshot was then refused. Such a scale is refused now. A body whose
// origin and shape are each within the limit can still have its centre, boxes and contacts
// beyond it (up to a few times as far): its snapshot restores.
TEST(FuzzFindings, ScaledPolygonsStayWithinTheWorldAndFarCentresRestore) {
  World world;
  BodyDef def;
  def.type = BodyType::dynamic;
  const BodyId body = world.create_body(def);
  ShapeDef scaled = ShapeDef::box(0.5, 0.5, Vec2(-1e14, 0));
  scaled.scale = ShapeScale{Vec2(0, 0), Vec2(1e4, 1)};
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.create_shape(body, scaled);
            }).find("ShapeDef.scale"),
            std::string::npos);
  EXPECT_TRUE(world.body_shapes(body).empty());

  def.position = Vec2(0.9 * max_world_coordinate, 0);
  const BodyId far = world.create_body(def);
  world.create_shape(far, ShapeDef::circle(1, Vec2(0.9 * max_world_coordinate, 0)));
  ASSERT_GT(world.world_center(far).x(), max_world_coordinate);
  const std::vector<std::uint8_t> bytes = world.snapshot();
  const World copy = World::from_snapshot(bytes);
  EXPECT_EQ(copy.state_hash(), world.state_hash());
}

// A velocity of 1e300 m/s, or the push of a force that size, was taken (it is finite), but the
// single-precision solver turned it infinite and the world NaN in a step; a kinematic body,
// which moves by its own velocity in double precision, spun at 1e300 rad/s turned NaN at once;
// an impulse of twice the largest double overflowed the velocity. (The World API fuzzer found
// these once it drew such values.) Velocities beyond max_setting_magnitude are now refused,
// as is an impulse or force that would overflow; anything faster than the speed limits goes
// at the limits, in the direction it was given, and every state stays finite.
TEST(FuzzFindings, HugeVelocitiesAndPushesGoAtTheSpeedLimit) {
  World world;
  const Real limit = world.def().max_linear_speed;
  const Real huge = max_setting_magnitude;
  const BodyId fired = test::add_box(world, {0, 0});
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_linear_velocity(fired, {1e300, -1e300});
            }).find("max_setting_magnitude"),
            std::string::npos);
  world.set_linear_velocity(fired, {huge, -huge});
  const BodyId pushed = test::add_box(world, {0, 20});
  world.apply_force(pushed, {-1e300, 0}, world.world_center(pushed));
  const BodyId struck = test::add_box(world, {0, 40});
  const Vec2 at_rest = world.linear_velocity(struck);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.apply_linear_impulse(struck, {0, std::numeric_limits<Real>::max()},
                                         world.world_center(struck));
            }).find("max_setting_magnitude"),
            std::string::npos);
  EXPECT_EQ(world.linear_velocity(struck), at_rest);
  world.apply_linear_impulse(struck, {0, huge}, world.world_center(struck));
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.apply_force(struck, {1e300, 0}, world.world_center(struck) + Vec2(0, 1e10));
            }).find("overflow"),
            std::string::npos);

  BodyDef spinner;
  spinner.type = BodyType::kinematic;
  spinner.position = Vec2(10, 10);
  const BodyId spun = world.create_body(spinner);
  world.create_shape(spun, ShapeDef::box(1, 0.1));
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_angular_velocity(spun, -1e300);
            }).find("max_setting_magnitude"),
            std::string::npos);
  world.set_angular_velocity(spun, -huge);
  world.set_linear_velocity(spun, {0, huge});

  world.step();
  ASSERT_TRUE(all_finite(world));
  const auto near = [&](const Vec2& v, const Vec2& expected) {
    return (v - expected).norm() <= 1e-3 * limit;
  };
  EXPECT_TRUE(near(world.linear_velocity(fired), Vec2(limit, -limit) / std::sqrt(2.0)))
      << world.linear_velocity(fired).transpose();
  EXPECT_TRUE(near(world.linear_velocity(pushed), Vec2(-limit, 0)))
      << world.linear_velocity(pushed).transpose();
  EXPECT_TRUE(near(world.linear_velocity(struck), Vec2(0, limit)))
      << world.linear_velocity(struck).transpose();
  // The kinematic body turns an eighth of a turn per substep at most, and says so.
  const Real h = world.def().time_step / world.def().substeps;
  EXPECT_EQ(world.angular_velocity(spun), -0.25 * std::numbers::pi / h);
  EXPECT_EQ(world.linear_velocity(spun), Vec2(0, limit));
}

// Two shapes of friction 1e300 touching mixed to an infinite contact friction (the root of
// the product overflowed), and the world's own snapshot was refused (the World API harness
// with its extreme values). Friction and restitution are refused beyond max_setting_magnitude
// (by the ShapeDef checks, the setters and the scene reader); at the limit, two such shapes
// touch, step finite and restore.
TEST(FuzzFindings, FrictionAndRestitutionBeyondTheSettingLimitAreRefused) {
  World world;
  ShapeDef rough = ShapeDef::box(0.5, 0.5);
  rough.friction = 1e300;
  const BodyId body = world.create_body({});
  std::string error =
      test::error_of<InvalidArgumentError>([&] { world.create_shape(body, rough); });
  EXPECT_NE(error.find("ShapeDef.friction"), std::string::npos) << error;
  EXPECT_NE(error.find("max_setting_magnitude"), std::string::npos) << error;
  rough.friction = 0;
  rough.restitution = std::numeric_limits<Real>::max();
  error = test::error_of<InvalidArgumentError>([&] { world.create_shape(body, rough); });
  EXPECT_NE(error.find("ShapeDef.restitution"), std::string::npos) << error;

  const BodyId ground = test::add_box(world, {0, 0}, 5, 0, max_setting_magnitude);
  world.set_body_type(ground, BodyType::static_body);
  const BodyId box =
      test::add_box(world, {0, 5.45}, 0.5, 0, max_setting_magnitude, max_setting_magnitude);
  const ShapeId box_shape = world.body_shapes(box).front();
  error = test::error_of<InvalidArgumentError>([&] { world.set_shape_friction(box_shape, 2e9); });
  EXPECT_NE(error.find("set_shape_friction"), std::string::npos) << error;
  error =
      test::error_of<InvalidArgumentError>([&] { world.set_shape_restitution(box_shape, 1e300); });
  EXPECT_NE(error.find("set_shape_restitution"), std::string::npos) << error;
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_GT(world.counters().touching_contacts, 0u);
  EXPECT_TRUE(all_finite(world));
  EXPECT_EQ(World::from_snapshot(world.snapshot()).state_hash(), world.state_hash());

  const std::string scene = R"({"format": "minkowski-scene", "version": 1, "bodies": [
      {"type": "dynamic", "position": [0, 2],
       "shapes": [{"circle": {"radius": 0.25}, "friction": 1e300}]}]})";
  const std::string scene_error =
      test::error_of<SceneFileError>([&] { (void)parse_scene_json(scene); });
  EXPECT_NE(scene_error.find("friction"), std::string::npos) << scene_error;
}

// A pulley made with a ground anchor or a ratio of 1.8e308 read an infinite coordinate and
// speed as soon as it was made (the World API harness with its extreme values): its rope's
// length_a + ratio * length_b overflowed. Ground anchors beyond the world, ratios beyond
// max_setting_magnitude and lengths no two points of the world can span are refused; at the
// limits the pulley steps, reads finite and restores.
TEST(FuzzFindings, PulleyBeyondTheWorldOrTheSettingLimitIsRefused) {
  World world;
  const BodyId a = test::add_ball(world, {-2, 5}, 0.25);
  const BodyId b = test::add_ball(world, {2, 5}, 0.25);
  const Real huge = std::numeric_limits<Real>::max();
  const auto refusal = [&](const PulleyJointDef& def) {
    return test::error_of<InvalidArgumentError>([&] { world.create_joint(def); });
  };
  std::string error =
      refusal(pulley_joint_at(world, a, b, {-2, huge}, {2, 10}, {-2, 5}, {2, 5}, 1));
  EXPECT_NE(error.find("pulley joint.ground_anchor_a"), std::string::npos) << error;
  EXPECT_NE(error.find("max_world_coordinate"), std::string::npos) << error;
  error = refusal(pulley_joint_at(world, a, b, {-2, 10}, {2, 10}, {-2, 5}, {2, 5}, huge));
  EXPECT_NE(error.find("pulley joint.ratio must not exceed max_setting_magnitude"),
            std::string::npos)
      << error;
  PulleyJointDef long_rope = pulley_joint_at(world, a, b, {-2, 10}, {2, 10}, {-2, 5}, {2, 5}, 1);
  long_rope.length_b = 1e300;
  error = refusal(long_rope);
  EXPECT_NE(error.find("pulley joint.length_b must not exceed"), std::string::npos) << error;
  EXPECT_EQ(world.joint_count(), 0u);

  const JointId pulley = world.create_joint(pulley_joint_at(
      world, a, b, {-2, max_world_coordinate}, {2, 10}, {-2, 5}, {2, 5}, max_setting_magnitude));
  for (int i = 0; i < 30; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
    ASSERT_TRUE(std::isfinite(world.joint_coordinate(pulley)) &&
                std::isfinite(world.joint_speed(pulley)) &&
                std::isfinite(world.joint_force(pulley).x()) &&
                std::isfinite(world.joint_force(pulley).y()))
        << "step " << i;
  }
  EXPECT_EQ(World::from_snapshot(world.snapshot()).state_hash(), world.state_hash());
}

// Every input in the snapshot-restore seed corpus, as that harness reads it (this build's
// header put around the state, size and checksum made to fit; whole bytes when they start with
// 'M'): refused with a SnapshotError, or a world that steps finite at 1 and 2 workers alike.
// The inputs the harness found failing are refused by name. One of them flagged a joint's
// dynamic body fixed, so the constraint graph let another constraint on that body into the
// joint's colour: the two were solved at once on two workers, and the world stepped apart in
// about one run in eight.
TEST(FuzzFindings, TheSnapshotRestoreCorpusIsRefusedOrStepsFinite) {
  const std::filesystem::path corpus =
      std::filesystem::path(MINK_FUZZ_CORPUS_DIR) / "snapshot_restore";
  const std::vector<std::uint8_t> header = [] {
    const std::vector<std::uint8_t> any = World().snapshot();
    return std::vector<std::uint8_t>(any.begin(), any.begin() + 36);
  }();
  const std::vector<std::string> found_failing = {"gravity-1e175",
                                                  "fixed-contact-count",
                                                  "body-reaching-beyond-the-world",
                                                  "a-hundred-million-substeps",
                                                  "a-billion-broadphase-bands",
                                                  "a-proxy-count-beyond-its-proxies",
                                                  "a-live-proxy-touched-as-destroyed",
                                                  "a-search-cursor-stamped-ahead",
                                                  "a-shape-of-another-type",
                                                  "a-proxy-whose-last-corner-is-nan",
                                                  "a-joint-flagging-its-moving-body-fixed"};
  int refused = 0, stepped = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    SCOPED_TRACE(entry.path().filename().string());
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> input((std::istreambuf_iterator<char>(in)), {});
    std::vector<std::uint8_t> bytes = input;
    if (input.empty() || input[0] != 'M') {
      bytes = header;
      bytes.insert(bytes.end(), input.begin(), input.end());
      bytes = test::resealed(std::move(bytes));
    }
    const std::string name = entry.path().filename().string();
    const bool must_refuse =
        std::find(found_failing.begin(), found_failing.end(), name) != found_failing.end();
    try {
      World one = World::from_snapshot(bytes, 1);
      World two = World::from_snapshot(bytes, 2);
      EXPECT_FALSE(must_refuse);
      for (int i = 0; i < 3; ++i) {
        one.step();
        two.step();
      }
      EXPECT_TRUE(all_finite(one));
      EXPECT_EQ(one.state_hash(), two.state_hash());
      ++stepped;
    } catch (const SnapshotError&) {
      ++refused;
    }
  }
  EXPECT_GE(refused, static_cast<int>(found_failing.size()));
  EXPECT_GE(stepped, 4);  // the scenes' own snapshots among the seeds
}

// A density of 1e300 gave a shape an infinite mass (the World API fuzzer, drawing such values);
// a shape's mass and rotational inertia, and set_mass_data's, now stay within
// max_mass_property.
TEST(FuzzFindings, MassTooLargeToRepresentIsRefused) {
  World world;
  const BodyId box = test::add_box(world, {0, 1});
  ShapeDef heavy = ShapeDef::circle(0.5);
  heavy.density = 1e300;
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.create_shape(box, heavy);
            }).find("max_mass_property"),
            std::string::npos);
  EXPECT_NE(test::error_of<InvalidArgumentError>([&] {
              world.set_mass_data(box, MassData{1e31, Vec2(0, 0), 1});
            }).find("max_mass_property"),
            std::string::npos);
  EXPECT_EQ(world.body_shapes(box).size(), 1u);
  heavy.density = 1e29;  // a circle of area 0.79 m^2: 7.9e28 kg
  world.create_shape(box, heavy);
  expect_steps_finite(world, 30);
}

}  // namespace
}  // namespace mink
