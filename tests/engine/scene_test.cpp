#include <gtest/gtest.h>

#include <algorithm>
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
  const std::set<std::string_view> expected = {"large_pyramid", "pyramid", "many_pyramids",
                                               "rain",          "tumbler", "paper"};
  EXPECT_EQ(std::set<std::string_view>(names.begin(), names.end()), expected);
  for (const std::string_view name : names) {
    const SceneDef scene = builtin_scene(name);
    EXPECT_FALSE(scene.bodies.empty()) << name;
  }
  EXPECT_THROW(builtin_scene("no_such_scene"), InvalidArgumentError);
}

TEST(Scenes, SizesAreThoseTheIssueNames) {
  EXPECT_EQ(count_dynamic(builtin_scene("large_pyramid")), 5050u);
  EXPECT_EQ(count_dynamic(builtin_scene("pyramid")), 210u);
  EXPECT_EQ(count_dynamic(builtin_scene("many_pyramids")), 20u * 20u * 55u);
  const SceneDef rain = builtin_scene("rain");
  std::size_t smallest = 1000, largest = 0;
  for (const SceneBody& b : rain.bodies) {
    if (b.body.type != BodyType::dynamic) continue;
    const std::size_t n = make_shape_hull(b.shapes[0]).size();
    smallest = std::min(smallest, n);
    largest = std::max(largest, n);
  }
  EXPECT_GE(smallest, 3u);
  EXPECT_LE(largest, 64u);
  EXPECT_GT(largest, 40u);
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

TEST(Scenes, TumblerTurnsAndKeepsItsBoxesInside) {
  World world = build_world(builtin_scene("tumbler"));
  BodyId drum;
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::kinematic) drum = id;
  }
  ASSERT_FALSE(drum.is_null());
  const int steps = 240;
  for (int i = 0; i < steps; ++i) world.step();
  EXPECT_NEAR(world.angle(drum), 0.25 * steps * world.def().time_step, 1e-3);
  for (const BodyId id : world.bodies()) {
    ASSERT_TRUE(test::finite_state(world, id));
    if (world.body_type(id) == BodyType::dynamic) {
      EXPECT_LT((world.position(id) - Vec2(0, 10)).norm(), 10 * std::sqrt(2.0));
    }
  }
}

TEST(Scenes, CaptureRebuildsTheWorldWhereItIs) {
  World world = build_world(builtin_scene("rain"));
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
    EXPECT_EQ(world.shape_hull(world.body_shapes(a[i])[0]),
              copy.shape_hull(copy.body_shapes(b[i])[0]));
  }
}

TEST(Scenes, EveryBuiltInSurvivesAFewStepsWithoutNan) {
  for (const std::string_view name : builtin_scene_names()) {
#ifdef MINK_SANITIZED_BUILD
    if (name == "many_pyramids" || name == "large_pyramid") continue;
#endif
    World world = build_world(builtin_scene(name));
    for (int i = 0; i < 5; ++i) world.step();
    for (const BodyId id : world.bodies()) ASSERT_TRUE(test::finite_state(world, id)) << name;
  }
}

}  // namespace
}  // namespace mink
