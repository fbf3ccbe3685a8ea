#include "mink/geometry/hull_input.hpp"

#include <cmath>

#include "mink/error.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

void require_finite(std::span<const Vec2> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      throw NonFiniteInputError(i);
    }
  }
}

void validate_hull_input(std::span<const Vec2> points) {
  require_finite(points);
  if (points.size() < 3) {
    throw DegenerateInputError("a hull needs at least 3 points, got " +
                               std::to_string(points.size()));
  }
  const Vec2& first = points[0];
  std::size_t other = 1;
  while (other < points.size() && points[other] == first) ++other;
  if (other == points.size()) {
    throw DegenerateInputError("all " + std::to_string(points.size()) +
                               " points are the same point");
  }
  for (std::size_t i = other + 1; i < points.size(); ++i) {
    if (orient2d(first, points[other], points[i]) != 0) return;
  }
  throw DegenerateInputError("all " + std::to_string(points.size()) + " points lie on one line");
}

}  // namespace mink
