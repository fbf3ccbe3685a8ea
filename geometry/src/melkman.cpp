#include "mink/geometry/melkman.hpp"

#include <algorithm>
#include <stdexcept>

#include "mink/error.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

namespace detail {

std::vector<Vec2> melkman_sorted_unchecked(std::span<const Vec2> sorted_points) {
  const std::size_t n = sorted_points.size();
  if (n == 0) return {};
  const Vec2& first = sorted_points[0];
  // The sorted prefix that lies on one line is a segment from `first` to its last point.
  std::size_t i = 1;
  while (i < n && sorted_points[i] == first) ++i;
  if (i == n) return {first};
  std::size_t segment_end = i;
  ++i;
  while (i < n && orient2d(first, sorted_points[segment_end], sorted_points[i]) == 0) {
    segment_end = i;
    ++i;
  }
  if (i == n) return {first, sorted_points[segment_end]};

  // The deque holds the hull CCW from bottom to top, with the newest point at both ends. The
  // paper's step 8 writes D[bottom+1] twice; the initial triangle here is the three first
  // non-collinear points, in CCW order.
  std::vector<Vec2> deque(2 * n + 4);
  std::size_t bottom = n;
  std::size_t top = n + 3;
  const Vec2& a = first;
  const Vec2& b = sorted_points[segment_end];
  const Vec2& c = sorted_points[i];
  deque[bottom] = c;
  deque[top] = c;
  if (orient2d(a, b, c) > 0) {
    deque[bottom + 1] = a;
    deque[bottom + 2] = b;
  } else {
    deque[bottom + 1] = b;
    deque[bottom + 2] = a;
  }
  Vec2 last = c;
  for (++i; i < n; ++i) {
    const Vec2& v = sorted_points[i];
    if (v == last) continue;
    // v follows every earlier point in (x, y) order, so it is outside their hull: there is no
    // "inside" case on a sorted chain. Pop what v hides from both ends, collinear too.
    while (orient2d(deque[top - 1], deque[top], v) <= 0) --top;
    deque[++top] = v;
    while (orient2d(v, deque[bottom], deque[bottom + 1]) <= 0) ++bottom;
    deque[--bottom] = v;
    last = v;
  }
  return std::vector<Vec2>(deque.begin() + static_cast<std::ptrdiff_t>(bottom),
                           deque.begin() + static_cast<std::ptrdiff_t>(top));
}

}  // namespace detail

std::vector<Vec2> melkman_sorted_chain_hull(std::span<const Vec2> sorted_points) {
  for (std::size_t i = 1; i < sorted_points.size(); ++i) {
    if (lex_less(sorted_points[i], sorted_points[i - 1])) {
      throw InvalidArgumentError("melkman: point " + std::to_string(i) + " is out of (x, y) order");
    }
  }
  std::vector<Vec2> ring = detail::melkman_sorted_unchecked(sorted_points);
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), lex_less), ring.end());
  return ring;
}

}  // namespace mink
