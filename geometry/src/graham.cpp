#include "mink/geometry/graham.hpp"

#include <algorithm>

#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

namespace detail {

void graham_scan(std::span<const Vec2> points, std::vector<Vec2>& scratch,
                 std::vector<Vec2>& ring) {
  if (points.empty()) return;
  const Vec2 pivot = *std::min_element(points.begin(), points.end(), lex_less);
  scratch.clear();
  for (const Vec2& p : points) {
    if (p != pivot) scratch.push_back(p);
  }
  // Every other point lies right of or straight above the pivot, a range of directions
  // narrower than a half-turn, so orientation is a strict weak order on them. Points on one
  // ray from the pivot go nearest first; along such a ray (x, y) order is distance order.
  const auto precedes = [&pivot](const Vec2& a, const Vec2& b) {
    const int turn = orient2d(pivot, a, b);
    if (turn != 0) return turn > 0;
    return lex_less(a, b);
  };
  std::sort(scratch.begin(), scratch.end(), precedes);

  const std::size_t base = ring.size();
  ring.push_back(pivot);
  for (const Vec2& p : scratch) {
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
  std::vector<Vec2> scratch;
  std::vector<Vec2> ring;
  scratch.reserve(points.size());
  detail::graham_scan(points, scratch, ring);
  return detail::hull_from_ccw_ring(std::move(ring));
}

}  // namespace mink
