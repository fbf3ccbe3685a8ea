#pragma once

// Work dealt into one run per worker, in order: a worker takes the items of its own run first,
// then what is left of the others', each item claimed once through its run's counter. Phases
// over the same items (a colour's blocks from substep to substep, the bodies from the solver's
// set-up to their finish) then give each worker the same part every time, so the records it
// writes stay in its core's cache instead of passing between the cores at every phase. Both
// the solver's stages (StageRunner) and the built-in worker pool's tasks are dealt this way.

#include <atomic>
#include <cstdint>

#include "run_counts.hpp"

namespace mink::detail {

struct alignas(64) DealtRun {
  std::atomic<std::uint32_t> next{0};
  std::uint32_t end = 0;
};

// Deals `items` into `runs` runs. Not concurrent with taking.
inline void deal(DealtRun* run, std::uint32_t runs, std::uint32_t items) {
  for (std::uint32_t r = 0; r < runs; ++r) {
    run[r].next.store(static_cast<std::uint32_t>(run_begin(items, r, runs)),
                      std::memory_order_relaxed);
    run[r].end = static_cast<std::uint32_t>(run_begin(items, r + 1, runs));
  }
}

// Whether some item is not yet taken.
inline bool any_left(const DealtRun* run, std::uint32_t runs) {
  for (std::uint32_t r = 0; r < runs; ++r) {
    if (run[r].next.load(std::memory_order_relaxed) < run[r].end) return true;
  }
  return false;
}

// Calls `take(item)` for every item this worker claims: those of its own run, then those left
// in the others'.
template <typename Take>
void take_dealt(DealtRun* run, std::uint32_t runs, std::uint32_t worker, Take&& take) {
  for (std::uint32_t k = 0; k < runs; ++k) {
    DealtRun& r = run[(worker + k) % runs];
    // A run another worker has drained is skipped without touching its line again.
    if (r.next.load(std::memory_order_relaxed) >= r.end) continue;
    for (;;) {
      const std::uint32_t item = r.next.fetch_add(1, std::memory_order_relaxed);
      if (item >= r.end) break;
      take(item);
    }
  }
}

}  // namespace mink::detail
