#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>

#include "dealt_runs.hpp"
#include "task_runner.hpp"

namespace mink::detail {

// Runs a list of stages in order, each split into blocks that may run at once on different
// workers (a colour of the solver, a range of bodies); a stage starts only when every block of
// the one before it has run. The stepping thread leads: it opens each stage, runs blocks and
// waits for the rest; the other workers spin on the open stage and take blocks as they come.
// One task per step instead of one per stage keeps the hand-over between stages to an atomic
// store and load. If the task system runs a follower late or never, the leader runs every
// block itself, so nothing waits on a thread that is not there.
class StageRunner {
 public:
  using BlockFunction = void(void* context, std::uint32_t stage, std::uint32_t block);

  StageRunner() = default;
  // Nothing lives past run(), so a moved runner starts afresh.
  StageRunner(StageRunner&&) noexcept {}
  StageRunner& operator=(StageRunner&&) noexcept { return *this; }

  // block_counts[s] blocks for stage s; run(context, s, b) for each.
  void run(TaskRunner& tasks, std::span<const std::uint32_t> block_counts, BlockFunction* run,
           void* context);

 private:
  // Each stage's blocks are dealt to the workers (dealt_runs.hpp).
  struct alignas(64) Done {
    std::atomic<std::uint32_t> blocks{0};
  };
  static void follow(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* self);
  void claim(std::uint32_t stage, std::uint32_t worker);

  std::unique_ptr<DealtRun[]> runs_;  // stage * workers_ + run
  std::unique_ptr<Done[]> done_;
  std::size_t run_capacity_ = 0, done_capacity_ = 0;
  std::uint32_t workers_ = 1;
  std::span<const std::uint32_t> counts_;
  BlockFunction* run_ = nullptr;
  void* context_ = nullptr;
  // 1 + the open stage; 0 before the first, counts_.size() + 1 once all have run.
  alignas(64) std::atomic<std::uint32_t> open_{0};
  // A task system may run a follower inside enqueue, on the leader's own thread: that follower
  // must return at once rather than wait for stages its own thread has yet to open.
  std::thread::id leader_;
};

}  // namespace mink::detail
