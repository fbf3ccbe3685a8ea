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
  std::size_t bodies = 0;
};

// 5050 unit boxes stacked in a pyramid of 100 rows, each tilted a little, drawn as filled
// and outlined polygons the way World::draw draws shapes.
BenchScene synthetic_pyramid(int rows = 100);

// The scene the benchmark measures. When the engine lands this becomes its large_pyramid
// scene stepped a few times, drawn by World::draw.
inline BenchScene bench_scene() {
  return synthetic_pyramid();
}

}  // namespace mink::bench
