#include <fstream>
#include <memory>
#include <ostream>
#include <string>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"

namespace mink::cli {

void add_scene_argument(CLI::App& command, std::string& scene) {
  command.add_option("scene", scene,
                     "built-in scene (see 'mink scenes') or scene file (default " + scene + ")");
}

Action add_scenes_command(CLI::App& app, Streams streams) {
  app.add_subcommand("scenes", "List the built-in scenes (each with its body count).");
  return [streams] {
    for (std::string_view name : builtin_scene_names()) {
      const SceneDef scene = builtin_scene(name);
      streams.out << name << " (" << scene.bodies.size() << " bodies"
                  << (scene.schedule ? "; changes as it runs" : "") << ")\n";
    }
    return static_cast<int>(kSuccess);
  };
}

Action add_export_scene_command(CLI::App& app, Streams streams) {
  auto name = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "export-scene", "Write a built-in scene as a scene file (docs/scene-format.md).");
  command->add_option("name", *name, "built-in scene name (see 'mink scenes')")->required();
  command->add_option("--out", *out, "file to write (default: standard output)");
  return [name, out, streams] {
    const SceneDef scene = builtin_scene(*name);
    if (scene.schedule) {
      streams.err << "note: scene '" << *name
                  << "' changes as it runs; a scene file holds its initial state only\n";
    }
    if (out->empty()) {
      streams.out << scene_to_json(scene);
    } else {
      save_scene_file(*out, scene);
      streams.out << "wrote " << *out << " (" << scene.bodies.size() << " bodies)\n";
    }
    return static_cast<int>(kSuccess);
  };
}

}  // namespace mink::cli
