#include <SDL.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "mink/render/input_script.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/sdl_window.hpp"
#include "sandbox.hpp"
#include "scene_view.hpp"

namespace mink::cli {

namespace {

struct SandboxOptions {
  std::string scene = "pyramid";
  std::string script;
  std::string screenshot;
  std::string size = "1280x720";
  std::string record;
};

void handle(Sandbox& sandbox, const SDL_Event& event) {
  switch (event.type) {
    case SDL_QUIT:
      sandbox.key("escape");
      break;
    case SDL_KEYDOWN:
      sandbox.key(SDL_GetKeyName(event.key.keysym.sym));
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.button == SDL_BUTTON_LEFT) {
        sandbox.mouse_down(Vec2(event.button.x + 0.5, event.button.y + 0.5));
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.button == SDL_BUTTON_LEFT) {
        sandbox.mouse_up(Vec2(event.button.x + 0.5, event.button.y + 0.5));
      }
      break;
    case SDL_MOUSEMOTION:
      sandbox.mouse_move(Vec2(event.motion.x + 0.5, event.motion.y + 0.5));
      break;
    default:
      break;
  }
}

int run_sandbox(const SandboxOptions& options, Streams streams) {
  int width = 0;
  int height = 0;
  parse_frame_size(options.size, width, height, {.require_even = false});
  SceneDef scene = resolve_scene(options.scene);
  std::optional<ScriptPlayer> player;
  if (!options.script.empty()) {
    std::ifstream in(options.script);
    if (!in) throw InvalidArgumentError("--script '" + options.script + "' cannot be read");
    player.emplace(parse_input_script(in, options.script));
  }
  SdlWindow window("mink sandbox", width, height, player ? false : true);
  Renderer renderer(window);
  Sandbox sandbox(renderer, options.scene, std::move(scene));
  if (!options.record.empty()) sandbox.record_to(options.record);
  // A scripted run's clock is the frame count at 60 frames a second, so it does the same
  // thing however fast the machine draws.
  Uint64 next_frame_ms = SDL_GetTicks64();
  for (std::uint64_t frame = 0; !sandbox.quit_requested(); ++frame) {
    sandbox.frame();
    if (player) {
      for (const ScriptEvent& event : player->due(static_cast<double>(frame) / 60.0)) {
        if (event.kind == ScriptEvent::Kind::screenshot) {
          if (options.screenshot.empty()) {
            throw InvalidArgumentError("--script '" + options.script + "' line " +
                                       std::to_string(event.line) +
                                       " takes a screenshot: give --screenshot FILE");
          }
          write_png(options.screenshot, renderer.read_pixels(3));
          streams.out << "wrote " << options.screenshot << '\n';
        } else if (event.kind == ScriptEvent::Kind::quit) {
          sandbox.key("escape");
        } else {
          window.push(event);
        }
      }
      if (player->finished() && !sandbox.quit_requested()) sandbox.key("escape");
    }
    SDL_Event event;
    while (SDL_PollEvent(&event) != 0) handle(sandbox, event);
    if (!player) {
      // Interactive: one world frame per 1/60 s of wall time, whatever the swap interval.
      const Uint64 now = SDL_GetTicks64();
      if (now < next_frame_ms) SDL_Delay(static_cast<Uint32>(next_frame_ms - now));
      next_frame_ms = std::max(now, next_frame_ms) + 16;
    }
  }
  if (const std::optional<std::size_t> steps = sandbox.finish_recording()) {
    streams.out << "recorded: " << options.record << " (" << *steps << " steps)\n";
  }
  return kSuccess;
}

}  // namespace

Action add_sandbox_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<SandboxOptions>();
  CLI::App* command = app.add_subcommand(
      "sandbox",
      "An SDL2 window on a scene: drag bodies, click to drop hulls, j joint mode (click "
      "body A or empty space, then body B: a revolute joint there), space pause, s step, r "
      "reset, n next scene, 1-9 debug layers, q quit.");
  add_scene_argument(*command, options->scene);
  command->add_option("--script", options->script,
                      "timed input events, one a line: TIME key NAME | mouse_down X Y | "
                      "mouse_move X Y | mouse_up X Y | screenshot | quit (times in seconds "
                      "at 60 frames a second)");
  command->add_option("--screenshot", options->screenshot, "PNG file for screenshot events");
  command->add_option("--size", options->size, "window size WIDTHxHEIGHT (default 1280x720)");
  command->add_option("--record", options->record,
                      "record the run for mink replay (the initial state, every call the "
                      "sandbox and your input make, each step's state hash); a reset is "
                      "recorded, a switch to another scene ends the recording");
  return [options, streams] { return run_sandbox(*options, streams); };
}

}  // namespace mink::cli
