#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mink/engine/scene.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::dynamic_bodies;
using test::Start;

const Start& top_box(const std::vector<Start>& starts) {
  return *std::max_element(starts.begin(), starts.end(), [](const Start& a, const Start& b) {
    return a.position.y() < b.position.y();
  });
}

TEST(Pyramid, TwentyRowsStandAfterTenSeconds) {
  World world = build_world(builtin_scene("pyramid"));
  const std::vector<Start> starts = dynamic_bodies(world);
  ASSERT_EQ(starts.size(), 210u);
  const Start& top = top_box(starts);
  const int steps = static_cast<int>(std::lround(10 / world.def().time_step));
  for (int i = 0; i < steps; ++i) world.step();
  Real worst_sideways = 0;
  for (const Start& s : starts) {
    worst_sideways = std::max(worst_sideways, std::abs(world.position(s.id).x() - s.position.x()));
  }
  EXPECT_LT(worst_sideways, 0.1);
  // The top box's height (its centre above the ground) within 1%.
  const Real height = top.position.y();
  EXPECT_NEAR(world.position(top.id).y(), height, 0.01 * height);
}

// 5050 boxes at our default settings, 500 steps with sleeping off; the top box stays within
// 0.3 of where it started. Heavy, so shrunk to a 40-box base under the sanitizers.
TEST(Pyramid, LargePyramidStandsAfterFiveHundredSteps) {
#ifdef MINK_SANITIZED_BUILD
  SceneDef scene = pyramid_scene(40);
#else
  SceneDef scene = builtin_scene("pyramid_100");
#endif
  scene.world.enable_sleep = false;
  World world = build_world(scene);
  const std::vector<Start> starts = dynamic_bodies(world);
  const Start& top = top_box(starts);
  for (int i = 0; i < 500; ++i) world.step();
  EXPECT_LT((world.position(top.id) - top.position).norm(), 0.3);
  EXPECT_GT(world.counters().touching_contacts, starts.size());
}

// A 40-row pyramid at our default settings (60 Hz contacts, 5 substeps), sleeping off. Box2D v3
// (617d32ab) given the same pyramid and settings moves its top box by (0.0018, -0.075) in 500
// steps and holds it there. Ours must hold as well: with friction also solved in the biased
// pass the light boxes near the top walked, and the top box crept 0.6 m sideways.
TEST(Pyramid, FortyRowsHoldStillAsBox2dV3sDoAtOurSettings) {
  SceneDef scene = pyramid_scene(40);
  scene.world.enable_sleep = false;
  World world = build_world(scene);
  const std::vector<Start> starts = dynamic_bodies(world);
  const Start& top = top_box(starts);
  for (int i = 0; i < 400; ++i) world.step();
  const Vec2 before = world.position(top.id);
  for (int i = 0; i < 100; ++i) world.step();
  const Vec2 after = world.position(top.id);
  EXPECT_LT(std::abs(after.x() - top.position.x()), 0.05);
  EXPECT_LT(std::abs(after.y() - top.position.y()), 0.1);
  EXPECT_LT((after - before).norm(), 0.005);  // no longer moving
}

// Box2D v3's large_pyramid at its settings (30 Hz contacts, 4 substeps): soft contacts under
// the load of 100 rows give, so its top box sinks by 0.73 m in Box2D v3 itself (0.0174,
// 98.7678 after 500 steps of 1/60 s from (0, 99.5), measured with Box2D v3 617d32ab) and then
// holds. Ours must stand as that one does: its top box within 0.3 of Box2D v3's, sideways as
// well as down, and settled.
TEST(Pyramid, Box2dV3LargePyramidStandsAsBox2dV3sDoes) {
#ifdef MINK_SANITIZED_BUILD
  GTEST_SKIP() << "5050 boxes for 500 steps: too slow under the sanitizers";
#else
  World world = build_world(builtin_scene("large_pyramid"));
  const std::vector<Start> starts = dynamic_bodies(world);
  const Start& top = top_box(starts);
  for (int i = 0; i < 450; ++i) world.step();
  const Vec2 before = world.position(top.id);
  for (int i = 0; i < 50; ++i) world.step();
  const Vec2 box2d_v3_top(0.0174, 98.7678);
  EXPECT_LT((world.position(top.id) - box2d_v3_top).norm(), 0.3);
  // No longer sinking (it may still sway sideways by a centimetre or two as it comes to rest,
  // as Box2D v3's does by one).
  EXPECT_LT(std::abs(world.position(top.id).y() - before.y()), 0.02);
#endif
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// Carrying manifolds along while pairs barely move must not change what the stack does:
// against the full narrowphase every step, the same boxes end up within a millimetre.
TEST(Pyramid, ManifoldReuseMatchesTheFullNarrowphase) {
  const auto [reused, full] =
      test::stepped_twins(15, 300, [](WorldDef& def) { def.reuse_manifolds = false; });
  const std::vector<BodyId> a = reused.bodies(), b = full.bodies();
  Real worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, (reused.position(a[i]) - full.position(b[i])).norm());
  }
  EXPECT_LT(worst, 1e-3);
}

}  // namespace
}  // namespace mink
