#include "mink/geometry/graham.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/orientation.hpp"
#include "polar_order.hpp"
#include "radix_sort.hpp"

namespace mink {

namespace detail {

namespace {

constexpr std::size_t kSmall = 16;

// Larger inputs: sort by the pseudo-angle, then settle every run of keys too close for their
// rounding errors to tell apart with the exact comparison. A pair the keys misorder differs
// by less than the tolerance, and so does every key between them, so the pair shares a run.
// The radix sort sees the keys as fixed-point numbers scaled to the range they span, so a
// group crowded into a narrow cone still spreads over all buckets, and two passes do.
// Fills scratch.sorted with the points other than the pivot; returns false when a key cannot
// be trusted (a difference overflowed). Fresh memory is slow to fault in, so nothing is
// stored twice.
template <typename Precedes>
bool sort_by_pseudo_angle(const Vec2& pivot, std::span<const Vec2> points, GrahamScratch& scratch,
                          Precedes precedes) {
  std::vector<Real>& keys = scratch.keys;  // first by input position, later in sorted order
  keys.resize(points.size());
  bool reliable = true;
  Real lowest = std::numeric_limits<Real>::infinity();
  Real highest = -lowest;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Real key = pseudo_angle(pivot, points[i]);  // NaN for the pivot, skipped below
    reliable &= pseudo_angle_reliable(pivot, points[i]);
    keys[i] = key;
    if (points[i] != pivot) {
      reliable &= std::isfinite(key);
      lowest = std::min(lowest, key);
      highest = std::max(highest, key);
    }
  }
  if (!reliable) return false;

  // Fixed-point digits: 16 bits in two 8-bit passes for small groups, 24 bits in two 12-bit
  // passes up to 2^21 points, 32 bits in three passes beyond.
  const std::size_t n = points.size();
  const int key_bits = n < 4096 ? 16 : n < (std::size_t{1} << 21) ? 24 : 32;
  const Real largest_digit = std::ldexp(1.0, key_bits) - 1;
  // Monotone in the key: subtracting and scaling by a positive number never reverse an order.
  // A span too narrow to scale (the quotient overflows) leaves one bucket: the exact passes
  // below then do all the ordering.
  Real scale = highest > lowest ? largest_digit / (highest - lowest) : 0;
  if (!std::isfinite(scale)) scale = 0;
  std::vector<std::uint64_t>& order = scratch.order;  // fixed-point key above bit 32, then index
  order.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (points[i] == pivot) continue;
    const Real scaled = std::min((keys[i] - lowest) * scale, largest_digit);
    order.push_back((static_cast<std::uint64_t>(scaled) << 32) | i);
  }
  const auto item_key = [](std::uint64_t item) { return item; };
  if (key_bits == 16) {
    radix_sort<8>(order, scratch.buffer, item_key, 32, 48);
  } else if (key_bits == 24) {
    radix_sort<12>(order, scratch.buffer, item_key, 32, 56);
  } else {
    radix_sort<11>(order, scratch.buffer, item_key, 32, 64);
  }
  const std::size_t others = order.size();
  std::vector<Vec2>& sorted = scratch.sorted;
  sorted.resize(others);
  keys.resize(others);
  for (std::size_t j = 0; j < others; ++j) {
    sorted[j] = points[order[j] & 0xffffffffULL];
    keys[j] = pseudo_angle(pivot, sorted[j]);
  }
  // Items that share their fixed-point key came out in input order: order each such run by
  // the full key. A sort, not insertion: near-collinear input makes one run of every point.
  for (std::size_t begin = 0; begin < others;) {
    std::size_t end = begin + 1;
    while (end < others && (order[end] >> 32) == (order[begin] >> 32)) ++end;
    if (end - begin > 1 && !std::is_sorted(keys.begin() + static_cast<std::ptrdiff_t>(begin),
                                           keys.begin() + static_cast<std::ptrdiff_t>(end))) {
      std::vector<std::pair<Real, Vec2>>& run = scratch.keyed_run;
      run.clear();
      for (std::size_t j = begin; j < end; ++j) run.emplace_back(keys[j], sorted[j]);
      std::sort(run.begin(), run.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t j = begin; j < end; ++j) std::tie(keys[j], sorted[j]) = run[j - begin];
    }
    begin = end;
  }
  for (std::size_t begin = 0; begin < others;) {
    std::size_t end = begin + 1;
    while (end < others && keys_indistinct(keys[end - 1], keys[end])) ++end;
    if (end - begin > 1) {
      std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(begin),
                sorted.begin() + static_cast<std::ptrdiff_t>(end), precedes);
    }
    begin = end;
  }
  return true;
}

}  // namespace

