// Scene files and built-in scenes: worlds read from JSON (bodies in the file's order) and
// written back.
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "bindings.hpp"
#include "mink/engine/scene_file.hpp"

namespace mink::python {

namespace {

WorldPtr scene_world(SceneDef scene, const py::kwargs& settings, std::string schedule_scene = {}) {
  scene.world = world_def(scene.world, settings);
  return std::make_shared<WorldHandle>(scene, std::move(schedule_scene));
}

constexpr const char* kSettingsDoc =
    " Keyword arguments change world settings as `mink run --world KEY=VALUE` does (the "
    "scene file's world keys, and workers).";

std::string settings_doc(const char* text) {
  return std::string(text) + kSettingsDoc;
}

}  // namespace

void bind_scenes(py::module_& m, WorldClass& world) {
  static const std::string load_doc = settings_doc(
      "The World of a scene file (docs/scene-format.md): its bodies in the file's order "
      "(World.bodies[i] is bodies[i] of the file), then its joints. Raises SceneFileError "
      "naming the offending value's JSON path.");
  static const std::string parse_doc = settings_doc("The World of a scene given as JSON text.");
  static const std::string builtin_doc = settings_doc(
      "The World of a built-in scene (builtin_scene_names()); a scene that changes as it runs "
      "(rain, junkyard) keeps its schedule, which acts before each World.step.");

  m.def(
       "load_scene",
       [](const std::filesystem::path& path, const py::kwargs& settings) {
         return scene_world(load_scene_file(path), settings);
       },
       py::arg("path"), load_doc.c_str())
      .def(
          "parse_scene",
          [](const std::string& text, const py::kwargs& settings) {
            return scene_world(parse_scene_json(text), settings);
          },
          py::arg("text"), parse_doc.c_str())
      .def(
          "builtin_scene",
          [](const std::string& name, const py::kwargs& settings) {
            SceneDef scene = builtin_scene(name);
            const bool scheduled = static_cast<bool>(scene.schedule);
            return scene_world(std::move(scene), settings, scheduled ? name : std::string());
          },
          py::arg("name"), builtin_doc.c_str())
      .def(
          "builtin_scene_names",
          [] {
            std::vector<std::string> names;
            for (const std::string_view name : builtin_scene_names()) names.emplace_back(name);
            return names;
          },
          "The built-in scenes' names.")
      .def(
          "builtin_scene_json",
          [](const std::string& name) { return scene_to_json(builtin_scene(name)); },
          py::arg("name"),
          "A built-in scene as scene-file JSON (what `mink export-scene NAME` writes).");

  world
      .def(
          "to_json", [](WorldHandle& w) { return scene_to_json(capture_scene(w.world())); },
          "The world as it stands, as scene-file JSON: every live body (slot order) with its "
          "pose, velocities and shapes, and every joint (contact impulses are not kept).")
      .def(
          "save",
          [](WorldHandle& w, const std::filesystem::path& path) {
            save_scene_file(path, capture_scene(w.world()));
          },
          py::arg("path"), "Writes World.to_json() to a scene file.");
}

}  // namespace mink::python
