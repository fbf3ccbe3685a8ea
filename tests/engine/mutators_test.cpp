// Changing bodies and shapes after creation, stepping with a caller's clock, and the checks at
// the API boundary for the new shape kinds.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "mink/engine/world.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::error_of;

TEST(Mutators, BodyTypeChangesMassAndMotion) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 3});
  world.set_body_type(box, BodyType::static_body);
  EXPECT_EQ(world.mass(box), 0);
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_EQ(world.position(box), Vec2(0, 3));  // static: hangs in the air
  world.set_body_type(box, BodyType::dynamic);
  EXPECT_NEAR(world.mass(box), 1, 1e-12);
  for (int i = 0; i < 90; ++i) world.step();
  EXPECT_NEAR(world.position(box).y(), 0.5, 0.02);  // fell and landed
}

TEST(Mutators, ADisabledBodyNeitherMovesNorCollides) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 0.5});
  const BodyId above = test::add_box(world, {0, 3});
  world.set_enabled(box, false);
  EXPECT_FALSE(world.is_enabled(box));
  for (int i = 0; i < 90; ++i) world.step();
  EXPECT_EQ(world.position(box), Vec2(0, 0.5));
  EXPECT_NEAR(world.position(above).y(), 0.5, 0.02);           // fell through where the box is
  EXPECT_TRUE(world.query_point(Vec2(0.3, 0.9)).size() == 1);  // only `above` is there
  world.set_transform(above, Vec2(5, 0.5), 0);
  world.set_enabled(box, true);
  for (int i = 0; i < 10; ++i) world.step();
  EXPECT_EQ(world.body_contacts(box).size(), 1u);  // on the ground again
}

TEST(Mutators, FixedRotationNeverTurns) {
  World world;
  test::add_ground(world);
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(0, 1);
  def.fixed_rotation = true;
  def.angular_velocity = 3;
  const BodyId body = world.create_body(def);
  world.create_shape(body, ShapeDef::box(0.5, 0.5, Vec2(0.3, 0)));  // off-centre
  EXPECT_EQ(world.rotational_inertia(body), 0);
  world.apply_torque(body, 100);
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_EQ(world.angle(body), 0);
  world.set_fixed_rotation(body, false);
  EXPECT_GT(world.rotational_inertia(body), 0);
}

TEST(Mutators, AKinematicTargetIsReachedInOneStep) {
  World world;
  BodyDef def;
  def.type = BodyType::kinematic;
  const BodyId platform = world.create_body(def);
  world.create_shape(platform, ShapeDef::box(1, 0.1, Vec2(0.5, 0)));
  world.set_target_transform(platform, Vec2(1, 2), 0.5, world.def().time_step);
  world.step();
  EXPECT_NEAR(world.position(platform).x(), 1, 1e-9);
  EXPECT_NEAR(world.position(platform).y(), 2, 1e-9);
  EXPECT_NEAR(world.angle(platform), 0.5, 1e-9);
  const BodyId dynamic = test::add_box(world, {5, 5});
  EXPECT_NE(error_of([&] {
              world.set_target_transform(dynamic, Vec2(0, 0), 0, 0.1);
            }).find("not kinematic"),
            std::string::npos);
}

TEST(Mutators, MassDataOverridesUntilTheShapesChange) {
  World world;
  const BodyId box = test::add_box(world, {0, 0});
  world.set_mass_data(box, MassData{5, Vec2(0.1, 0), 2});
  EXPECT_EQ(world.mass(box), 5);
  EXPECT_EQ(world.rotational_inertia(box), 2);
  EXPECT_EQ(world.local_center(box), Vec2(0.1, 0));
  world.set_shape_density(world.body_shapes(box)[0], 2);
  EXPECT_NEAR(world.mass(box), 2, 1e-12);  // back to the shapes: 1 m^2 at 2 kg/m^2
  EXPECT_NE(error_of([&] {
              world.set_mass_data(box, MassData{-1, Vec2(0, 0), 1});
            }).find("set_mass_data"),
            std::string::npos);
}

