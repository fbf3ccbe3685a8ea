// The scene reader on any bytes: parse_scene_json returns a scene or throws SceneFileError,
// nothing else. A scene it accepts is written back (scene_to_json), read again and written
// again: the two texts must be equal. Small accepted scenes are then built and stepped, where
// nothing may be thrown.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail = {}) {
  std::fprintf(stderr, "fuzz_scene_reader: %s\n%s\n", what, detail.c_str());
  std::abort();
}

// Scenes larger than this are read and written but not run: stepping them would only slow
// the search down.
constexpr std::size_t max_run_bodies = 48;
constexpr std::size_t max_run_points = 512;
constexpr int max_run_substeps = 16;

bool small_enough_to_run(const mink::SceneDef& scene) {
  if (scene.bodies.size() > max_run_bodies || scene.world.substeps > max_run_substeps) {
    return false;
  }
  std::size_t points = 0;
  for (const mink::SceneBody& body : scene.bodies) {
    for (const mink::ShapeDef& shape : body.shapes) points += shape.points.size();
  }
  return points <= max_run_points;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  mink::SceneDef scene;
  try {
    scene = mink::parse_scene_json(text);
  } catch (const mink::SceneFileError&) {
    return 0;
  }

  const std::string written = mink::scene_to_json(scene);
  mink::SceneDef reread;
  try {
    reread = mink::parse_scene_json(written);
  } catch (const mink::Error& error) {
    fail("the reader refuses what the writer wrote", std::string(error.what()) + "\n" + written);
  }
  const std::string rewritten = mink::scene_to_json(reread);
  if (rewritten != written) fail("the scene changed on a round trip", written + "\n" + rewritten);

  if (!small_enough_to_run(scene)) return 0;
  // The reader accepts up to 256 workers; two are enough to run the parallel paths.
  if (scene.world.worker_count > 2) scene.world.worker_count = 2;
  // The reader checks everything a run needs, so a scene it accepts builds and steps without
  // any error.
  try {
    mink::World world = mink::build_world(scene);
    for (int step = 0; step < 3; ++step) world.step();
  } catch (const mink::Error& error) {
    fail("an accepted scene fails to run", error.what());
  }
  return 0;
}
