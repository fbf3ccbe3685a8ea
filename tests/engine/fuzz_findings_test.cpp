// What the fuzz harnesses of fuzz/ found in the engine, each as the smallest case that showed
// it (the failing inputs themselves are in fuzz/corpus/).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::all_finite;

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
  for (int i = 0; i < 120; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
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
  for (int i = 0; i < 300; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
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
  const BodyId far = test::add_box(world, {2.2e17, 17});
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
      {"type": "dynamic", "position": [216516504294495533, 17], "shapes": [{"circle":
      {"radius": 0.25}}]}], "joints": [{"type": "revolute", "body_a": 0, "body_b": 1,
      "anchor": [2.5, 17.5]}]})";
  const std::string scene_error =
      test::error_of<SceneFileError>([&] { (void)parse_scene_json(scene); });
  EXPECT_NE(scene_error.find("joints[0]"), std::string::npos) << scene_error;
  EXPECT_NE(scene_error.find("local_anchor_b"), std::string::npos) << scene_error;
}

}  // namespace
}  // namespace mink
