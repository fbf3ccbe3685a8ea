// The sandbox without a window: keys, dragging and dropping drive the world as documented,
// drawn headless through the same renderer the window uses.

#include "sandbox.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "cli_test_support.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "render_test_support.hpp"
#include "sandbox_scenes.hpp"

namespace {

using mink::Vec2;
using mink::cli::Sandbox;
using mink_test::count_pixels;
using mink_test::Headless;
using mink_test::PixelRect;
using mink_test::to_rgba;

// World::draw's colours for an awake dynamic body and for a joint.
constexpr mink::Color kDynamic{0.9f, 0.7f, 0.7f, 1};
constexpr mink::Color kJoint{0.5f, 0.8f, 0.8f, 1};

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

// b steps back to the last moment kept (every 30 steps): a hull dropped since is gone, the
// world is bitwise as it was, and stepping on repeats the run without the drop.
TEST(Sandbox, StepsBackInTime) {
  Headless frame(mink::GlBackend::osmesa, 480, 360);
  Sandbox sandbox(*frame.renderer, "rain_mixed");
  sandbox.key("b");  // nothing kept yet: nothing happens
  EXPECT_EQ(sandbox.world().step_count(), 0u);
  for (int i = 0; i < 30; ++i) sandbox.frame();
  const std::uint64_t at_30 = sandbox.world().state_hash();
  const std::size_t bodies = sandbox.world().body_count();
  sandbox.mouse_down(Vec2(240.5, 90.5));
  sandbox.mouse_up(Vec2(240.5, 90.5));
  for (int i = 0; i < 10; ++i) sandbox.frame();
  EXPECT_EQ(sandbox.world().body_count(), bodies + 1);
  sandbox.key("b");
  EXPECT_EQ(sandbox.world().step_count(), 30u);
  EXPECT_EQ(sandbox.world().state_hash(), at_30);
  EXPECT_EQ(sandbox.world().body_count(), bodies);
  for (int i = 0; i < 40; ++i) sandbox.frame();
  Sandbox straight(*frame.renderer, "rain_mixed");
  for (int i = 0; i < 70; ++i) straight.frame();
  EXPECT_EQ(sandbox.world().state_hash(), straight.world().state_hash());
  // Twice back: from step 70 to 60, then to 30.
  sandbox.key("b");
  EXPECT_EQ(sandbox.world().step_count(), 60u);
  sandbox.key("b");
  EXPECT_EQ(sandbox.world().step_count(), 30u);
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

// Pixels of `colour` in the square of half side `half` (metres) about `center` (world).
int pixels_near(const mink::Image& image, const mink::Camera& camera, const Vec2& center,
                mink::Real half, const mink::Color& colour) {
  const Vec2 low = camera.world_to_pixel(center + Vec2(-half, half));
  const Vec2 high = camera.world_to_pixel(center + Vec2(half, -half));
  return count_pixels(image, to_rgba(colour),
                      PixelRect{static_cast<int>(low.x()), static_cast<int>(low.y()),
                                static_cast<int>(high.x()), static_cast<int>(high.y())});
}

// The stack scene's top box, grabbed off its centre, is pulled sideways off the stack: the
// grabbed point ends under the cursor, the frame shows the box there and not where it was, and
// the two boxes below hardly stir.
TEST(Sandbox, DragsTheTopBoxOffAStackWithAMotorJoint) {
  Headless frame(mink::GlBackend::osmesa, 480, 360);
  Sandbox sandbox(*frame.renderer, "stack", mink_test::stack_scene());
  const mink::World& world = sandbox.world();
  const mink::BodyId top = world.bodies()[mink_test::kTop];
  const std::array<mink::BodyId, 2> below{world.bodies()[mink_test::kBottom],
                                          world.bodies()[mink_test::kMiddle]};
  const mink::Camera& camera = frame.renderer->camera();
  const Vec2 start = world.world_center(top);
  const std::array<Vec2, 2> below_start{world.world_center(below[0]), world.world_center(below[1])};
  const Vec2 grabbed = start + Vec2(0.3, -0.2);
  const Vec2 grab_local = world.pose(top).apply_inverse(grabbed);
  sandbox.mouse_down(camera.world_to_pixel(grabbed));
  ASSERT_EQ(sandbox.dragged(), top);
  ASSERT_TRUE(sandbox.drag_joint());
  EXPECT_EQ(world.joint_type(*sandbox.drag_joint()), mink::JointType::motor);
  EXPECT_EQ(world.joint_body_b(*sandbox.drag_joint()), top);
  const Vec2 cursor_pixel = camera.world_to_pixel(grabbed + Vec2(2.5, 0.5));
  sandbox.mouse_move(cursor_pixel);
  const Vec2 cursor = camera.pixel_to_world(cursor_pixel);
  mink::Real fastest_below = 0;
  for (int i = 0; i < 60; ++i) {
    sandbox.frame();
    for (const mink::BodyId body : below) {
      fastest_below = std::max(fastest_below, world.linear_velocity(body).norm());
    }
  }
  // The grabbed point, not the centre, is under the cursor.
  EXPECT_LT((world.pose(top).apply(grab_local) - cursor).norm(), 0.01);
  EXPECT_GT((world.world_center(top) - cursor).norm(), 0.3);
  EXPECT_LT(fastest_below, 0.05);
  for (std::size_t i = 0; i < below.size(); ++i) {
    EXPECT_LT((world.world_center(below[i]) - below_start[i]).norm(), 0.01);
  }
  // The frame: the box's colour fills its new place (but for the joint's marks at its centre)
  // and is gone from the old one, above the middle box.
  const mink::Image image = frame.renderer->read_pixels();
  const mink::Real side = 0.8 * camera.pixels_per_unit();
  EXPECT_GT(pixels_near(image, camera, world.world_center(top), 0.4, kDynamic), 0.9 * side * side);
  EXPECT_EQ(pixels_near(image, camera, start, 0.4, kDynamic), 0);
  sandbox.mouse_up(cursor_pixel);
  EXPECT_FALSE(sandbox.dragged());
  EXPECT_EQ(world.joint_count(), 0u);
}

// The drag's force is capped for heavy bodies: a box 1000 times as heavy as the others does
// not budge where a light one follows the cursor.
TEST(Sandbox, HeavyBodiesResistTheDrag) {
  Headless frame(mink::GlBackend::osmesa, 320, 240);
  for (const std::size_t index : {mink_test::kHeavy, mink_test::kTop}) {
    Sandbox sandbox(*frame.renderer, "stack", mink_test::stack_scene());
    const mink::BodyId body = sandbox.world().bodies()[index];
    const mink::Camera& camera = frame.renderer->camera();
    const Vec2 start = sandbox.world().world_center(body);
    sandbox.mouse_down(camera.world_to_pixel(start));
    ASSERT_EQ(sandbox.dragged(), body);
    const Vec2 cursor_pixel = camera.world_to_pixel(start + Vec2(-2, 0.5));
    sandbox.mouse_move(cursor_pixel);
    for (int i = 0; i < 60; ++i) sandbox.frame();
    const Vec2 moved = sandbox.world().world_center(body) - start;
    if (index == mink_test::kHeavy) {
      EXPECT_LT(moved.norm(), 0.01) << "the heavy box moved " << moved.transpose();
    } else {
      EXPECT_LT((moved - (camera.pixel_to_world(cursor_pixel) - start)).norm(), 0.01)
          << "the light box moved " << moved.transpose();
    }
  }
}

// Joint mode: a click on empty space then one on a box pins the box to the world there; a
// click on that box then one on a second box hinges them at the second click. The pair swings
// as a double pendulum and both joints hold.
TEST(Sandbox, JointModeMakesRevoluteJointsThatHold) {
  mink::SceneDef scene = mink_test::stack_scene();
  // Lift the top box and the heavy one (made light) into the air beside each other.
  scene.bodies[mink_test::kTop].body.position = Vec2(0, 5);
  scene.bodies[mink_test::kHeavy].body.position = Vec2(1.2, 5);
  scene.bodies[mink_test::kHeavy].shapes[0].density = 1;
  Headless frame(mink::GlBackend::osmesa, 480, 360);
  Sandbox sandbox(*frame.renderer, "stack", scene);
  const mink::World& world = sandbox.world();
  const mink::BodyId first = world.bodies()[mink_test::kTop];
  const mink::BodyId second = world.bodies()[mink_test::kHeavy];
  const mink::Camera& camera = frame.renderer->camera();
  const auto click = [&](const Vec2& at) {
    sandbox.mouse_down(camera.world_to_pixel(at));
    sandbox.mouse_up(camera.world_to_pixel(at));
  };
  sandbox.key("space");
  sandbox.key("j");
  ASSERT_TRUE(sandbox.joint_mode());
  const std::size_t bodies = world.body_count();
  click(Vec2(-2, 6));  // empty space: the world
  EXPECT_TRUE(sandbox.joint_first());
  EXPECT_EQ(world.joint_count(), 0u);
  click(Vec2(-0.4, 5.4));  // the first box, near its top-left corner
  ASSERT_EQ(world.joint_count(), 1u);
  EXPECT_FALSE(sandbox.joint_first());
  EXPECT_EQ(world.body_count(), bodies + 1);  // the static world anchor, without shapes
  const mink::JointId pin = world.joints()[0];
  EXPECT_EQ(world.joint_type(pin), mink::JointType::revolute);
  EXPECT_EQ(world.body_type(world.joint_body_a(pin)), mink::BodyType::static_body);
  EXPECT_TRUE(world.body_shapes(world.joint_body_a(pin)).empty());
  EXPECT_EQ(world.joint_body_b(pin), first);
  EXPECT_LT((world.joint_anchor_b(pin) - Vec2(-0.4, 5.4)).norm(), 0.01);
  click(Vec2(0, 5));  // the same body twice makes nothing
  click(Vec2(0.1, 5));
  EXPECT_EQ(world.joint_count(), 1u);
  click(Vec2(0, 5));
  click(Vec2(0.75, 5));  // the second box, at its edge facing the first
  ASSERT_EQ(world.joint_count(), 2u);
  const mink::JointId hinge = world.joints()[1];
  EXPECT_EQ(world.joint_type(hinge), mink::JointType::revolute);
  EXPECT_EQ(world.joint_body_a(hinge), first);
  EXPECT_EQ(world.joint_body_b(hinge), second);
  EXPECT_LT((world.joint_anchor_b(hinge) - Vec2(0.75, 5)).norm(), 0.01);
  EXPECT_EQ(world.body_count(), bodies + 1);  // joint mode's clicks neither drop nor drag

  sandbox.key("space");
  const Vec2 start = world.world_center(second);
  mink::Real widest = 0;
  for (int i = 0; i < 60; ++i) {
    sandbox.frame();
    for (const mink::JointId joint : {pin, hinge}) {
      widest = std::max(widest, (world.joint_anchor_a(joint) - world.joint_anchor_b(joint)).norm());
    }
  }
  EXPECT_LT(widest, 0.01);
  EXPECT_GT((world.world_center(second) - start).norm(), 1.0);  // it swung
  // The sandbox draws the joints (layer 9).
  EXPECT_GT(count_pixels(frame.renderer->read_pixels(), to_rgba(kJoint)), 0);
  sandbox.key("9");
  sandbox.frame();
  EXPECT_EQ(count_pixels(frame.renderer->read_pixels(), to_rgba(kJoint)), 0);
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

// A recorded sandbox session replays with equal state hashes at 1 and 2 workers: rain_mixed
// with a body dragged, a hull dropped, a revolute joint pinned in joint mode, a step back in
// time and a reset, all recorded through the world's recorder hook and written by
// finish_recording. A switch to another scene ends a recording and writes it.
TEST(Sandbox, ARecordedSessionReplaysWithEqualHashes) {
  const auto dir = mink_test::fresh_dir("sandbox_recording");
  const auto file = dir / "session.rec";
  Headless frame(mink::GlBackend::osmesa, 480, 360);
  Sandbox sandbox(*frame.renderer, "rain_mixed");
  sandbox.record_to(file);
  EXPECT_TRUE(sandbox.recording());
  const mink::Camera& camera = frame.renderer->camera();
  std::size_t steps = 0;
  const auto frames = [&](int count) {
    for (int i = 0; i < count; ++i) sandbox.frame();
    steps += static_cast<std::size_t>(count);
  };
  const auto lowest_dynamic = [&] {
    mink::BodyId found{};
    mink::Real lowest = 1e300;
    for (const mink::BodyId body : sandbox.world().bodies()) {
      if (sandbox.world().body_type(body) != mink::BodyType::dynamic) continue;
      if (sandbox.world().position(body).y() < lowest) {
        lowest = sandbox.world().position(body).y();
        found = body;
      }
    }
    return found;
  };
  frames(40);
  const Vec2 grabbed = sandbox.world().world_center(lowest_dynamic());
  sandbox.mouse_down(camera.world_to_pixel(grabbed));
  ASSERT_TRUE(sandbox.dragged());
  sandbox.mouse_move(camera.world_to_pixel(grabbed + Vec2(1, 2)));
  frames(20);
  sandbox.mouse_up(camera.world_to_pixel(grabbed + Vec2(1, 2)));
  sandbox.mouse_down(Vec2(240.5, 30.5));  // high above the floor: a dropped hull
  sandbox.mouse_up(Vec2(240.5, 30.5));
  frames(15);
  const std::size_t joints_before = sandbox.world().joint_count();
  sandbox.key("j");
  const Vec2 pin = sandbox.world().world_center(lowest_dynamic());
  sandbox.mouse_down(camera.world_to_pixel(pin + Vec2(0, 20)));  // empty space: the world
  sandbox.mouse_up(camera.world_to_pixel(pin + Vec2(0, 20)));
  sandbox.mouse_down(camera.world_to_pixel(pin));
  sandbox.mouse_up(camera.world_to_pixel(pin));
  sandbox.key("j");
  EXPECT_EQ(sandbox.world().joint_count(), joints_before + 1) << "no joint pinned";
  frames(10);
  sandbox.key("b");  // back to step 60, before the joint
  EXPECT_EQ(sandbox.world().step_count(), 60u);
  EXPECT_EQ(sandbox.world().joint_count(), joints_before);
  frames(25);
  sandbox.key("r");
  EXPECT_EQ(sandbox.world().step_count(), 0u);
  frames(30);
  const std::uint64_t final_hash = sandbox.world().state_hash();
  const std::optional<std::size_t> recorded = sandbox.finish_recording();
  ASSERT_TRUE(recorded);
  EXPECT_EQ(*recorded, steps);
  EXPECT_FALSE(sandbox.recording());

  const mink::cli::Recording recording = mink::cli::load_recording(file);
  for (const int workers : {1, 2}) {
    const mink::cli::ReplayResult result = mink::cli::replay(recording, workers);
    EXPECT_FALSE(result.diverged_at)
        << workers << " workers: diverged at step " << result.diverged_at.value_or(0);
    EXPECT_EQ(result.steps, steps) << workers << " workers";
  }
  // The recording's last step is the session's last state.
  ASSERT_FALSE(recording.entries.empty());
  EXPECT_TRUE(recording.entries.back().is_step);
  EXPECT_EQ(recording.entries.back().hash, final_hash);

  // A recording holds one world: the next scene ends it, and it is written then.
  const auto second = dir / "until_switch.rec";
  sandbox.record_to(second);
  frames(5);
  sandbox.key("n");
  EXPECT_FALSE(sandbox.recording());
  EXPECT_FALSE(sandbox.finish_recording());
  EXPECT_EQ(mink::cli::replay(mink::cli::load_recording(second), 1).steps, 5u);
}
