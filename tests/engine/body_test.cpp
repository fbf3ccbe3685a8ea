#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mink/engine/stale_id_error.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace mink {
namespace {

BodyId dynamic_body(World& world, const Vec2& position, Real angle = 0) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  def.angle = angle;
  return world.create_body(def);
}

TEST(Body, BoxMassCentroidAndInertiaComeFromTheHull) {
  World world;
  const BodyId body = dynamic_body(world, {1, 2});
  ShapeDef box = ShapeDef::box(1, 0.5, Vec2(0.5, 0));
  box.density = 3;
  world.create_shape(body, box);
  // 2 x 1 box: area 2, mass 6, I = m (w^2 + h^2) / 12 = 6 * 5 / 12.
  EXPECT_NEAR(world.mass(body), 6, 1e-12);
  EXPECT_NEAR(world.rotational_inertia(body), 2.5, 1e-12);
  EXPECT_NEAR(world.local_center(body).x(), 0.5, 1e-12);
  EXPECT_NEAR(world.world_center(body).x(), 1.5, 1e-12);
  EXPECT_NEAR(world.world_center(body).y(), 2, 1e-12);
}

TEST(Body, TwoShapesCombineByParallelAxis) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  world.create_shape(body, ShapeDef::box(0.5, 0.5, Vec2(-1, 0)));
  world.create_shape(body, ShapeDef::box(0.5, 0.5, Vec2(1, 0)));
  EXPECT_NEAR(world.mass(body), 2, 1e-12);
  EXPECT_NEAR(world.local_center(body).norm(), 0, 1e-12);
  // Each unit box: 1/6 about its centre plus 1 * 1^2.
  EXPECT_NEAR(world.rotational_inertia(body), 2 * (1.0 / 6 + 1), 1e-12);
}

TEST(Body, StaticAndKinematicBodiesHaveNoMass) {
  World world;
  const BodyId ground = world.create_body({});
  world.create_shape(ground, ShapeDef::box(5, 1));
  EXPECT_EQ(world.mass(ground), 0);
  BodyDef def;
  def.type = BodyType::kinematic;
  const BodyId mover = world.create_body(def);
  world.create_shape(mover, ShapeDef::box(1, 1));
  EXPECT_EQ(world.mass(mover), 0);
}

TEST(Body, PointsAreHulledWithTheChosenAlgorithm) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  ShapeDef def;
  def.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0.5, 1.5}, {1, 0}};
  for (HullAlgorithm algorithm : all_hull_algorithms()) {
    def.algorithm = algorithm;
    const ShapeId shape = world.create_shape(body, def);
    EXPECT_EQ(world.shape_hull(shape).size(), 4u) << to_string(algorithm);
    EXPECT_EQ(world.shape_algorithm(shape), algorithm);
    world.destroy_shape(shape);
  }
}

TEST(Body, ScaleAboutAFixedPointIsAppliedAtCreation) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  ShapeDef def = ShapeDef::box(1, 1, Vec2(1, 1));  // [0,2] x [0,2]
  def.scale = ShapeScale{Vec2(0, 0), Vec2(2, 0.5)};
  const ShapeId shape = world.create_shape(body, def);
  const Aabb box = world.shape_aabb(shape);
  EXPECT_NEAR(box.lower.x(), 0, 1e-12);
  EXPECT_NEAR(box.upper.x(), 4, 1e-12);
  EXPECT_NEAR(box.upper.y(), 1, 1e-12);
  EXPECT_NEAR(world.mass(body), 4, 1e-12);
}

TEST(Body, RegularPolygonHelper) {
  const ShapeDef hexagon = ShapeDef::regular_polygon(6, 2);
  EXPECT_EQ(make_shape_hull(hexagon).size(), 6u);
  EXPECT_THROW(ShapeDef::regular_polygon(2, 1), InvalidArgumentError);
  EXPECT_THROW(ShapeDef::box(-1, 1), InvalidArgumentError);
}

TEST(Body, BadInputRaisesTypedErrors) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  ShapeDef def = ShapeDef::box(1, 1);
  def.density = -1;
  EXPECT_THROW(world.create_shape(body, def), InvalidArgumentError);
  def = ShapeDef::box(1, 1);
  def.friction = std::nan("");
  EXPECT_THROW(world.create_shape(body, def), InvalidArgumentError);
  ShapeDef line;
  line.points = {{0, 0}, {1, 1}, {2, 2}};
  EXPECT_THROW(world.create_shape(body, line), DegenerateInputError);
  ShapeDef nan_point;
  nan_point.points = {{0, 0}, {1, 0}, {std::nan(""), 1}};
  EXPECT_THROW(world.create_shape(body, nan_point), NonFiniteInputError);
  BodyDef bad;
  bad.position = Vec2(std::numeric_limits<Real>::infinity(), 0);
  EXPECT_THROW(world.create_body(bad), InvalidArgumentError);
  WorldDef bad_world;
  bad_world.substeps = 0;
  EXPECT_THROW(World{bad_world}, InvalidArgumentError);
  bad_world = {};
  bad_world.time_step = -1;
  EXPECT_THROW(World{bad_world}, InvalidArgumentError);
}

