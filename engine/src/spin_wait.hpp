#pragma once

#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace mink::detail {

// Busy waiting that stays polite: a CPU pause per round, and after a few dozen rounds the
// thread yields, so a waiter never starves the thread it waits for when there are more
// threads than cores.
class SpinWait {
 public:
  void pause() {
    if (++rounds_ < 64) {
#if defined(__x86_64__) || defined(__i386__)
      _mm_pause();
#endif
    } else {
      std::this_thread::yield();
    }
  }

 private:
  int rounds_ = 0;
};

}  // namespace mink::detail