TEST(Mutators, FrictionChangesReachExistingContacts) {
  World world;
  test::add_ground(world);
  const BodyId box = test::add_box(world, {0, 0.5});
  for (int i = 0; i < 10; ++i) world.step();
  ASSERT_EQ(world.body_contacts(box).size(), 1u);
  world.set_shape_friction(world.body_shapes(box)[0], 0);  // the ground keeps 0.6: mix is 0
  world.set_linear_velocity(box, Vec2(2, 0));
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_NEAR(world.linear_velocity(box).x(), 2, 1e-6);  // nothing slows it
  world.set_shape_friction(world.body_shapes(box)[0], 0.6);
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_LT(world.linear_velocity(box).x(), 0.1);  // 6 m/s^2 stops it within a third of a second
}

TEST(Mutators, StepWithItsOwnTimeStepAndSubsteps) {
  WorldDef def;
  def.gravity = Vec2(0, 0);
  World world(def);
  BodyDef body;
  body.type = BodyType::dynamic;
  body.linear_velocity = Vec2(2, 0);
  const BodyId id = world.create_body(body);
  world.create_shape(id, ShapeDef::circle(0.5));
  world.step(0.25, 2);
  EXPECT_NEAR(world.position(id).x(), 0.5, 1e-12);
  EXPECT_NEAR(world.time(), 0.25, 1e-12);
  // The pose before and after the last step, blended.
  EXPECT_NEAR(world.interpolated_pose(id, 0.5).position.x(), 0.25, 1e-12);
  EXPECT_NE(error_of([&] { world.step(0, 4); }).find("time_step"), std::string::npos);
  EXPECT_NE(error_of([&] { world.step(0.1, 0); }).find("substeps"), std::string::npos);
}

TEST(ShapeKinds, MassesOfEveryKindAreTheirClosedForms) {
  World world;
  BodyDef def;
  def.type = BodyType::dynamic;
  const auto mass_of = [&](const ShapeDef& shape) {
    const BodyId body = world.create_body(def);
    world.create_shape(body, shape);
    return world.mass_data(body);
  };
  const Real pi = std::numbers::pi;
  const MassData disk = mass_of(ShapeDef::circle(2, Vec2(1, 0)));
  EXPECT_NEAR(disk.mass, 4 * pi, 1e-12);
  EXPECT_NEAR(disk.rotational_inertia, 0.5 * 4 * pi * 4, 1e-9);
  EXPECT_NEAR(disk.center.x(), 1, 1e-12);
  const MassData capsule = mass_of(ShapeDef::capsule(Vec2(-1, 0), Vec2(1, 0), 0.5));
  EXPECT_NEAR(capsule.mass, 2 * 1 + pi * 0.25, 1e-12);
  ShapeDef rounded = ShapeDef::box(1, 1);
  rounded.radius = 0.1;
  // Core 4, four edge strips 4 * 2 * 0.1, four quarter disks one whole disk.
  EXPECT_NEAR(mass_of(rounded).mass, 4 + 0.8 + pi * 0.01, 1e-12);
  EXPECT_NEAR(mass_of(ShapeDef::segment(Vec2(0, 0), Vec2(1, 0))).mass, 1, 0);  // no area: 1
}

