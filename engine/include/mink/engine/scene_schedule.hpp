#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "mink/engine/ids.hpp"
#include "mink/engine/world.hpp"

namespace mink {

struct SceneDef;

/// @brief The world's ids for what was made of a scene: bodies[i] is the scene's body i,
/// joints[i] its joint i.
struct SceneIds {
  std::vector<BodyId> bodies;
  std::vector<JointId> joints;
};

/// @name Scene schedules
/// Most scenes are their initial state. Some change as they run: Box2D v3's `rain` drops 25
/// ragdolls every eighth step and, once 1000 are down, destroys the oldest 25 to drop them
/// anew; its `junkyard` steers a kinematic pusher along a path. A SceneDef carries that as a
/// schedule.
///
/// A schedule starts a run: given a world just built from the scene and the ids of the scene's
/// bodies and joints, it returns that run's actions, which keep whatever state they need (the
/// bodies they made, a counter) to themselves. The actions are called before each step with
/// the number of steps taken so far (0 before the first), so a run of N steps calls them with
/// 0..N-1. Actions may create and destroy bodies, shapes and joints and set velocities or
/// targets; they must depend only on the world and the step number, so that a run is as
/// deterministic as a static scene. Each run starts its own actions: two runs of one scene do
/// not share state.
///
/// A schedule is code, not data: scene files do not carry it, so a scene written out (`mink
/// export-scene`, capture_scene, `mink run --save`) is the state at that moment only, and
/// resumes without the schedule.
/// @{

/// One run's actions: `act` is called before each step with the steps taken so far. Actions
/// that keep state of their own (the bodies they made, a counter) also give `save` and `load`,
/// so that a SceneRun snapshot resumes them exactly.
struct SceneActions {
  std::function<void(World& world, std::uint64_t step)> act;
  /// The actions' own state as bytes (none: nothing beyond the scene's ids and the step).
  std::function<std::vector<std::uint8_t>()> save;
  /// Reads what save wrote, ids taking `world`'s number; throws SnapshotError for bytes it
  /// cannot read, its state then unchanged.
  std::function<void(std::span<const std::uint8_t> bytes, const World& world)> load;

  void operator()(World& world, std::uint64_t step) const { act(world, step); }
  explicit operator bool() const noexcept { return static_cast<bool>(act); }
};

/// @brief Starts a run of a scene: the actions for a world just built from it.
using SceneSchedule = std::function<SceneActions(World& world, const SceneIds& ids)>;

/// @}

/// A world built from a scene, running the scene's schedule: step() runs the schedule's
/// actions for this step, then one world step. For a scene without a schedule it is
/// build_world and World::step. What `mink run` and the sandbox step.
class SceneRun {
 public:
  /// @brief Builds the world (build_world) and starts the scene's schedule, if it has one.
  /// @throws what build_world throws.
  explicit SceneRun(const SceneDef& scene);

  /// @brief The scene's actions for the coming step (none without a schedule), then one step.
  void step();

  World& world() noexcept { return world_; }
  const World& world() const noexcept { return world_; }
  /// @brief The ids of the scene's own bodies and joints (not of those its schedule makes).
  const SceneIds& ids() const noexcept { return ids_; }

  /// @brief The world's snapshot (World::snapshot) and the schedule's own state.
  std::vector<std::uint8_t> snapshot() const;
  /// Puts the world and the schedule back to `snapshot`, taken from a run of the same scene:
  /// the run then continues as that one would have.
  /// @throws SnapshotError as World::restore, or for schedule state that does not read; the
  /// run is then left as it was.
  void restore(std::span<const std::uint8_t> snapshot);

 private:
  World world_;
  SceneIds ids_;
  SceneActions actions_;
};

}  // namespace mink
