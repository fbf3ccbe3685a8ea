// `mink sandbox` in its SDL2 window under Xvfb (a ctest entry run inside xvfb-run): scripted
// input goes through SDL's event queue, and the screenshots show what it did.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "mink/render/png_file.hpp"

namespace {

using Rgb = std::array<std::uint8_t, 3>;

// World::draw's colours: an awake dynamic body, and an AABB outline.
constexpr Rgb kDynamic{230, 179, 179};
constexpr Rgb kAabb{230, 77, 230};

Rgb rgb(const mink::Image& image, int x, int y) {
  const auto p = image.at(x, y);
  return {p[0], p[1], p[2]};
}

int count(const mink::Image& image, Rgb colour) {
  int found = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) found += rgb(image, x, y) == colour;
  }
  return found;
}

// Runs `mink sandbox pyramid` at 640 x 480 with the script and returns its screenshot.
mink::Image shoot(const std::string& name, const std::string& script) {
  const auto dir = std::filesystem::path(testing::TempDir());
  const auto script_file = dir / ("mink_sandbox_" + name + ".txt");
  const auto shot = dir / ("mink_sandbox_" + name + ".png");
  std::ofstream(script_file) << script;
  std::filesystem::remove(shot);
  const std::vector<std::string> arguments = {
      "mink",         "sandbox",     "pyramid", "--script", script_file.string(),
      "--screenshot", shot.string(), "--width", "640",      "--height",
      "480"};
  std::vector<const char*> argv;
  for (const std::string& a : arguments) argv.push_back(a.c_str());
  std::istringstream in;
  std::ostringstream out;
  std::ostringstream err;
  const int code = mink::cli::run(static_cast<int>(argv.size()), argv.data(), {in, out, err});
  EXPECT_EQ(code, 0) << err.str();
  EXPECT_NE(out.str().find("wrote"), std::string::npos) << out.str();
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
  EXPECT_NE(rgb(before, 320, 110), kDynamic);  // empty space above the pyramid
  EXPECT_GT(count(before, kDynamic), 1000);    // the pyramid's boxes
  EXPECT_EQ(count(before, kAabb), 0);

  const mink::Image dropped = shoot("dropped",
                                    "0 key space\n"
                                    "0.1 mouse_down 320 110\n"
                                    "0.15 mouse_up 320 110\n"
                                    "0.2 key s\n"
                                    "0.3 screenshot\n"
                                    "0.35 quit\n");
  EXPECT_EQ(rgb(dropped, 320, 110), kDynamic);  // the dropped hull, where the click was
  EXPECT_EQ(count(dropped, kAabb), 0);

  const mink::Image toggled =
      shoot("toggled", "0 key space\n0.1 key 2\n0.2 screenshot\n0.25 quit\n");
  EXPECT_GT(count(toggled, kAabb), 500);  // key 2 turned the AABB layer on
}

}  // namespace
