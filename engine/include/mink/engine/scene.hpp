#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "mink/engine/body_def.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/engine/world.hpp"
#include "mink/engine/world_def.hpp"

namespace mink {

struct SceneBody {
  BodyDef body;
  std::vector<ShapeDef> shapes;
};

// A scene is plain data: world settings plus body definitions with their shapes, so it can be
// written to and read from files. Bodies are created in order.
struct SceneDef {
  WorldDef world;
  std::vector<SceneBody> bodies;
};

World build_world(const SceneDef& scene);

// The current state of a world as a scene: every live body (slot order) with its pose,
// velocities and settings, each shape as its hull's vertices. build_world(capture_scene(w))
// recreates the bodies where they are now (contact impulses are not kept).
SceneDef capture_scene(const World& world);

// Built-in scenes: large_pyramid, pyramid, many_pyramids, rain, tumbler, paper.
std::span<const std::string_view> builtin_scene_names() noexcept;
// Throws InvalidArgumentError naming an unknown scene.
SceneDef builtin_scene(std::string_view name);

// The building blocks of the built-ins, for tests and benchmarks that need other sizes.
// A pyramid of unit boxes with `base_count` boxes in its bottom row, its bottom-centre at
// `base_center`.
void add_pyramid(SceneDef& scene, int base_count, const Vec2& base_center, Real box_size = 1);
SceneDef pyramid_scene(int base_count);
SceneDef many_pyramids_scene(int rows, int columns, int base_count);
SceneDef rain_scene(int body_count, std::uint64_t seed);

}  // namespace mink
