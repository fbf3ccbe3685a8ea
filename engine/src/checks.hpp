#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "mink/engine/body_def.hpp"
#include "mink/engine/world_def.hpp"
#include "mink/error.hpp"
#include "mink/geometry/types.hpp"

namespace mink::detail {

// The argument checks of the World API: a failed one throws InvalidArgumentError with `what`.
inline void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidArgumentError(what);
}

inline bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

// Finite and within `limit` of the origin on each axis.
inline bool within(const Vec2& v, Real limit) {
  return finite(v) && std::abs(v.x()) <= limit && std::abs(v.y()) <= limit;
}

// Finite and within max_world_coordinate of the origin on each axis.
inline bool within_world(const Vec2& v) {
  return within(v, max_world_coordinate);
}

// Finite and within four times max_world_coordinate on each axis: where what a body carries
// can reach. Its origin lies within max_world_coordinate, its shapes' points and its centre of
// mass within that of the origin, and a radius adds at most that again (as a body's extent).
inline bool within_reach(const Vec2& v) {
  return within(v, 4 * max_world_coordinate);
}

// Finite and within max_setting_magnitude: a velocity (each component), an angular velocity.
inline bool within_settings(Real v) {
  return std::isfinite(v) && std::abs(v) <= max_setting_magnitude;
}
inline bool within_settings(const Vec2& v) {
  return within_settings(v.x()) && within_settings(v.y());
}

// A friction or restitution: non-negative and within max_setting_magnitude, so that a
// contact's mix of two (the root of their product, or the larger) stays finite.
inline bool valid_coefficient(Real v) {
  return v >= 0 && within_settings(v);
}

// `value` to all 17 significant digits: for messages about values too close to a limit to
// show in fewer.
inline std::string exact_number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace mink::detail
