#include "mink/engine/scene_schedule.hpp"

#include <cstring>

#include "mink/engine/scene.hpp"

namespace mink {

SceneRun::SceneRun(const SceneDef& scene) : world_(scene.world), ids_(add_scene(world_, scene)) {
  if (scene.schedule) actions_ = scene.schedule(world_, ids_);
}

void SceneRun::step() {
  if (actions_) actions_(world_, world_.step_count());
  world_.step();
}

// The world's snapshot with its length in front, then the schedule's bytes.
std::vector<std::uint8_t> SceneRun::snapshot() const {
  std::vector<std::uint8_t> world = world_.snapshot();
  const std::vector<std::uint8_t> schedule =
      actions_.save ? actions_.save() : std::vector<std::uint8_t>{};
  ByteWriter out;
  out.value(static_cast<std::uint64_t>(world.size()));
  out.raw(world.data(), world.size());
  out.raw(schedule.data(), schedule.size());
  return std::move(out.bytes());
}

void SceneRun::restore(std::span<const std::uint8_t> snapshot) {
  ByteReader in(snapshot);
  const auto size = in.get<std::uint64_t>();
  if (size > in.remaining()) {
    throw SnapshotError("run snapshot truncated at byte " + std::to_string(snapshot.size()) +
                        ": its world needs " + std::to_string(size + 8) + " bytes");
  }
  const std::span<const std::uint8_t> world = snapshot.subspan(8, size);
  const std::span<const std::uint8_t> schedule = snapshot.subspan(8 + size);
  if (!actions_.load && !schedule.empty()) {
    throw SnapshotError("run snapshot carries schedule state this scene's schedule does not keep");
  }
  if (!actions_.load) {
    world_.restore(world);
    return;
  }
  // The schedule's state is read after the world's: should it not read, the world goes back.
  const std::vector<std::uint8_t> before = world_.snapshot();
  world_.restore(world);
  try {
    actions_.load(schedule, world_);
  } catch (...) {
    world_.restore(before);
    throw;
  }
}

}  // namespace mink