TEST(ShapeKinds, BadDefinitionsNameTheirField) {
  World world;
  const BodyId body = world.create_body({});
  EXPECT_NE(error_of([&] { world.create_shape(body, ShapeDef::circle(0)); }).find("radius"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              world.create_shape(body, ShapeDef::capsule(Vec2(1, 1), Vec2(1, 1), 1));
            }).find("must differ"),
            std::string::npos);
  EXPECT_NE(
      error_of([&] { world.create_chain(body, ShapeDef::chain({Vec2(0, 0)})); }).find("at least 2"),
      std::string::npos);
  EXPECT_NE(error_of([&] {
              world.create_shape(body, ShapeDef::chain({Vec2(0, 0), Vec2(1, 0)}));
            }).find("create_chain"),
            std::string::npos);
  ShapeDef scaled = ShapeDef::circle(1);
  scaled.scale = ShapeScale{};
  EXPECT_NE(error_of([&] { world.create_shape(body, scaled); }).find("scale"), std::string::npos);
  ShapeDef bad = ShapeDef::circle(1);
  bad.points[0] = Vec2(std::nan(""), 0);
  EXPECT_NE(error_of([&] { world.create_shape(body, bad); }).find("non-finite"), std::string::npos);
  EXPECT_EQ(world.shape_count(), 0u);
}

TEST(ShapeKinds, CaptureKeepsEventFlagsAndChainsExactly) {
  World world;
  const BodyId body = world.create_body({});
  ShapeDef quiet = ShapeDef::circle(1);
  quiet.enable_contact_events = false;
  quiet.enable_sensor_events = false;
  quiet.enable_hit_events = true;
  world.create_shape(body, quiet);
  // Two chains back to back, the second a loop: captured as two chains, not one run.
  world.create_chain(body, ShapeDef::chain({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)}));
  world.create_chain(body, ShapeDef::chain({Vec2(2, 0), Vec2(3, 0), Vec2(3, 1)}, true));
  const SceneDef scene = capture_scene(world);
  ASSERT_EQ(scene.bodies.size(), 1u);
  const std::vector<ShapeDef>& shapes = scene.bodies[0].shapes;
  ASSERT_EQ(shapes.size(), 3u);
  EXPECT_FALSE(shapes[0].enable_contact_events);
  EXPECT_FALSE(shapes[0].enable_sensor_events);
  EXPECT_TRUE(shapes[0].enable_hit_events);
  EXPECT_EQ(shapes[1].points.size(), 3u);
  EXPECT_FALSE(shapes[1].loop);
  EXPECT_EQ(shapes[2].points, (std::vector<Vec2>{Vec2(2, 0), Vec2(3, 0), Vec2(3, 1)}));
  EXPECT_TRUE(shapes[2].loop);
  const std::vector<ShapeId> ids = world.body_shapes(body);
  EXPECT_FALSE(world.shape_chain(ids[0]));
  EXPECT_EQ(world.shape_chain(ids[1])->chain, 0u);
  EXPECT_EQ(world.shape_chain(ids.back())->chain, 1u);
}

TEST(ShapeKinds, QueriesSeeEveryKind) {
  World world;
  const BodyId body = world.create_body({});
  const ShapeId circle = world.create_shape(body, ShapeDef::circle(1, Vec2(0, 0)));
  const ShapeId capsule = world.create_shape(body, ShapeDef::capsule(Vec2(4, 0), Vec2(6, 0), 0.5));
  const ShapeId segment = world.create_shape(body, ShapeDef::segment(Vec2(10, -1), Vec2(10, 1)));
  EXPECT_EQ(world.query_point(Vec2(0.7, 0.7)), std::vector<ShapeId>{circle});
  EXPECT_TRUE(world.query_point(Vec2(0.72, 0.72)).empty());  // outside the disk, inside its box
  EXPECT_EQ(world.query_point(Vec2(6.3, 0.3)), std::vector<ShapeId>{capsule});
  EXPECT_EQ(world.query_aabb(Aabb{Vec2(9, -0.1), Vec2(11, 0.1)}), std::vector<ShapeId>{segment});
  const auto hit = world.ray_cast(Vec2(-5, 0), Vec2(20, 0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->shape, circle);
  EXPECT_NEAR(hit->hit.point.x(), -1, 1e-12);
  const auto second = world.ray_cast(Vec2(2, 0), Vec2(20, 0));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->shape, capsule);
  EXPECT_NEAR(second->hit.point.x(), 3.5, 1e-12);
}

}  // namespace
}  // namespace mink
