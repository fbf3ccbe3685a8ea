#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "mink/engine/scene.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

std::size_t count_dynamic(const SceneDef& scene) {
  return static_cast<std::size_t>(
      std::count_if(scene.bodies.begin(), scene.bodies.end(),
                    [](const SceneBody& b) { return b.body.type == BodyType::dynamic; }));
}

TEST(Scenes, BuiltInNamesAreListedAndBuild) {
  const auto names = builtin_scene_names();
  const std::set<std::string_view> expected = {
      "pyramid",  "pyramid_100",   "pyramid_grid",   "rain_mixed", "tumbler_400",
      "paper",    "shapes",        "pendulum",       "chain",      "bridge",
      "ragdolls", "car",           "newtons_cradle", "compounds",  "joint_grid",
      "junkyard", "large_pyramid", "many_pyramids",  "rain",       "smash",
      "spinner",  "tumbler",       "washer"};
  EXPECT_EQ(std::set<std::string_view>(names.begin(), names.end()), expected);
  for (const std::string_view name : names) {
    const SceneDef scene = builtin_scene(name);
    EXPECT_FALSE(scene.bodies.empty()) << name;
  }
  EXPECT_THROW(builtin_scene("no_such_scene"), InvalidArgumentError);
}

TEST(Scenes, SizesAreThoseTheIssueNames) {
  EXPECT_EQ(count_dynamic(builtin_scene("pyramid_100")), 5050u);
  EXPECT_EQ(count_dynamic(builtin_scene("pyramid")), 210u);
  EXPECT_EQ(count_dynamic(builtin_scene("pyramid_grid")), 20u * 20u * 55u);
  const SceneDef rain = builtin_scene("rain_mixed");
  EXPECT_EQ(count_dynamic(rain), 300u);
  std::size_t smallest = 1000, largest = 0;
  std::map<ShapeType, int> kinds;
  for (const SceneBody& b : rain.bodies) {
    if (b.body.type != BodyType::dynamic) continue;
    ++kinds[b.shapes[0].type];
    if (b.shapes[0].type != ShapeType::polygon) continue;
    const std::size_t n = make_shape_hull(b.shapes[0]).size();
    smallest = std::min(smallest, n);
    largest = std::max(largest, n);
  }
  EXPECT_GE(smallest, 3u);
  EXPECT_LE(largest, 64u);
  EXPECT_GT(largest, 40u);
  // About half polygons, a quarter each circles and capsules.
  EXPECT_GT(kinds[ShapeType::polygon], 100);
  EXPECT_GT(kinds[ShapeType::circle], 50);
  EXPECT_GT(kinds[ShapeType::capsule], 50);
  EXPECT_EQ(kinds.size(), 3u);
}

TEST(Scenes, RainIsTheSameForTheSameSeedAndPolygonsOnlyByDefault) {
  const auto points = [](const SceneDef& scene) {
    std::vector<std::vector<Vec2>> out;
    for (const SceneBody& b : scene.bodies) out.push_back(b.shapes[0].points);
    return out;
  };
  EXPECT_EQ(points(rain_scene(50, 9, RainShapes::mixed)),
            points(rain_scene(50, 9, RainShapes::mixed)));
  EXPECT_NE(points(rain_scene(50, 9, RainShapes::mixed)),
            points(rain_scene(50, 10, RainShapes::mixed)));
  for (const SceneBody& b : rain_scene(50, 9).bodies) {
    EXPECT_EQ(b.shapes[0].type, ShapeType::polygon);
  }
}

// Shape kinds in creation order over the whole scene.
std::vector<ShapeType> shape_kinds(const SceneDef& scene) {
  std::vector<ShapeType> kinds;
  for (const SceneBody& b : scene.bodies) {
    for (const ShapeDef& s : b.shapes) kinds.push_back(s.type);
  }
  return kinds;
}

// The closest a red-team body comes to a blue-team one after the scene settles (team by
// shape user data 1 and 2).
Real closest_red_to_blue(const SceneDef& scene) {
  World world = build_world(scene);
  for (int i = 0; i < 240; ++i) world.step();
  std::vector<Vec2> red, blue;
  for (const BodyId id : world.bodies()) {
    const std::uint64_t team = world.shape_user_data(world.body_shapes(id)[0]);
    if (team == 1) red.push_back(world.position(id));
    if (team == 2) blue.push_back(world.position(id));
  }
  EXPECT_EQ(red.size(), 4u);
  EXPECT_EQ(blue.size(), 4u);
  Real closest = 1e9;
  for (const Vec2& r : red) {
    for (const Vec2& b : blue) closest = std::min(closest, (r - b).norm());
  }
  return closest;
}