void graham_scan(std::span<const Vec2> points, GrahamScratch& scratch, std::vector<Vec2>& ring) {
  if (points.empty()) return;
  const Vec2 pivot = *std::min_element(points.begin(), points.end(), lex_less);
  const auto precedes = [&pivot](const Vec2& a, const Vec2& b) {
    return polar_precedes(pivot, a, b);
  };

  if (points.size() <= kSmall) {
    // Small groups (Chan's first rounds make many): the same key-then-exact sort, by
    // insertion in local arrays.
    std::array<Vec2, kSmall> sorted;
    std::array<Real, kSmall> keys;
    std::size_t count = 0;
    bool reliable = true;
    for (const Vec2& p : points) {
      if (p == pivot) continue;
      const Real key = pseudo_angle(pivot, p);
      reliable &= std::isfinite(key) && pseudo_angle_reliable(pivot, p);
      std::size_t j = count++;
      for (; j > 0 && keys[j - 1] > key; --j) {
        keys[j] = keys[j - 1];
        sorted[j] = sorted[j - 1];
      }
      keys[j] = key;
      sorted[j] = p;
    }
    for (std::size_t i = 1; i < count; ++i) {
      if (!reliable || keys_indistinct(keys[i - 1], keys[i])) {
        // Exact insertion step; a no-op where the keys already had the order right.
        const Vec2 p = sorted[i];
        std::size_t j = i;
        for (; j > 0 && precedes(p, sorted[j - 1]); --j) sorted[j] = sorted[j - 1];
        sorted[j] = p;
      }
    }
    std::array<Vec2, kSmall + 1> stack;
    std::size_t top = 0;
    stack[top++] = pivot;
    for (std::size_t i = 0; i < count; ++i) {
      while (top >= 2 && orient2d(stack[top - 2], stack[top - 1], sorted[i]) <= 0) --top;
      stack[top++] = sorted[i];
    }
    ring.insert(ring.end(), stack.begin(), stack.begin() + static_cast<std::ptrdiff_t>(top));
    return;
  }

  std::vector<Vec2>& others = scratch.sorted;
  if (points.size() > std::numeric_limits<std::uint32_t>::max() ||
      !sort_by_pseudo_angle(pivot, points, scratch, precedes)) {
    others.clear();
    for (const Vec2& p : points) {
      if (p != pivot) others.push_back(p);
    }
    std::sort(others.begin(), others.end(), precedes);
  }

  const std::size_t base = ring.size();
  ring.reserve(base + others.size() + 1);  // untouched capacity costs no page faults
  ring.push_back(pivot);
  for (const Vec2& p : others) {
    // Pop right turns and straight continuations: the hull keeps only strict left turns.
    while (ring.size() - base >= 2 && orient2d(ring[ring.size() - 2], ring.back(), p) <= 0) {
      ring.pop_back();
    }
    ring.push_back(p);
  }
}

}  // namespace detail

ConvexHull graham_hull(std::span<const Vec2> points) {
  validate_hull_input(points);
  detail::GrahamScratch scratch;
  std::vector<Vec2> ring;
  detail::graham_scan(points, scratch, ring);
  return detail::hull_from_ccw_ring(std::move(ring));
}

}  // namespace mink