TEST(Body, StaleIdsThrowNamingTheId) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  const ShapeId shape = world.create_shape(body, ShapeDef::box(1, 1));
  world.destroy_body(body);
  EXPECT_FALSE(world.is_valid(body));
  EXPECT_FALSE(world.is_valid(shape));
  try {
    world.position(body);
    FAIL() << "stale body id accepted";
  } catch (const StaleIdError& error) {
    EXPECT_NE(std::string(error.what()).find(to_string(body)), std::string::npos);
  }
  EXPECT_THROW(world.shape_hull(shape), StaleIdError);
  EXPECT_THROW(world.destroy_body(body), StaleIdError);
  EXPECT_THROW(world.destroy_shape(shape), StaleIdError);
  // The slot is reused with a new generation: the old id stays stale.
  const BodyId reused = dynamic_body(world, {1, 1});
  EXPECT_EQ(reused.index, body.index);
  EXPECT_NE(reused.generation, body.generation);
  EXPECT_THROW(world.position(body), StaleIdError);
  EXPECT_NO_THROW(world.position(reused));
  EXPECT_THROW(world.position(BodyId{}), StaleIdError);
  EXPECT_THROW(world.create_shape(body, ShapeDef::box(1, 1)), StaleIdError);
  EXPECT_TRUE((std::is_base_of_v<Error, StaleIdError>));
}

TEST(Body, PoseAndVelocitySetters) {
  World world;
  const BodyId body = dynamic_body(world, {0, 0});
  world.create_shape(body, ShapeDef::box(1, 1, Vec2(1, 0)));
  world.set_transform(body, Vec2(3, 4), std::numbers::pi / 2);
  EXPECT_NEAR(world.position(body).x(), 3, 1e-12);
  EXPECT_NEAR(world.angle(body), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(world.world_center(body).x(), 3, 1e-12);
  EXPECT_NEAR(world.world_center(body).y(), 5, 1e-12);
  world.set_linear_velocity(body, Vec2(1, 2));
  world.set_angular_velocity(body, 0.5);
  EXPECT_EQ(world.linear_velocity(body), Vec2(1, 2));
  EXPECT_EQ(world.angular_velocity(body), 0.5);
  EXPECT_THROW(world.set_linear_velocity(body, Vec2(std::nan(""), 0)), InvalidArgumentError);
}

TEST(Body, FreeFallIsSemiImplicitEuler) {
  WorldDef def;
  def.substeps = 1;
  World world(def);
  const BodyId body = dynamic_body(world, {0, 0});
  world.create_shape(body, ShapeDef::box(0.5, 0.5));
  const Real dt = def.time_step;
  Real v = 0, y = 0;
  for (int i = 0; i < 10; ++i) {
    world.step();
    v += dt * def.gravity.y();
    y += dt * v;  // velocity first, then position with the new velocity
  }
  // To the solver's single precision (velocities and the step's position change are floats;
  // explicit Euler would be dt * v, about 5e-3, away).
  EXPECT_NEAR(world.linear_velocity(body).y(), v, 1e-6 * std::abs(v));
  EXPECT_NEAR(world.position(body).y(), y, 1e-6 * std::abs(y));
}

TEST(Body, AdvanceRunsWholeStepsAndReportsTheRemainder) {
  World world;
  const Real dt = world.def().time_step;
  AdvanceResult result = world.advance(2.5 * dt);
  EXPECT_EQ(result.steps, 2);
  EXPECT_NEAR(result.alpha, 0.5, 1e-9);
  result = world.advance(0.6 * dt);
  EXPECT_EQ(result.steps, 1);
  EXPECT_NEAR(result.alpha, 0.1, 1e-9);
  EXPECT_EQ(world.step_count(), 3u);
  EXPECT_THROW(world.advance(-1), InvalidArgumentError);
  // A huge frame is capped, not replayed.
  result = world.advance(100);
  EXPECT_EQ(result.steps, world.def().max_steps_per_advance);
  EXPECT_LT(result.alpha, 1);
}

}  // namespace
}  // namespace mink
