#pragma once

#include <optional>
#include <vector>

#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

/// @brief Scale about a fixed point (paper eq. 6), applied to the points once, at shape creation.
struct ShapeScale {
  Vec2 fixed_point{0, 0};  ///< body-local point that stays put
  Vec2 factor{1, 1};       ///< per-axis factors
};

/// A convex shape: `points` (body-local) are hulled at creation with `algorithm`, so any
/// point set will do; extra interior points cost nothing afterwards. Plain data.
struct ShapeDef {
  std::vector<Vec2> points;                       ///< body-local; hulled at creation
  HullAlgorithm algorithm = HullAlgorithm::chan;  ///< which algorithm hulls `points`
  Real density = 1;                               ///< kg/m^2, >= 0
  Real friction = 0.6;                            ///< Coulomb coefficient, >= 0
  Real restitution = 0;                           ///< bounciness, >= 0 (0: none)
  std::optional<ShapeScale> scale;                ///< applied to `points` before hulling

  /// @brief A box of half extents (hx, hy) centred at `center`, rotated by `angle` (radians).
  /// @throws InvalidArgumentError unless hx and hy are positive and finite.
  static ShapeDef box(Real hx, Real hy, const Vec2& center = {0, 0}, Real angle = 0);
  /// @brief A regular polygon of `count` vertices on a circle of `radius` about `center`.
  /// @throws InvalidArgumentError for count < 3 or a radius that is not positive.
  static ShapeDef regular_polygon(int count, Real radius, const Vec2& center = {0, 0});
};

/// @brief The hull a ShapeDef makes (scale, then hull), in body-local coordinates.
/// @throws InvalidArgumentError for a negative or non-finite density, friction or restitution
/// or a bad scale
/// @throws NonFiniteInputError, DegenerateInputError (the hull errors) for bad points
ConvexHull make_shape_hull(const ShapeDef& def);

}  // namespace mink
