#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "mink/engine/scene.hpp"
#include "mink/error.hpp"

namespace mink {

/// A scene file that cannot be used. The message starts with the JSON path of the offending
/// value (e.g. "bodies[3].shapes[0].points[2]") and says what is wrong. An
/// InvalidArgumentError, so the `mink` command exits with code 2 (bad input).
class SceneFileError : public InvalidArgumentError {
 public:
  /// @brief "json_path: problem".
  SceneFileError(const std::string& json_path, const std::string& problem)
      : InvalidArgumentError(json_path + ": " + problem), json_path_(json_path) {}
  /// @brief Where the problem is, e.g. "bodies[3].shapes[0].points[2]".
  const std::string& json_path() const noexcept { return json_path_; }

 private:
  std::string json_path_;
};

/// @brief Reads the scene format of docs/scene-format.md. Everything a run needs is checked
/// before it returns (each field's type and range, every shape, the world settings), so a bad
/// file never starts a run.
/// @param source names the text in the message of a file that is not JSON at all
/// @throws SceneFileError for the first problem found
SceneDef parse_scene_json(std::string_view text, const std::string& source = "scene");
/// @brief parse_scene_json on a file's contents; messages end with " (in PATH)".
/// @throws InvalidArgumentError for an unreadable file, SceneFileError for a bad one
SceneDef load_scene_file(const std::filesystem::path& path);

/// @brief Every field of every object, each shape in its own kind's form, doubles in shortest
/// round-trip form: parse_scene_json(scene_to_json(s)) gives back exactly `s` (but for the
/// bounds of a joint limit that is off, which are not written). Joints are written body-local.
std::string scene_to_json(const SceneDef& scene);
/// @brief Writes scene_to_json(scene), creating the parent directories, through an OutputFile:
/// a file already at `path` is replaced only by the complete new one.
/// @throws FileWriteError (the environment failed) when the directory or file cannot be written
void save_scene_file(const std::filesystem::path& path, const SceneDef& scene);

/// @brief Changes one world setting, as `mink run --world KEY=VALUE` does: `key` as in the
/// scene file's `world` object, `value` the JSON it would hold there (`4`, `false`,
/// `[0, -9.8]`), checked exactly as the scene reader checks it. `world` is left as it was when
/// the key or value is refused.
/// @throws SceneFileError with the path "world.KEY" (an unknown key: "world.KEY: unknown key")
void set_world_setting(WorldDef& world, std::string_view key, std::string_view value);

/// @brief A built-in's name (builtin_scene_names), or else a path to a scene file.
/// @throws InvalidArgumentError naming the built-ins when it is neither
SceneDef resolve_scene(const std::string& name_or_path);

}  // namespace mink
