#pragma once

#include <optional>
#include <vector>

#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

// Scale about a fixed point (paper eq. 6), applied to the points once, at shape creation.
struct ShapeScale {
  Vec2 fixed_point{0, 0};
  Vec2 factor{1, 1};
};

// A convex shape: `points` (body-local) are hulled at creation with `algorithm`, so any point
// set will do; extra interior points cost nothing afterwards. Plain data.
struct ShapeDef {
  std::vector<Vec2> points;
  HullAlgorithm algorithm = HullAlgorithm::chan;
  Real density = 1;
  Real friction = 0.6;
  Real restitution = 0;
  std::optional<ShapeScale> scale;

  // A box of half extents (hx, hy) centred at `center`, rotated by `angle`.
  static ShapeDef box(Real hx, Real hy, const Vec2& center = {0, 0}, Real angle = 0);
  // A regular polygon of `count` vertices on a circle of `radius` about `center`.
  static ShapeDef regular_polygon(int count, Real radius, const Vec2& center = {0, 0});
};

// The hull a ShapeDef makes (scale, then hull). Throws InvalidArgumentError for a negative or
// non-finite density, friction or restitution or a bad scale, and the hull errors
// (NonFiniteInputError, DegenerateInputError) for bad points.
ConvexHull make_shape_hull(const ShapeDef& def);

}  // namespace mink
