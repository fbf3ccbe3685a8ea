// The SDL2 window under a display (run by ctest inside xvfb-run): the same renderer draws a
// static scene into it, a scripted screenshot saves it, and scripted input arrives as SDL
// events.

#include "mink/render/sdl_window.hpp"

#include <SDL.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <vector>

#include "mink/error.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/renderer.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Color;
using mink::Vec2;
using mink_test::count_pixels;
using mink_test::to_rgba;

constexpr Color kBackground{0.2f, 0.4f, 0.6f, 1};
constexpr Color kRed{1, 0, 0, 1};
constexpr Color kWhite{1, 1, 1, 1};

std::vector<mink::ScriptEvent> parse(const std::string& text) {
  std::istringstream in(text);
  return mink::parse_input_script(in, "test script");
}

TEST(SdlWindow, ScriptedScreenshotOfAStaticDrawing) {
  mink::SdlWindow window("mink window test", 320, 240, false);
  ASSERT_EQ(window.width(), 320);
  ASSERT_EQ(window.height(), 240);
  mink::Renderer renderer(window);
  renderer.camera().fit(Vec2(0, 0), Vec2(32, 24), 0);
  const auto path = mink_test::temp_path("mink_window_screenshot.png");
  std::filesystem::remove(path);
  mink::ScriptPlayer player(parse("0.25 screenshot\n0.5 quit\n"));
  bool quit = false;
  int frames = 0;
  for (int frame = 0; !quit && frame < 100; ++frame) {
    renderer.begin_frame(kBackground);
    const Vec2 square[] = {{4, 14}, {12, 14}, {12, 22}, {4, 22}};
    renderer.draw_polygon(square, kRed, kWhite);
    renderer.draw_overlay("frame " + std::to_string(frame));
    renderer.end_frame();
    ++frames;
    for (const mink::ScriptEvent& event : player.due(frame / 60.0)) {
      if (event.kind == mink::ScriptEvent::Kind::screenshot) {
        mink::write_png(path, renderer.read_pixels(3));
      }
      quit |= event.kind == mink::ScriptEvent::Kind::quit;
    }
    SDL_Event event;
    while (SDL_PollEvent(&event) != 0) {
    }
  }
  EXPECT_TRUE(quit);
  EXPECT_EQ(frames, 31);  // frame 30 is at 0.5 s
  const mink::Image shot = mink::read_png(path);
  std::filesystem::remove(path);
  ASSERT_EQ(shot.width, 320);
  ASSERT_EQ(shot.height, 240);
  // The square's centre (8, 18) is pixel (80, 60); the far corner is background; the
  // overlay's text is at the top left.
  EXPECT_EQ(shot.at(80, 60), to_rgba(kRed));
  EXPECT_EQ(shot.at(300, 220), to_rgba(kBackground));
  const int white = count_pixels(shot, to_rgba(kWhite), {0, 0, 150, 30});
  EXPECT_GT(white, 50);
}

TEST(SdlWindow, FramesFollowAResizedWindow) {
  mink::SdlWindow window("mink resize test", 200, 100, true);
  mink::Renderer renderer(window);
  renderer.camera().fit(Vec2(-1, -1), Vec2(1, 1), 0);
  SDL_SetWindowSize(window.handle(), 260, 180);
  // The X server applies the size asynchronously; give it a moment.
  for (int i = 0; i < 100 && window.width() != 260; ++i) {
    SDL_PumpEvents();
    SDL_Delay(10);
  }
  ASSERT_EQ(window.width(), 260);
  ASSERT_EQ(window.height(), 180);
  renderer.begin_frame(kBackground);
  const Vec2 square[] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  renderer.draw_polygon(square, kRed, kRed);
  renderer.end_frame();
  const mink::Image frame = renderer.read_pixels();
  EXPECT_EQ(frame.width, 260);
  EXPECT_EQ(frame.height, 180);
  // The camera kept its zoom and now centres on the new frame's middle.
  EXPECT_EQ(renderer.camera().world_to_pixel(Vec2(0, 0)), Vec2(130, 90));
  EXPECT_EQ(frame.at(130, 90)[0], 255);
  EXPECT_EQ(frame.at(130, 90)[1], 0);
}

TEST(SdlWindow, ScriptedInputArrivesAsSdlEvents) {
  mink::SdlWindow window("mink input test", 200, 150, false);
  const std::uint32_t id = SDL_GetWindowID(window.handle());
  SDL_Event event;
  while (SDL_PollEvent(&event) != 0) {
  }
  for (const mink::ScriptEvent& e :
       parse("0 key space\n0 mouse_down 20 30\n0 mouse_move 40 50\n0 mouse_up 40 50 right\n")) {
    window.push(e);
  }
  std::vector<SDL_Event> seen;
  while (SDL_PollEvent(&event) != 0) {
    if (event.type == SDL_KEYDOWN || event.type == SDL_KEYUP || event.type == SDL_MOUSEBUTTONDOWN ||
        event.type == SDL_MOUSEBUTTONUP || event.type == SDL_MOUSEMOTION) {
      seen.push_back(event);
    }
  }
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_EQ(seen[0].type, SDL_KEYDOWN);
  EXPECT_EQ(seen[0].key.keysym.sym, SDLK_SPACE);
  EXPECT_EQ(seen[0].key.windowID, id);
  EXPECT_EQ(seen[1].type, SDL_KEYUP);
  EXPECT_EQ(seen[2].type, SDL_MOUSEBUTTONDOWN);
  EXPECT_EQ(seen[2].button.button, SDL_BUTTON_LEFT);
  EXPECT_EQ(seen[2].button.x, 20);
  EXPECT_EQ(seen[2].button.y, 30);
  EXPECT_EQ(seen[3].type, SDL_MOUSEMOTION);
  EXPECT_EQ(seen[3].motion.x, 40);
  EXPECT_EQ(seen[4].type, SDL_MOUSEBUTTONUP);
  EXPECT_EQ(seen[4].button.button, SDL_BUTTON_RIGHT);

  mink::ScriptEvent unknown;
  unknown.kind = mink::ScriptEvent::Kind::key;
  unknown.key = "NoSuchKey";
  EXPECT_THROW(window.push(unknown), mink::InvalidArgumentError);
}

}  // namespace
