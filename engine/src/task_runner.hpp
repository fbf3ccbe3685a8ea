#pragma once

#include <cstdint>
#include <memory>

#include "mink/engine/task_system.hpp"
#include "worker_pool.hpp"

namespace mink::detail {

// What the step sees of threads: the embedder's task system when it gave one, otherwise the
// world's own pool (made only for more than one worker).
class TaskRunner {
 public:
  void configure(int worker_count, const TaskSystem& system);
  std::uint32_t workers() const { return workers_; }

  // Starts `function` over [0, item_count); null when it already ran to the end.
  void* enqueue(TaskFunction* function, std::uint32_t item_count, std::uint32_t min_range,
                void* context);
  void finish(void* task);

  // Calls body(begin, end, worker) over ranges covering [0, count), at least min_range items
  // each, and returns when all have run. Each range must write only what its items own.
  template <class Body>
  void parallel_for(std::uint32_t count, std::uint32_t min_range, Body&& body) {
    if (count == 0) return;
    if (workers_ == 1 || count <= min_range) {
      body(0u, count, 0u);
      return;
    }
    TaskFunction* call = [](std::uint32_t begin, std::uint32_t end, std::uint32_t worker,
                            void* context) { (*static_cast<Body*>(context))(begin, end, worker); };
    if (void* task = enqueue(call, count, min_range, &body)) finish(task);
  }

 private:
  std::uint32_t workers_ = 1;
  TaskSystem system_;
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace mink::detail