TEST(Scenes, ShapesSceneHasEveryKindAndItsTeamsPassThroughEachOther) {
  const SceneDef scene = builtin_scene("shapes");
  const std::vector<ShapeType> kinds = shape_kinds(scene);
  for (const ShapeType kind : {ShapeType::polygon, ShapeType::circle, ShapeType::capsule,
                               ShapeType::segment, ShapeType::chain}) {
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), kind), kinds.end()) << to_string(kind);
  }
  bool rounded = false, sensor = false;
  for (const SceneBody& b : scene.bodies) {
    for (const ShapeDef& s : b.shapes) {
      rounded |= s.type == ShapeType::polygon && s.radius > 0;
      sensor |= s.is_sensor;
    }
  }
  EXPECT_TRUE(rounded);
  EXPECT_TRUE(sensor);
  // A 0.4 half-extent box and a 0.4 radius circle that collide keep their centres at least
  // 0.8 apart; the teams' filters let them overlap. Without the filters they do collide.
  EXPECT_LT(closest_red_to_blue(scene), 0.6);
  SceneDef unfiltered = scene;
  for (SceneBody& b : unfiltered.bodies) {
    for (ShapeDef& s : b.shapes) s.filter = Filter{};
  }
  EXPECT_GT(closest_red_to_blue(unfiltered), 0.75);
  World world = build_world(scene);
  for (int i = 0; i < 300; ++i) world.step();
  for (const BodyId id : world.bodies()) {
    ASSERT_TRUE(test::finite_state(world, id));
    EXPECT_GT(world.position(id).y(), -1);  // nothing fell through the chain
  }
}

TEST(Scenes, CaptureKeepsEveryShapeKindAndEachChainAsOneShape) {
  SceneDef scene = builtin_scene("shapes");
  // A closed loop and a second open chain on one body, next to the terrain's.
  scene.bodies[0].shapes.push_back(
      ShapeDef::chain({Vec2(-1, 12), Vec2(1, 12), Vec2(1, 13), Vec2(-1, 13)}, true));
  scene.bodies[0].shapes.push_back(ShapeDef::chain({Vec2(-4, 12), Vec2(-3, 12)}));
  SceneBody moving;
  moving.body.type = BodyType::dynamic;
  moving.body.position = Vec2(0, 20);
  moving.body.fixed_rotation = true;
  moving.body.bullet = true;
  moving.body.enabled = false;
  moving.shapes.push_back(ShapeDef::circle(0.25, Vec2(0.1, 0)));
  scene.bodies.push_back(moving);
  const SceneDef captured = capture_scene(build_world(scene));
  EXPECT_EQ(shape_kinds(captured), shape_kinds(scene));
  ASSERT_EQ(captured.bodies.size(), scene.bodies.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    for (std::size_t k = 0; k < scene.bodies[i].shapes.size(); ++k) {
      const ShapeDef& given = scene.bodies[i].shapes[k];
      const ShapeDef& got = captured.bodies[i].shapes[k];
      // Polygons come back as their hulls, which may start at another vertex.
      if (given.type != ShapeType::polygon) {
        EXPECT_EQ(got.points, given.points) << i << " " << k;
      }
      EXPECT_EQ(got.radius, given.radius) << i << " " << k;
      EXPECT_EQ(got.loop, given.loop) << i << " " << k;
      EXPECT_EQ(got.filter, given.filter) << i << " " << k;
      EXPECT_EQ(got.is_sensor, given.is_sensor) << i << " " << k;
      EXPECT_EQ(got.user_data, given.user_data) << i << " " << k;
    }
  }
  const BodyDef& body = captured.bodies.back().body;
  EXPECT_TRUE(body.fixed_rotation);
  EXPECT_TRUE(body.bullet);
  EXPECT_FALSE(body.enabled);
}

