#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "mink/engine/task_system.hpp"

namespace mink::detail {

// The built-in task system: worker_count - 1 threads, numbered 1 and up, plus the thread that
// calls finish(), which helps as worker 0. Idle threads spin briefly for the next task (a step
// enqueues several in quick succession) and then sleep.
class WorkerPool {
 public:
  explicit WorkerPool(int worker_count);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void* enqueue(TaskFunction* function, std::uint32_t item_count, std::uint32_t min_range,
                void* context);
  void finish(void* task);

 private:
  struct Task;
  std::uint32_t workers() const { return static_cast<std::uint32_t>(threads_.size() + 1); }
  void work(std::uint32_t worker);
  // Runs ranges of `task` until none is left unclaimed.
  void run_ranges(Task& task, std::uint32_t worker) const;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Task*> queue_;                  // tasks with ranges left to claim
  std::atomic<std::uint64_t> generation_{0};  // bumped by every enqueue, for spinning threads
  std::atomic<bool> stopping_{false};
  std::vector<std::unique_ptr<Task>> free_tasks_;  // reused, so a step allocates nothing
  std::vector<std::thread> threads_;
};

}  // namespace mink::detail
