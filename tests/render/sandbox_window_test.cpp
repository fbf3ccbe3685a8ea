// `mink sandbox` in its SDL2 window under Xvfb (a ctest entry run inside xvfb-run): scripted
// input goes through SDL's event queue, and the screenshots show what it did.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_support.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/render/png_file.hpp"
#include "render_test_support.hpp"
#include "sandbox_scenes.hpp"

namespace {

using mink_test::count_pixels;
using mink_test::PixelRect;
using mink_test::Rgb;

// World::draw's colours: an awake dynamic body, and an AABB outline.
constexpr Rgb kDynamic{230, 179, 179};
constexpr Rgb kAabb{230, 77, 230};

Rgb rgb(const mink::Image& image, int x, int y) {
  const auto p = image.at(x, y);
  return {p[0], p[1], p[2]};
}

// Runs `mink sandbox SCENE --size SIZE` with the script and returns its screenshot.
mink::Image shoot(const std::string& name, const std::string& script,
                  const std::string& scene = "pyramid", const std::string& size = "640x480") {
  const auto script_file = mink_test::temp_path("mink_sandbox_" + name + ".txt");
  const auto shot = mink_test::temp_path("mink_sandbox_" + name + ".png");
  mink_test::write_text(script_file, script);
  std::filesystem::remove(shot);
  const mink_test::CliResult result =
      mink_test::run_cli({"sandbox", scene, "--script", script_file.string(), "--screenshot",
                          shot.string(), "--size", size});
  EXPECT_EQ(result.code, 0) << result.err;
  EXPECT_NE(result.out.find("wrote"), std::string::npos) << result.out;
  std::filesystem::remove(script_file);
  mink::Image image = mink::read_png(shot);
  std::filesystem::remove(shot);
  return image;
}

TEST(SandboxWindow, ScriptedDropStepAndLayerToggle) {
  // Paused at once, so the pyramid stands still between runs.
  const mink::Image before = shoot("before", "0 key space\n0.2 screenshot\n0.25 quit\n");
  ASSERT_EQ(before.width, 640);
  ASSERT_EQ(before.height, 480);
  EXPECT_NE(rgb(before, 320, 110), kDynamic);       // empty space above the pyramid
  EXPECT_GT(count_pixels(before, kDynamic), 1000);  // the pyramid's boxes
  EXPECT_EQ(count_pixels(before, kAabb), 0);

  const mink::Image dropped = shoot("dropped",
                                    "0 key space\n"
                                    "0.1 mouse_down 320 110\n"
                                    "0.15 mouse_up 320 110\n"
                                    "0.2 key s\n"
                                    "0.3 screenshot\n"
                                    "0.35 quit\n");
  EXPECT_EQ(rgb(dropped, 320, 110), kDynamic);  // the dropped hull, where the click was
  EXPECT_EQ(count_pixels(dropped, kAabb), 0);

  const mink::Image toggled =
      shoot("toggled", "0 key space\n0.1 key 2\n0.2 screenshot\n0.25 quit\n");
  EXPECT_GT(count_pixels(toggled, kAabb), 500);  // key 2 turned the AABB layer on
}

// The stack scene's top box, dragged sideways off the stack by scripted mouse events through
// SDL: the frame shows it where the cursor went and no longer on the stack. Where the box is
// comes from the first frame's pixels, so the test does not assume the sandbox's camera.
TEST(SandboxWindow, DragsTheTopBoxOffAStack) {
  const auto scene_file = mink_test::temp_path("mink_sandbox_stack.json");
  mink::save_scene_file(scene_file, mink_test::stack_scene());
  const mink::Image before =
      shoot("stack_before", "0.1 screenshot\n0.15 quit\n", scene_file.string());
  // The top box: the run of its colour in the highest row that has any (the heavy box is two
  // boxes lower).
  int top_row = -1;
  int left = 0;
  int right = 0;
  for (int y = 0; y < before.height && top_row < 0; ++y) {
    for (int x = 0; x < before.width; ++x) {
      if (rgb(before, x, y) != kDynamic) continue;
      if (top_row < 0) {
        top_row = y;
        left = x;
      } else if (x != right + 1) {
        break;
      }
      right = x;
    }
  }
  ASSERT_GE(top_row, 0) << "no box in the first frame";
  const int side = right - left + 1;
  ASSERT_GT(side, 20) << "the box is too small to drag by pixels";
  const int x0 = (left + right) / 2;
  const int y0 = top_row + side / 2;
  const int x1 = x0 + 5 * side / 2;
  const int y1 = y0 - side / 2;
  ASSERT_LT(x1 + side, before.width);
  ASSERT_GE(y1 - side, 0);
  const std::string script =
      "0.2 mouse_down " + std::to_string(x0) + " " + std::to_string(y0) + "\n0.3 mouse_move " +
      std::to_string(x0 + side) + " " + std::to_string(y0 - side / 4) + "\n0.4 mouse_move " +
      std::to_string(x1) + " " + std::to_string(y1) + "\n1.4 screenshot\n1.45 quit\n";
  const mink::Image after = shoot("stack_after", script, scene_file.string());
  std::filesystem::remove(scene_file);
  // The squares of 80% of the box's side about the cursor and about where the box was: the
  // first all box (but for the joint's marks at the box's centre), the second none.
  const int half = 2 * side / 5;
  const auto near = [&](int x, int y) {
    return count_pixels(after, kDynamic, PixelRect{x - half, y - half, x + half, y + half});
  };
  EXPECT_GT(near(x1, y1), 0.9 * (2 * half) * (2 * half)) << script;
  EXPECT_EQ(near(x0, y0), 0) << script;
  EXPECT_GT(near(x0, y0 + side), 0.9 * (2 * half) * (2 * half));  // the middle box stays
}

// The SCENE argument and --size are those of `mink run`: a scene file opens, and a bad size or
// scene is a usage error before any window.
TEST(SandboxWindow, TakesASceneFileAndASize) {
  const auto scene_file = mink_test::temp_path("mink_sandbox_scene.json");
  mink::save_scene_file(scene_file, mink::pyramid_scene(2));
  const mink::Image shot = shoot("scene_file", "0 key space\n0.1 screenshot\n0.15 quit\n",
                                 scene_file.string(), "320x240");
  std::filesystem::remove(scene_file);
  ASSERT_EQ(shot.width, 320);
  ASSERT_EQ(shot.height, 240);
  EXPECT_GT(count_pixels(shot, kDynamic), 100);  // the file's three boxes

  const auto bad_size = mink_test::run_cli({"sandbox", "pyramid", "--size", "640"});
  EXPECT_EQ(bad_size.code, 2);
  EXPECT_NE(bad_size.err.find("--size '640' is not WIDTHxHEIGHT"), std::string::npos)
      << bad_size.err;
  const auto bad_scene = mink_test::run_cli({"sandbox", "no_such_scene"});
  EXPECT_EQ(bad_scene.code, 2);
  EXPECT_NE(bad_scene.err.find("'no_such_scene' is neither a built-in scene"), std::string::npos)
      << bad_scene.err;
}

}  // namespace

