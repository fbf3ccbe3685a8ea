#include "mink/engine/scene_schedule.hpp"

#include "mink/engine/scene.hpp"

namespace mink {

SceneRun::SceneRun(const SceneDef& scene) : world_(scene.world), ids_(add_scene(world_, scene)) {
  if (scene.schedule) actions_ = scene.schedule(world_, ids_);
}

void SceneRun::step() {
  if (actions_) actions_(world_, world_.step_count());
  world_.step();
}

}  // namespace mink
