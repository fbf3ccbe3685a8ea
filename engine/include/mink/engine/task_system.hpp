#pragma once

#include <cstdint>

namespace mink {

/// @file
/// @brief How a world spreads a step over threads: its built-in worker pool, or the
/// embedder's own task system plugged in through two callbacks (as Box2D v3 and Jolt allow).

/// @brief One task: process items [begin, end) as worker `worker` (0 .. worker_count - 1; no two
/// ranges running at the same time share a worker number). `context` is what enqueue was given.
using TaskFunction = void(std::uint32_t begin, std::uint32_t end, std::uint32_t worker,
                          void* context);

/// @brief An embedder's task system. Leave both callbacks null to use the world's built-in
/// worker pool (WorldDef::worker_count threads, the stepping thread among them).
///
/// The world calls `enqueue` to have `function` run over items [0, item_count), split into
/// ranges of at least `min_range` items as the system likes, with worker numbers below
/// WorldDef::worker_count, and later `finish` with the returned handle, which must return only
/// once every range has run. `enqueue` may run everything itself and return null; `finish` is
/// then not called. Results never depend on how the items are split or on which worker runs
/// them: a world steps to bitwise the same state at any worker count.
struct TaskSystem {
  void* (*enqueue)(TaskFunction* function, std::uint32_t item_count, std::uint32_t min_range,
                   void* task_context, void* user_context) = nullptr;
  void (*finish)(void* task, void* user_context) = nullptr;
  void* user_context = nullptr;  ///< passed to both callbacks
};

}  // namespace mink
