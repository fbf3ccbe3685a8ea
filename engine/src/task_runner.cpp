#include "task_runner.hpp"

namespace mink::detail {

void TaskRunner::configure(int worker_count, const TaskSystem& system) {
  workers_ = static_cast<std::uint32_t>(worker_count);
  system_ = system;
  pool_.reset();
  if (system_.enqueue == nullptr && workers_ > 1)
    pool_ = std::make_unique<WorkerPool>(worker_count);
}

void* TaskRunner::enqueue(TaskFunction* function, std::uint32_t item_count, std::uint32_t min_range,
                          void* context) {
  if (pool_) return pool_->enqueue(function, item_count, min_range, context);
  if (system_.enqueue != nullptr) {
    return system_.enqueue(function, item_count, min_range, context, system_.user_context);
  }
  if (item_count > 0) function(0, item_count, 0, context);
  return nullptr;
}

void TaskRunner::finish(void* task) {
  if (task == nullptr) return;
  if (pool_) {
    pool_->finish(task);
  } else {
    system_.finish(task, system_.user_context);
  }
}

}  // namespace mink::detail