TEST(Scenes, PaperSceneHullsByChanAndDivideAndConquerScaledIntoEachOther) {
  const SceneDef scene = builtin_scene("paper");
  World world = build_world(scene);
  std::vector<ShapeId> hulls;
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic) hulls.push_back(world.body_shapes(id)[0]);
  }
  ASSERT_EQ(hulls.size(), 2u);
  EXPECT_EQ(world.shape_algorithm(hulls[0]), HullAlgorithm::chan);
  EXPECT_EQ(world.shape_algorithm(hulls[1]), HullAlgorithm::divide_conquer);
  EXPECT_TRUE(world.shape_aabb(hulls[0]).overlaps(world.shape_aabb(hulls[1])));
  for (int i = 0; i < 240; ++i) world.step();
  // Pushed apart and resting on the ground, above it.
  for (const ShapeId s : hulls) EXPECT_GT(world.shape_aabb(s).lower.y(), -0.05);
}

// The drum is dynamic, turned by a revolute motor with torque to spare: it keeps the motor's
// speed under the boxes' load, its pin holds it up.
TEST(Scenes, TumblerTurnsAndKeepsItsBoxesInside) {
  World world = build_world(builtin_scene("tumbler_400"));
  ASSERT_EQ(world.joint_count(), 1u);
  const JointId motor = world.joints()[0];
  EXPECT_EQ(world.joint_type(motor), JointType::revolute);
  const BodyId drum = world.joint_body_b(motor);
  ASSERT_EQ(world.body_type(drum), BodyType::dynamic);
  const int steps = 240;
  for (int i = 0; i < steps; ++i) world.step();
  EXPECT_NEAR(world.angle(drum), 0.25 * steps * world.def().time_step, 1e-2);
  EXPECT_NEAR(world.angular_velocity(drum), 0.25, 1e-3);
  EXPECT_LT((world.position(drum) - Vec2(0, 10)).norm(), 1e-2);
  for (const BodyId id : world.bodies()) {
    ASSERT_TRUE(test::finite_state(world, id));
    if (world.body_type(id) == BodyType::dynamic && id != drum) {
      EXPECT_LT((world.position(id) - Vec2(0, 10)).norm(), 10 * std::sqrt(2.0));
    }
  }
}

TEST(Scenes, CaptureRebuildsTheWorldWhereItIs) {
  World world = build_world(builtin_scene("rain_mixed"));
  for (int i = 0; i < 60; ++i) world.step();
  const SceneDef captured = capture_scene(world);
  ASSERT_EQ(captured.bodies.size(), world.body_count());
  World copy = build_world(captured);
  const std::vector<BodyId> a = world.bodies(), b = copy.bodies();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((world.position(a[i]) - copy.position(b[i])).norm(), 0, 1e-12);
    EXPECT_NEAR(world.angle(a[i]), copy.angle(b[i]), 1e-12);
    EXPECT_NEAR((world.linear_velocity(a[i]) - copy.linear_velocity(b[i])).norm(), 0, 1e-9);
    EXPECT_NEAR(world.angular_velocity(a[i]), copy.angular_velocity(b[i]), 1e-12);
    EXPECT_NEAR(world.mass(a[i]), copy.mass(b[i]), 1e-12);
    EXPECT_EQ(world.is_awake(a[i]), copy.is_awake(b[i]));
    const ShapeId shape_a = world.body_shapes(a[i])[0];
    const ShapeId shape_b = copy.body_shapes(b[i])[0];
    ASSERT_EQ(world.shape_type(shape_a), copy.shape_type(shape_b));
    EXPECT_EQ(world.shape_radius(shape_a), copy.shape_radius(shape_b));
    if (world.shape_type(shape_a) == ShapeType::polygon) {
      EXPECT_EQ(world.shape_hull(shape_a), copy.shape_hull(shape_b));
    }
  }
}

TEST(Scenes, EveryBuiltInSurvivesAFewStepsWithoutNan) {
  for (const std::string_view name : builtin_scene_names()) {
#ifdef MINK_SANITIZED_BUILD
    // Thousands of bodies: the suite's scenes run under the sanitizers in suite_scene_test.
    if (name == "pyramid_grid" || name == "pyramid_100" || test::is_benchmark_scene(name)) continue;
#endif
    SceneRun run(builtin_scene(name));
    for (int i = 0; i < 5; ++i) run.step();
    const World& world = run.world();
    for (const BodyId id : world.bodies()) ASSERT_TRUE(test::finite_state(world, id)) << name;
  }
}

}  // namespace
}  // namespace mink
