#include "worker_pool.hpp"

#include <algorithm>

#include "dealt_runs.hpp"
#include "spin_wait.hpp"

namespace mink::detail {

struct WorkerPool::Task {
  explicit Task(std::uint32_t workers) : runs(std::make_unique<DealtRun[]>(workers)) {}
  TaskFunction* function = nullptr;
  void* context = nullptr;
  std::uint32_t item_count = 0;
  std::uint32_t range_size = 1;
  std::uint32_t range_count = 0;
  std::unique_ptr<DealtRun[]> runs;  // the ranges, dealt to the workers (dealt_runs.hpp)
  std::atomic<std::uint32_t> done_ranges{0};
  // Threads that took the task from the queue and may still look at it: it is reused only
  // once none does.
  std::atomic<std::uint32_t> visitors{0};
};

WorkerPool::WorkerPool(int worker_count) {
  threads_.reserve(static_cast<std::size_t>(std::max(0, worker_count - 1)));
  for (int i = 1; i < worker_count; ++i) {
    threads_.emplace_back([this, i] { work(static_cast<std::uint32_t>(i)); });
  }
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_.store(true);
    generation_.fetch_add(1);
  }
  wake_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::run_ranges(Task& task, std::uint32_t worker) const {
  take_dealt(task.runs.get(), workers(), worker, [&](std::uint32_t range) {
    const std::uint32_t begin = range * task.range_size;
    const std::uint32_t end = std::min(task.item_count, begin + task.range_size);
    task.function(begin, end, worker, task.context);
    task.done_ranges.fetch_add(1, std::memory_order_release);
  });
}

void* WorkerPool::enqueue(TaskFunction* function, std::uint32_t item_count, std::uint32_t min_range,
                          void* context) {
  if (item_count == 0) return nullptr;
  if (workers() == 1) {
    function(0, item_count, 0, context);
    return nullptr;
  }
  std::unique_ptr<Task> owned;
  {
    std::lock_guard lock(mutex_);
    if (free_tasks_.empty()) {
      owned = std::make_unique<Task>(workers());
    } else {
      owned = std::move(free_tasks_.back());
      free_tasks_.pop_back();
    }
  }
  Task& task = *owned;
  // About four ranges per worker: enough to even out uneven items, few enough to stay cheap.
  const std::uint32_t target = 4 * workers();
  task.function = function;
  task.context = context;
  task.item_count = item_count;
  task.range_size = std::max(std::max(min_range, 1u), (item_count + target - 1) / target);
  task.range_count = (item_count + task.range_size - 1) / task.range_size;
  deal(task.runs.get(), workers(), task.range_count);
  task.done_ranges.store(0, std::memory_order_relaxed);
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(owned.release());
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  return &task;
}

void WorkerPool::finish(void* handle) {
  Task* task = static_cast<Task*>(handle);
  run_ranges(*task, 0);
  SpinWait wait;
  while (task->done_ranges.load(std::memory_order_acquire) < task->range_count) wait.pause();
  {
    std::lock_guard lock(mutex_);
    queue_.erase(std::remove(queue_.begin(), queue_.end(), task), queue_.end());
  }
  while (task->visitors.load(std::memory_order_acquire) != 0) wait.pause();
  std::lock_guard lock(mutex_);
  free_tasks_.emplace_back(task);
}

void WorkerPool::work(std::uint32_t worker) {
  std::uint64_t seen = 0;
  for (;;) {
    Task* task = nullptr;
    {
      std::unique_lock lock(mutex_);
      for (;;) {
        if (stopping_.load()) return;
        for (Task* t : queue_) {
          if (any_left(t->runs.get(), workers())) {
            task = t;
            task->visitors.fetch_add(1, std::memory_order_relaxed);
            break;
          }
        }
        if (task != nullptr) break;
        seen = generation_.load(std::memory_order_relaxed);
        lock.unlock();
        // Spin a little before sleeping: the next task of a step is usually microseconds away.
        SpinWait wait;
        bool moved = false;
        for (int i = 0; i < 2000 && !moved; ++i) {
          wait.pause();
          moved = generation_.load(std::memory_order_acquire) != seen;
        }
        lock.lock();
        if (!moved) {
          wake_.wait(lock, [&] { return generation_.load() != seen || stopping_.load(); });
        }
      }
    }
    run_ranges(*task, worker);
    task->visitors.fetch_sub(1, std::memory_order_release);
  }
}

}  // namespace mink::detail
