#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "mink/engine/body_def.hpp"
#include "mink/engine/joint_def.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/engine/world.hpp"
#include "mink/engine/world_def.hpp"

namespace mink {

/// @brief One body of a scene with its shapes.
struct SceneBody {
  BodyDef body;                  ///< where and how it moves
  std::vector<ShapeDef> shapes;  ///< created in order
};

/// One joint of a scene. `def` is body-local (anchors in each body's frame, as the *_joint_at
/// helpers make them), so it holds whatever the bodies' poses; its BodyId and JointId members
/// are not used: a scene names bodies and joints by index.
struct SceneJoint {
  JointDef def;            ///< the kind and its settings
  std::size_t body_a = 0;  ///< index into SceneDef::bodies (unused by gears)
  std::size_t body_b = 0;  ///< index into SceneDef::bodies (unused by gears)
  std::size_t joint1 = 0;  ///< gears: index into SceneDef::joints, of an earlier joint
  std::size_t joint2 = 0;  ///< gears: index into SceneDef::joints, of an earlier joint
};

/// A scene is plain data: world settings plus body definitions with their shapes, and joints
/// between the bodies, so it can be written to and read from files. Bodies are created in
/// order, then joints in order. A scene that changes as it runs also has a schedule (code, not
/// written to files; see scene_schedule.hpp), run by SceneRun.
struct SceneDef {
  WorldDef world;                  ///< world settings
  std::vector<SceneBody> bodies;   ///< created in order
  std::vector<SceneJoint> joints;  ///< created in order, after every body
  SceneSchedule schedule;          ///< empty for a scene that is its initial state
};

/// @brief A world with the scene's settings, bodies, shapes and joints; bodies defined asleep
/// stay asleep. The scene's initial state only: SceneRun also runs its schedule.
/// @throws InvalidArgumentError (or a hull error) for a bad definition, as World,
/// World::create_shape and World::create_joint would, and for a joint naming a body or joint
/// the scene does not have ("joints[3].body_b: no body 12").
World build_world(const SceneDef& scene);

/// @brief Creates the scene's bodies, shapes and joints in an existing world, as build_world
/// does in a new one (the scene's world settings and schedule are not used), and returns their
/// ids. Schedules add parts this way while a world runs.
/// @throws as build_world; what was created before a bad definition stays.
SceneIds add_scene(World& world, const SceneDef& scene);

/// @brief The current state of a world as a scene: every live body (slot order) with its pose,
/// velocities and settings, each shape in its own kind (a polygon as its hull's vertices, a
/// chain as one chain shape), and every live joint with its current settings (slot order, but
/// gears after the joints they couple). build_world(capture_scene(w)) recreates the bodies
/// where they are now and the same joints (contact and joint impulses are not kept).
SceneDef capture_scene(const World& world);

/// @brief Where build_world creates body `index` of the scene: its defined position and angle.
/// @throws InvalidArgumentError for an index past the scene's bodies.
Pose scene_body_pose(const SceneDef& scene, std::size_t index);

/// @brief Moves the whole scene by `offset`, as if it had been built there: every body's
/// position and the world points of pulley joints (shapes and other joints are body-local).
/// A schedule, being code, is not moved: a scene with one is refused.
/// @throws InvalidArgumentError for a non-finite offset or a scene with a schedule.
void shift_scene(SceneDef& scene, const Vec2& offset);

/// @brief Built-in scenes: ours (pyramid, pyramid_100, pyramid_grid, rain_mixed, tumbler_400,
/// paper, shapes, pendulum, chain, bridge, ragdolls, car, newtons_cradle), then Box2D v3's
/// benchmark suite (see benchmark_suite).
std::span<const std::string_view> builtin_scene_names() noexcept;
/// @brief Whether `name` is one of builtin_scene_names().
bool is_builtin_scene(std::string_view name) noexcept;
/// @brief The built-in scene of that name (see builtin_scene_names).
/// @throws InvalidArgumentError naming an unknown scene.
SceneDef builtin_scene(std::string_view name);

/// @brief A scene of Box2D v3's benchmark suite and how many steps its benchmark app runs it.
struct BenchmarkScene {
  std::string_view name;  ///< the built-in's name, as Box2D v3 names it
  int steps = 0;          ///< steps per run in Box2D v3's benchmark/main.c
};

/// Box2D v3's ten benchmark scenes (its shared/benchmarks.c and shared/human.c), built-ins of
/// the same names: compounds, joint_grid, junkyard, large_pyramid, many_pyramids, rain, smash,
/// spinner, tumbler, washer. Each has Box2D v3's geometry, materials, counts, filters, joints,
/// motors and kinematic movers, and the world settings its benchmark app runs at (1/60 s steps
/// of 4 substeps, 30 Hz contacts, joints at 60 Hz, 3 m/s push-out; sleeping off where the
/// scene turns it off: joint_grid, large_pyramid, many_pyramids). rain (ragdolls dropped and
/// replaced every eighth step) and junkyard (a pusher steered along a path) have schedules.
std::span<const BenchmarkScene> benchmark_suite() noexcept;

// The building blocks of the built-ins, for tests and benchmarks that need other sizes.

/// @brief Appends a pyramid of dynamic square boxes (side `box_size`, unit by default) with
/// `base_count` boxes in its bottom row, its bottom-centre at `base_center`.
void add_pyramid(SceneDef& scene, int base_count, const Vec2& base_center, Real box_size = 1);
/// @brief One pyramid of `base_count` boxes on a static ground.
/// @throws InvalidArgumentError when base_count < 1.
SceneDef pyramid_scene(int base_count);
/// @brief A grid of rows x columns pyramids, each row on its own thin static floor.
/// @throws InvalidArgumentError unless all three counts are positive.
SceneDef many_pyramids_scene(int rows, int columns, int base_count);
/// @brief Which shapes rain_scene drops.
enum class RainShapes : std::uint8_t {
  polygons,  ///< random convex polygons of 3..64 vertices only
  mixed,     ///< polygons, circles and capsules (the `rain_mixed` built-in)
};

/// @brief `body_count` random convex bodies falling into a walled box; the same `seed` and
/// `shapes` give the same scene.
/// @throws InvalidArgumentError when body_count < 0.
SceneDef rain_scene(int body_count, std::uint64_t seed, RainShapes shapes = RainShapes::polygons);

}  // namespace mink
