// The sandbox without a window: keys, dragging and dropping drive the world as documented,
// drawn headless through the same renderer the window uses.

#include "sandbox.hpp"

#include <gtest/gtest.h>

#include "cli_test_support.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Vec2;
using mink::cli::Sandbox;
using mink_test::Headless;
using mink_test::to_rgba;

// World::draw's colour for an awake dynamic body.
constexpr mink::Color kDynamic{0.9f, 0.7f, 0.7f, 1};

TEST(Sandbox, KeysPauseStepResetSwitchAndToggle) {
  Headless frame(mink::GlBackend::osmesa, 320, 240);
  Sandbox sandbox(*frame.renderer, "pyramid");
  sandbox.frame();
  EXPECT_EQ(sandbox.world().step_count(), 1u);
  sandbox.key("Space");
  EXPECT_TRUE(sandbox.paused());
  sandbox.frame();
  EXPECT_EQ(sandbox.world().step_count(), 1u);
  sandbox.key("s");
  sandbox.frame();
  sandbox.frame();
  EXPECT_EQ(sandbox.world().step_count(), 2u);  // one step per press
  const std::uint32_t layers = sandbox.layers();
  sandbox.key("2");
  EXPECT_EQ(sandbox.layers(), layers ^ mink::draw_aabbs);
  sandbox.key("r");
  EXPECT_EQ(sandbox.world().step_count(), 0u);
  const std::string first = sandbox.scene();
  sandbox.key("n");
  EXPECT_NE(sandbox.scene(), first);
  EXPECT_FALSE(sandbox.quit_requested());
  sandbox.key("q");
  EXPECT_TRUE(sandbox.quit_requested());
}

// The sandbox steps a scene with its schedule: rain drops 275 bodies before steps 0, 8, ...,
// and a reset starts the schedule again.
TEST(Sandbox, RunsTheScenesSchedule) {
  Headless frame(mink::GlBackend::osmesa, 320, 240);
  Sandbox sandbox(*frame.renderer, "rain");
  EXPECT_EQ(sandbox.world().body_count(), 1u);
  for (int i = 0; i < 9; ++i) sandbox.frame();
  EXPECT_EQ(sandbox.world().body_count(), 1u + 2 * 275u);
  sandbox.key("r");
  EXPECT_EQ(sandbox.world().body_count(), 1u);
  sandbox.frame();
  EXPECT_EQ(sandbox.world().body_count(), 1u + 275u);
}

TEST(Sandbox, ClickOnEmptySpaceDropsAHullThere) {
  Headless frame(mink::GlBackend::osmesa, 480, 360);
  Sandbox sandbox(*frame.renderer, "pyramid");
  sandbox.key("space");
  const Vec2 pixel(240.5, 90.5);  // below the overlay, above the pyramid
  const Vec2 world = frame.renderer->camera().pixel_to_world(pixel);
  ASSERT_TRUE(sandbox.world().query_point(world).empty());
  const std::size_t bodies = sandbox.world().body_count();
  sandbox.mouse_down(pixel);
  sandbox.mouse_up(pixel);
  EXPECT_FALSE(sandbox.dragged());
  ASSERT_EQ(sandbox.world().body_count(), bodies + 1);
  EXPECT_FALSE(sandbox.world().query_point(world).empty());
  sandbox.frame();
  const mink::Image image = frame.renderer->read_pixels();
  EXPECT_EQ(image.at(240, 90), to_rgba(kDynamic));
}

TEST(Sandbox, DraggingPullsTheGrabbedBodyToTheCursor) {
  Headless frame(mink::GlBackend::osmesa, 320, 240);
  Sandbox sandbox(*frame.renderer, "pyramid");
  // The top box of the pyramid.
  mink::BodyId top{};
  mink::Real best = -1e300;
  for (const mink::BodyId body : sandbox.world().bodies()) {
    if (sandbox.world().body_type(body) != mink::BodyType::dynamic) continue;
    if (sandbox.world().position(body).y() > best) {
      best = sandbox.world().position(body).y();
      top = body;
    }
  }
  const mink::Camera& camera = frame.renderer->camera();
  const Vec2 start = sandbox.world().world_center(top);
  sandbox.mouse_down(camera.world_to_pixel(start));
  ASSERT_TRUE(sandbox.dragged());
  EXPECT_EQ(*sandbox.dragged(), top);
  const Vec2 target = start + Vec2(4, 3);
  sandbox.mouse_move(camera.world_to_pixel(target));
  for (int i = 0; i < 90; ++i) sandbox.frame();
  EXPECT_LT((sandbox.world().world_center(top) - target).norm(), 0.5);
  sandbox.mouse_up(camera.world_to_pixel(target));
  EXPECT_FALSE(sandbox.dragged());
}

// A scene file works as a scene, as for `mink run`; reset rebuilds it, n goes on to the
// built-ins.
TEST(Sandbox, OpensAndResetsASceneFile) {
  const auto path = mink_test::fresh_dir("sandbox_scene") / "two.json";
  mink::SceneDef scene = mink::pyramid_scene(2);
  scene.bodies[1].body.angular_velocity = 3;
  mink::save_scene_file(path, scene);
  Headless frame(mink::GlBackend::osmesa, 64, 64);
  Sandbox sandbox(*frame.renderer, path.string());
  EXPECT_EQ(sandbox.scene(), path.string());
  ASSERT_EQ(sandbox.world().body_count(), 4u);
  const mink::BodyId spinning = sandbox.world().bodies()[1];
  EXPECT_EQ(sandbox.world().angular_velocity(spinning), 3);
  sandbox.frame();
  sandbox.key("r");
  EXPECT_EQ(sandbox.world().step_count(), 0u);
  EXPECT_EQ(sandbox.world().body_count(), 4u);
  EXPECT_EQ(sandbox.world().angular_velocity(sandbox.world().bodies()[1]), 3);
  sandbox.key("n");
  EXPECT_EQ(sandbox.scene(), mink::builtin_scene_names().front());
}

TEST(Sandbox, UnknownSceneIsNamed) {
  Headless frame(mink::GlBackend::osmesa, 64, 64);
  try {
    Sandbox sandbox(*frame.renderer, "no_such_scene");
    FAIL() << "expected InvalidArgumentError";
  } catch (const mink::InvalidArgumentError& error) {
    EXPECT_NE(std::string(error.what()).find("no_such_scene"), std::string::npos);
  }
}

}  // namespace
