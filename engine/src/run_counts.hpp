#pragma once

// A stable counting sort split into runs, one per worker: each run counts its items per bucket
// (run r's count of bucket b at counts[r * stride + b]), place_runs turns the counts into each
// run's first position per bucket, and each run then places its items from those: the order one
// run over all the items gives, buckets in order and, within a bucket, the items in theirs.

#include <cstddef>
#include <cstdint>
#include <span>

namespace mink::detail {

// Buckets in order and, within a bucket, the runs in order; returns how many items there are.
inline std::uint32_t place_runs(std::span<std::uint32_t> counts, std::uint32_t runs,
                                std::size_t stride, std::size_t buckets) {
  std::uint32_t placed = 0;
  for (std::size_t bucket = 0; bucket < buckets; ++bucket) {
    for (std::uint32_t run = 0; run < runs; ++run) {
      std::uint32_t& count = counts[run * stride + bucket];
      const std::uint32_t here = count;
      count = placed;
      placed += here;
    }
  }
  return placed;
}

// Where run `run` of `runs` begins among `items`.
inline std::size_t run_begin(std::size_t items, std::uint32_t run, std::uint32_t runs) {
  return items * run / runs;
}

}  // namespace mink::detail
