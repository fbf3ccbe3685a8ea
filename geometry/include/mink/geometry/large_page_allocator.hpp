#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

// Under AddressSanitizer every array takes the standard allocator, whose memory it guards.
#if defined(__SANITIZE_ADDRESS__)
#define MINK_LARGE_PAGES 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MINK_LARGE_PAGES 0
#endif
#endif
#if !defined(MINK_LARGE_PAGES) && defined(__linux__) && defined(MADV_HUGEPAGE)
#define MINK_LARGE_PAGES 1
#elif !defined(MINK_LARGE_PAGES)
#define MINK_LARGE_PAGES 0
#endif

namespace mink {

/// @brief An allocator for the engine's large arrays (bodies, shapes, joints, contacts, solver
/// records) that asks the kernel for 2 MiB pages.
///
/// Why: the step reads these arrays scattered (a constraint's contact, a contact's bodies), one
/// record per few kilobytes, so with 4 KiB pages nearly every read also misses the address
/// translation cache; with 2 MiB pages a 30 MB contact array needs 15 entries instead of 7,500.
/// Arrays of 2 MiB and more are mapped on their own, aligned to 2 MiB and advised
/// (MADV_HUGEPAGE) before their first use, which is when the kernel picks the page size. The
/// kernel may still give small pages (transparent huge pages off, or no free huge page): only
/// the speed differs. Smaller arrays, systems without madvise and AddressSanitizer builds take
/// the standard allocator.
template <typename T>
class LargePageAllocator {
 public:
  using value_type = T;

  LargePageAllocator() noexcept = default;
  template <typename U>
  LargePageAllocator(const LargePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
#if MINK_LARGE_PAGES
    if (n > max_size()) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes >= kHugePage) {
      const std::size_t size = mapped_size(bytes);
      // One page more than asked, so an aligned start lies within; the ends beyond it go back.
      void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (raw == MAP_FAILED) throw std::bad_alloc();
      char* const begin = static_cast<char*>(raw);
      const std::size_t head =
          (kHugePage - reinterpret_cast<std::uintptr_t>(begin) % kHugePage) % kHugePage;
      char* const aligned = begin + head;
      if (head > 0) munmap(begin, head);
      munmap(aligned + size, kHugePage - head);
      madvise(aligned, size, MADV_HUGEPAGE);
      return reinterpret_cast<T*>(aligned);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) noexcept {
#if MINK_LARGE_PAGES
    const std::size_t bytes = n * sizeof(T);
    if (bytes >= kHugePage) {
      munmap(p, mapped_size(bytes));
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  static constexpr std::size_t max_size() noexcept {
    return (std::size_t(-1) / 2 - kHugePage) / sizeof(T);
  }

  friend bool operator==(const LargePageAllocator&, const LargePageAllocator&) noexcept {
    return true;
  }

 private:
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static constexpr std::size_t mapped_size(std::size_t bytes) noexcept {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
  }
};

template <typename T>
using LargeVector = std::vector<T, LargePageAllocator<T>>;

}  // namespace mink
