#pragma once

#include <cstddef>
#include <functional>

#include "mink/engine/debug_draw.hpp"

namespace mink::bench {

// What the render benchmark draws each frame: a callback that issues the draw calls, the
// world box the camera fits, and how many bodies that is.
struct BenchScene {
  std::function<void(DebugDraw&)> draw;
  Vec2 lower;
  Vec2 upper;
  std::size_t bodies = 0;  // dynamic bodies
};

// The engine's large_pyramid scene (5050 boxes in 100 rows on a ground), stepped `steps`
// times so its contacts exist, drawn by World::draw with the drawer's layers.
BenchScene large_pyramid(int steps = 10);

// The scene the benchmark measures, built once.
const BenchScene& bench_scene();

}  // namespace mink::bench
