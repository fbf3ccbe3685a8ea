#include <iostream>
#include <map>

#include "commands.hpp"
#include "exit_codes.hpp"

namespace mink::cli {

int run(int argc, const char* const* argv, Streams streams) {
  CLI::App app{
      "mink - Minkowski, a 2D rigid-body physics sandbox built on exact convex hulls and GJK.\n"
      "Exit codes: 0 success, 1 internal error, 2 bad input or usage, 3 degenerate point set, 4 "
      "runtime failure (GL, ffmpeg, the file system).",
      "mink"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "help for every command");
  std::map<std::string, Action> actions;
  actions["hull"] = add_hull_command(app, streams);
  actions["demo"] = add_demo_command(app, streams);
  actions["overlap"] = add_overlap_command(app, streams);
#ifdef MINK_WITH_BOX2D
  actions["crosscheck"] = add_crosscheck_command(app, streams);
  actions["compare"] = add_compare_command(app, streams);
#endif
  actions["paper"] = add_paper_command(app, streams);
  actions["scenes"] = add_scenes_command(app, streams);
  actions["export-scene"] = add_export_scene_command(app, streams);
  actions["run"] = add_run_command(app, streams);
  actions["replay"] = add_replay_command(app, streams);
  actions["sweep"] = add_sweep_command(app, streams);
#ifdef MINK_WITH_SANDBOX
  actions["sandbox"] = add_sandbox_command(app, streams);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    streams.out << app.help();
    return kSuccess;
  } catch (const CLI::CallForAllHelp&) {
    streams.out << app.help("", CLI::AppFormatMode::All);
    return kSuccess;
  } catch (const CLI::ParseError& error) {
    // Help for a subcommand arrives as CallForHelp from that subcommand's parse.
    streams.err << "mink: " << error.what() << "\nRun 'mink --help' for usage.\n";
    return kBadInput;
  }
  for (const CLI::App* command : app.get_subcommands()) {
    try {
      return actions.at(command->get_name())();
    } catch (const std::exception& error) {
      return report_error(error, streams.err);
    }
  }
  return kBadInput;
}

}  // namespace mink::cli
