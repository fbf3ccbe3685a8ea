#include "stage_runner.hpp"

#include "spin_wait.hpp"

namespace mink::detail {

void StageRunner::claim(std::uint32_t stage) {
  Counters& c = counters_[stage];
  const std::uint32_t count = counts_[stage];
  for (;;) {
    const std::uint32_t block = c.claimed.fetch_add(1, std::memory_order_relaxed);
    if (block >= count) return;
    run_(context_, stage, block);
    c.done.fetch_add(1, std::memory_order_release);
  }
}

void StageRunner::follow(std::uint32_t begin, std::uint32_t end, std::uint32_t, void* self) {
  StageRunner& r = *static_cast<StageRunner*>(self);
  if (std::this_thread::get_id() == r.leader_) return;
  const auto last = static_cast<std::uint32_t>(r.counts_.size() + 1);
  // Several followers in one range (a task system that merged them) run one after the other:
  // the second finds every stage done.
  for (std::uint32_t i = begin; i < end; ++i) {
    std::uint32_t seen = 0;
    SpinWait wait;
    for (;;) {
      const std::uint32_t open = r.open_.load(std::memory_order_acquire);
      if (open == last) break;
      if (open == seen) {
        wait.pause();
        continue;
      }
      seen = open;
      r.claim(open - 1);
      wait = SpinWait();
    }
  }
}

void StageRunner::run(TaskRunner& tasks, std::span<const std::uint32_t> block_counts,
                      BlockFunction* run, void* context) {
  const auto stages = static_cast<std::uint32_t>(block_counts.size());
  if (tasks.workers() == 1) {
    for (std::uint32_t s = 0; s < stages; ++s) {
      for (std::uint32_t b = 0; b < block_counts[s]; ++b) run(context, s, b);
    }
    return;
  }
  if (capacity_ < stages) {
    counters_ = std::make_unique<Counters[]>(stages);
    capacity_ = stages;
  }
  for (std::uint32_t s = 0; s < stages; ++s) {
    counters_[s].claimed.store(0, std::memory_order_relaxed);
    counters_[s].done.store(0, std::memory_order_relaxed);
  }
  counts_ = block_counts;
  run_ = run;
  context_ = context;
  open_.store(0, std::memory_order_relaxed);
  leader_ = std::this_thread::get_id();
  void* followers = tasks.enqueue(&follow, tasks.workers() - 1, 1, this);
  for (std::uint32_t s = 0; s < stages; ++s) {
    open_.store(s + 1, std::memory_order_release);
    claim(s);
    SpinWait wait;
    while (counters_[s].done.load(std::memory_order_acquire) < block_counts[s]) wait.pause();
  }
  open_.store(stages + 1, std::memory_order_release);
  tasks.finish(followers);
}

}  // namespace mink::detail
