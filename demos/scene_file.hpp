#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "mink/engine/scene.hpp"
#include "mink/error.hpp"

namespace mink::cli {

// A scene file that cannot be used: the message starts with the JSON path of the offending
// value (e.g. "bodies[3].shapes[0].points[2]") and says what is wrong. An
// InvalidArgumentError, so `mink` exits with code 2 (bad input).
class SceneFileError : public InvalidArgumentError {
 public:
  SceneFileError(const std::string& json_path, const std::string& problem)
      : InvalidArgumentError(json_path + ": " + problem), json_path_(json_path) {}
  const std::string& json_path() const noexcept { return json_path_; }

 private:
  std::string json_path_;
};

// The scene format of docs/scene-format.md. Parsing checks everything a run needs (every
// field's type and range, every hull, the world settings) before it returns, so a bad file
// never starts a run. `source` names the file in messages.
SceneDef parse_scene_json(std::string_view text, const std::string& source = "scene");
SceneDef load_scene_file(const std::filesystem::path& path);

// Every field written out (points as given, no helpers), doubles in shortest round-trip form.
std::string scene_to_json(const SceneDef& scene);
void save_scene_file(const std::filesystem::path& path, const SceneDef& scene);

// A built-in's name, or else a path to a scene file.
SceneDef resolve_scene(const std::string& name_or_path);

}  // namespace mink::cli
