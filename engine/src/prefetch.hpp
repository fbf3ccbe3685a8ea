#pragma once

#include <cstddef>

namespace mink::detail {

// Asks for the cache line at `p`. An asm statement on x86 rather than __builtin_prefetch: GCC
// 12's side-effect analysis (IPA modref) takes a function or lambda made only of prefetch
// builtins for one without effects and drops its calls.
[[gnu::always_inline]] inline void prefetch_line(const void* p) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

// Asks for the cache lines of the `size` bytes at `p` (which need not start a line).
[[gnu::always_inline]] inline void prefetch_bytes(const void* p, std::size_t size) {
  const char* bytes = static_cast<const char*>(p);
  for (std::size_t offset = 0; offset < size; offset += 64) prefetch_line(bytes + offset);
  prefetch_line(bytes + size - 1);
}

}  // namespace mink::detail
