#include "mink/geometry/jarvis.hpp"

#include <algorithm>
#include <stdexcept>

#include "mink/geometry/hull_input.hpp"
#include "wrap_order.hpp"

namespace mink {

ConvexHull jarvis_hull(std::span<const Vec2> points) {
  validate_hull_input(points);
  const Vec2 start = *std::min_element(points.begin(), points.end(), lex_less);
  std::vector<Vec2> ring{start};
  Vec2 current = start;
  for (;;) {
    const Vec2* next = nullptr;
    for (const Vec2& candidate : points) {
      if (candidate == current) continue;
      if (next == nullptr || detail::wraps_before(current, candidate, *next)) next = &candidate;
    }
    if (*next == start) break;
    current = *next;
    ring.push_back(current);
    // Exact predicates make every step a new hull vertex; more steps than points is a bug.
    if (ring.size() > points.size()) throw std::logic_error("jarvis_hull: wrap did not close");
  }
  return detail::hull_from_ccw_ring(std::move(ring));
}

}  // namespace mink
