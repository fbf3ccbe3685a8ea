#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

struct DivideConquerOptions {
  /// Ranges of at most this many sorted points are hulled by Melkman directly; larger ones are
  /// halved and merged by common tangents. 0 means the paper's shape: one split into two halves.
  std::size_t leaf_size = 0;
};

/// Divide and conquer (paper 4.2): sort by (x, y), hull each half by Melkman on the sorted
/// chain, merge the halves by their upper and lower common tangents (4.2.2). O(n log n).
ConvexHull divide_conquer_hull(std::span<const Vec2> points, DivideConquerOptions options = {});

namespace detail {
/// Hull of two CCW rings whose points are separated in (x, y) order: every point of `left`
/// precedes every point of `right`. Either ring may be degenerate (1 or 2 vertices).
std::vector<Vec2> merge_by_common_tangents(std::span<const Vec2> left, std::span<const Vec2> right);
/// Sorts by (x, y): a radix sort on x with ties settled by y.
void sort_lexicographic(std::vector<Vec2>& points);
}  // namespace detail

}  // namespace mink
