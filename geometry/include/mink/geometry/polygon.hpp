#pragma once

#include <span>

#include "mink/geometry/types.hpp"

namespace mink {

/// Mass properties of a simple polygon of unit density, vertices in order (CCW gives a
/// positive area). Computed about the first vertex, so far-from-origin polygons keep precision.
struct AreaProperties {
  Real area = 0;          ///< signed: positive for counter-clockwise vertices
  Vec2 centroid{0, 0};    ///< paper eq. 3
  Real polar_moment = 0;  ///< second moment of area about the centroid, integral of |r|^2 dA
};

/// Shoelace area, positive for counter-clockwise order.
Real signed_area(std::span<const Vec2> polygon);

/// @brief Area, centroid (eq. 3) and polar second moment about the centroid in one pass.
/// @throws DegenerateInputError when there are fewer than 3 vertices or the area is zero.
AreaProperties area_properties(std::span<const Vec2> polygon);

/// @brief Centroid alone (eq. 3).
/// @throws DegenerateInputError as area_properties does.
Vec2 centroid(std::span<const Vec2> polygon);

}  // namespace mink
