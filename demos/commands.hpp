#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <iosfwd>
#include <string>

namespace mink::cli {

// Each command registers its subcommand and returns the action that runs it; the action
// returns the exit code.
using Action = std::function<int()>;

struct Streams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
};

Action add_hull_command(CLI::App& app, Streams streams);
Action add_demo_command(CLI::App& app, Streams streams);
Action add_overlap_command(CLI::App& app, Streams streams);
Action add_crosscheck_command(CLI::App& app, Streams streams);
Action add_paper_command(CLI::App& app, Streams streams);
Action add_scenes_command(CLI::App& app, Streams streams);
Action add_export_scene_command(CLI::App& app, Streams streams);
Action add_run_command(CLI::App& app, Streams streams);
Action add_replay_command(CLI::App& app, Streams streams);
Action add_compare_command(CLI::App& app, Streams streams);
Action add_sandbox_command(CLI::App& app, Streams streams);
Action add_sweep_command(CLI::App& app, Streams streams);

// The SCENE argument of the commands that run a scene: a built-in's name or a scene file,
// resolved by resolve_scene (scene_file.hpp). `scene` holds the default.
void add_scene_argument(CLI::App& command, std::string& scene);

// Runs `mink` with the given arguments; what main() does, callable from tests.
int run(int argc, const char* const* argv, Streams streams);

}  // namespace mink::cli
