#include "mink/geometry/divide_conquer.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/melkman.hpp"
#include "mink/geometry/orientation.hpp"
#include "radix_sort.hpp"
#include "wrap_order.hpp"

namespace mink {

namespace detail {

void sort_lexicographic(std::vector<Vec2>& points) {
  const std::size_t n = points.size();
  if (n < 4096) {
    std::sort(points.begin(), points.end(), lex_less);
    return;
  }
  std::vector<Vec2> buffer;
  radix_sort(points, buffer, [](const Vec2& p) { return ordered_bits(p.x()); });
  // Equal x: order by y. Runs are short unless the points share columns.
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && points[end].x() == points[begin].x()) ++end;
    if (end - begin > 1) {
      std::sort(points.begin() + static_cast<std::ptrdiff_t>(begin),
                points.begin() + static_cast<std::ptrdiff_t>(end),
                [](const Vec2& p, const Vec2& q) { return p.y() < q.y(); });
    }
    begin = end;
  }
}

std::vector<Vec2> merge_by_common_tangents(std::span<const Vec2> left,
                                           std::span<const Vec2> right) {
  const std::size_t nl = left.size();
  const std::size_t nr = right.size();
  const auto next_l = [nl](std::size_t i) { return i + 1 == nl ? 0 : i + 1; };
  const auto prev_l = [nl](std::size_t i) { return i == 0 ? nl - 1 : i - 1; };
  const auto next_r = [nr](std::size_t i) { return i + 1 == nr ? 0 : i + 1; };
  const auto prev_r = [nr](std::size_t i) { return i == 0 ? nr - 1 : i - 1; };
  const std::size_t left_last =
      static_cast<std::size_t>(std::max_element(left.begin(), left.end(), lex_less) - left.begin());
  const std::size_t right_first = static_cast<std::size_t>(
      std::min_element(right.begin(), right.end(), lex_less) - right.begin());

  // Moving a tangent end to a neighbour that is strictly beyond the line, or on it and
  // farther out, until neither end moves (4.2.2). The farther-on-the-line rule keeps the
  // extreme point of a collinear run as the hull vertex.
  const auto improves = [](const Vec2& pivot, const Vec2& end, const Vec2& neighbour, int side) {
    const int turn = orient2d(pivot, end, neighbour);
    return turn == side || (turn == 0 && detail::farther_on_ray(pivot, neighbour, end));
  };
  // Upper tangent: the left hull climbs CCW, the right hull CW, from the facing extremes.
  std::size_t upper_l = left_last;
  std::size_t upper_r = right_first;
  for (bool moved = true; moved;) {
    moved = false;
    while (nr > 1 && improves(left[upper_l], right[upper_r], right[prev_r(upper_r)], 1)) {
      upper_r = prev_r(upper_r);
      moved = true;
    }
    while (nl > 1 && improves(right[upper_r], left[upper_l], left[next_l(upper_l)], -1)) {
      upper_l = next_l(upper_l);
      moved = true;
    }
  }
  // Lower tangent: the mirror image.
  std::size_t lower_l = left_last;
  std::size_t lower_r = right_first;
  for (bool moved = true; moved;) {
    moved = false;
    while (nr > 1 && improves(left[lower_l], right[lower_r], right[next_r(lower_r)], -1)) {
      lower_r = next_r(lower_r);
      moved = true;
    }
    while (nl > 1 && improves(right[lower_r], left[lower_l], left[prev_l(lower_l)], 1)) {
      lower_l = prev_l(lower_l);
      moved = true;
    }
  }

  // Walk CCW: left hull from its lowest (x, y) vertex (a vertex of the merged hull) to the
  // lower tangent, the right hull from the lower to the upper tangent, then the left hull back.
  // Vertices that end up collinear at the tangents are dropped on the way.
  const std::size_t left_first =
      static_cast<std::size_t>(std::min_element(left.begin(), left.end(), lex_less) - left.begin());
  std::vector<Vec2> merged;
  merged.reserve(nl + nr);
  const auto push = [&merged](const Vec2& v) {
    while (merged.size() >= 2 && orient2d(merged[merged.size() - 2], merged.back(), v) <= 0) {
      merged.pop_back();
    }
    merged.push_back(v);
  };
  std::size_t i = left_first;
  for (;; i = next_l(i)) {
    push(left[i]);
    if (i == lower_l) break;
  }
  for (i = lower_r;; i = next_r(i)) {
    push(right[i]);
    if (i == upper_r) break;
  }
  if (upper_l != left_first) {
    for (i = upper_l; i != left_first; i = next_l(i)) push(left[i]);
  }
  while (merged.size() >= 3 &&
         orient2d(merged[merged.size() - 2], merged.back(), merged.front()) <= 0) {
    merged.pop_back();
  }
  return merged;
}

namespace {

std::vector<Vec2> hull_of_sorted_range(std::span<const Vec2> sorted, std::size_t leaf_size) {
  if (sorted.size() <= leaf_size) return melkman_sorted_unchecked(sorted);
  const std::size_t half = sorted.size() / 2;
  const std::vector<Vec2> left = hull_of_sorted_range(sorted.first(half), leaf_size);
  const std::vector<Vec2> right = hull_of_sorted_range(sorted.subspan(half), leaf_size);
  return merge_by_common_tangents(left, right);
}

}  // namespace

}  // namespace detail

ConvexHull divide_conquer_hull(std::span<const Vec2> points, DivideConquerOptions options) {
  validate_hull_input(points);
  std::vector<Vec2> sorted(points.begin(), points.end());
  detail::sort_lexicographic(sorted);
  // The merge needs the halves strictly apart in (x, y) order, so no point may repeat.
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  const std::size_t leaf_size = options.leaf_size == 0
                                    ? (sorted.size() + 1) / 2
                                    : std::max<std::size_t>(options.leaf_size, 1);
  return detail::hull_from_ccw_ring(detail::hull_of_sorted_range(sorted, leaf_size));
}

}  // namespace mink
