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

// For a loop over records scattered in memory, each holding a list it walks (a body's
// contacts, its joints): asks for the line holding the list of the record `ahead` steps on,
// and for the list itself of the record half as far, once that line is in. `list_at(i)` is
// the list of step i.
template <typename ListAt>
[[gnu::always_inline]] inline void prefetch_list_ahead(std::size_t k, std::size_t end,
                                                       std::size_t ahead, ListAt&& list_at) {
  if (k + ahead < end) prefetch_line(&list_at(k + ahead));
  if (k + ahead / 2 < end) {
    const auto& list = list_at(k + ahead / 2);
    if (!list.empty()) prefetch_line(list.data());
  }
}

}  // namespace mink::detail
