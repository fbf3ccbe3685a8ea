#include "mink/geometry/hull_input.hpp"

#include <algorithm>
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
  if (!all_on_one_line(points)) return;
  const auto same_as_first = [&](const Vec2& p) { return p == points[0]; };
  if (std::all_of(points.begin(), points.end(), same_as_first)) {
    throw DegenerateInputError("all " + std::to_string(points.size()) +
                               " points are the same point");
  }
  throw DegenerateInputError("all " + std::to_string(points.size()) + " points lie on one line");
}

}  // namespace mink
