#include "stage_runner.hpp"

#include "spin_wait.hpp"

namespace mink::detail {

void StageRunner::claim(std::uint32_t stage, std::uint32_t worker) {
  take_dealt(&runs_[stage * workers_], workers_, worker, [&](std::uint32_t block) {
    run_(context_, stage, block);
    done_[stage].blocks.fetch_add(1, std::memory_order_release);
  });
}

void StageRunner::follow(std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* self) {
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
      r.claim(open - 1, worker);
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
  workers_ = tasks.workers();
  if (run_capacity_ < std::size_t{stages} * workers_) {
    run_capacity_ = std::size_t{stages} * workers_;
    runs_ = std::make_unique<DealtRun[]>(run_capacity_);
  }
  if (done_capacity_ < stages) {
    done_capacity_ = stages;
    done_ = std::make_unique<Done[]>(stages);
  }
  counts_ = block_counts;
  for (std::uint32_t s = 0; s < stages; ++s) {
    deal(&runs_[s * workers_], workers_, block_counts[s]);
    done_[s].blocks.store(0, std::memory_order_relaxed);
  }
  run_ = run;
  context_ = context;
  open_.store(0, std::memory_order_relaxed);
  leader_ = std::this_thread::get_id();
  void* followers = tasks.enqueue(&follow, tasks.workers() - 1, 1, this);
  for (std::uint32_t s = 0; s < stages; ++s) {
    open_.store(s + 1, std::memory_order_release);
    claim(s, 0);
    SpinWait wait;
    while (done_[s].blocks.load(std::memory_order_acquire) < block_counts[s]) wait.pause();
  }
  open_.store(stages + 1, std::memory_order_release);
  tasks.finish(followers);
}

}  // namespace mink::detail