namespace {

// `mink sandbox --record` with scripted input through SDL's queue (a hull dropped, a drag, a
// step back, a reset) writes a recording that `mink replay` plays back with every step's state
// hash equal, at 1 and 2 threads.
TEST(SandboxWindow, ARecordedSessionReplays) {
  const auto script_file = mink_test::temp_path("mink_sandbox_record.txt");
  const auto recording = mink_test::temp_path("mink_sandbox_record.rec");
  std::filesystem::remove(recording);
  mink_test::write_text(script_file,
                        "0.2 mouse_down 320 60\n"
                        "0.25 mouse_up 320 60\n"
                        "0.6 mouse_down 320 300\n"
                        "0.7 mouse_move 200 200\n"
                        "0.9 mouse_up 200 200\n"
                        "1.1 key b\n"
                        "1.3 key r\n"
                        "1.5 quit\n");
  const mink_test::CliResult run =
      mink_test::run_cli({"sandbox", "rain_mixed", "--script", script_file.string(), "--record",
                          recording.string(), "--size", "640x480"});
  std::filesystem::remove(script_file);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("recorded: " + recording.string()), std::string::npos) << run.out;
  for (const char* threads : {"1", "2"}) {
    const mink_test::CliResult replayed =
        mink_test::run_cli({"replay", recording.string(), "--threads", threads});
    EXPECT_EQ(replayed.code, 0) << replayed.out << replayed.err;
    EXPECT_NE(replayed.out.find("every state hash equals the recording's"), std::string::npos)
        << replayed.out;
  }
  std::filesystem::remove(recording);
}

}  // namespace
