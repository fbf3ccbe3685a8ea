#include "mink/geometry/large_page_allocator.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace mink {
namespace {

struct alignas(64) Record {
  std::uint64_t value = 0;
  char rest[56] = {};
};

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Arrays of 2 MiB and more come mapped on their own at a 2 MiB boundary, and hold what is
// written to every element; smaller ones keep their type's alignment.
TEST(LargePageAllocator, LargeArraysStartOnALargePageAndHoldTheirElements) {
  LargeVector<Record> small(100);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % alignof(Record), 0u);
  LargeVector<Record> large(3 * kHugePage / sizeof(Record) + 7);
  if (MINK_LARGE_PAGES) {
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % kHugePage, 0u);
  }
  for (std::size_t i = 0; i < large.size(); ++i) large[i].value = i;
  std::uint64_t sum = 0;
  for (const Record& r : large) sum += r.value;
  EXPECT_EQ(sum, large.size() * (large.size() - 1) / 2);
}

// Growing through the threshold moves the elements from the standard allocator's memory to a
// mapping and on to larger mappings; a copy and a swap keep them.
TEST(LargePageAllocator, GrowthCopiesAndSwapsKeepTheElements) {
  LargeVector<std::uint32_t> grown;
  const std::size_t count = 5 * kHugePage / sizeof(std::uint32_t);
  for (std::size_t i = 0; i < count; ++i) grown.push_back(static_cast<std::uint32_t>(i));
  LargeVector<std::uint32_t> copy = grown;
  LargeVector<std::uint32_t> other(10, 7);
  other.swap(copy);
  ASSERT_EQ(other.size(), count);
  EXPECT_EQ(copy, LargeVector<std::uint32_t>(10, 7));
  for (std::size_t i = 0; i < count; i += 4097) EXPECT_EQ(other[i], i);
  EXPECT_EQ(std::accumulate(other.begin(), other.end(), std::uint64_t{0}),
            std::uint64_t{count} * (count - 1) / 2);
  grown.clear();
  grown.shrink_to_fit();
  EXPECT_EQ(grown.capacity(), 0u);
}

}  // namespace
}  // namespace mink
