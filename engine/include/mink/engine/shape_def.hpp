#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "mink/engine/filter.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

/// @brief Scale about a fixed point (paper eq. 6), applied to the points once, at shape creation.
struct ShapeScale {
  Vec2 fixed_point{0, 0};  ///< body-local point that stays put
  Vec2 factor{1, 1};       ///< per-axis factors
};

/// @brief What a ShapeDef describes. Every kind is a core (its `points`) plus `radius`.
enum class ShapeType : std::uint8_t {
  polygon,  ///< `points` hulled at creation (any count), rounded by `radius` (>= 0)
  circle,   ///< `points[0]` is the centre, `radius` > 0
  capsule,  ///< `points[0]` and `points[1]` are the two centres, `radius` > 0
  segment,  ///< `points[0]` to `points[1]`, two-sided, no area, `radius` 0
  chain,    ///< a polyline of one-sided segments (World::create_chain); `loop` closes it
};

/// @brief "polygon", "circle", "capsule", "segment" or "chain".
std::string_view to_string(ShapeType type) noexcept;

/// A shape: a convex core (`points`, body-local) plus a rounding `radius`, and its material,
/// filter and event flags. Polygons are hulled at creation with `algorithm`, so any point set
/// will do. Plain data: the factories below fill it in.
struct ShapeDef {
  ShapeType type = ShapeType::polygon;            ///< how `points` and `radius` are read
  std::vector<Vec2> points;                       ///< body-local core points
  Real radius = 0;                                ///< circle/capsule radius, polygon rounding
  bool loop = false;                              ///< chains only: join the last point to the first
  HullAlgorithm algorithm = HullAlgorithm::chan;  ///< polygons: which algorithm hulls `points`
  Real density = 1;                               ///< kg/m^2, >= 0
  Real friction = 0.6;                ///< Coulomb coefficient, in [0, max_setting_magnitude]
  Real restitution = 0;               ///< bounciness, in [0, max_setting_magnitude] (0: none)
  std::optional<ShapeScale> scale;    ///< polygons: applied to `points` before hulling
  Filter filter;                      ///< which shapes it may touch
  bool is_sensor = false;             ///< detects overlap (sensor events), never pushes
  bool enable_contact_events = true;  ///< begin/end contact events for this shape's pairs
  bool enable_sensor_events = true;   ///< sensors see this shape (and a sensor reports at all)
  bool enable_hit_events = false;     ///< hit events for this shape's pairs
  std::uint64_t user_data = 0;        ///< anything the caller wants back from shape_user_data

  /// @brief A box of half extents (hx, hy) centred at `center`, rotated by `angle` (radians).
  /// @throws InvalidArgumentError unless hx and hy are positive and finite.
  static ShapeDef box(Real hx, Real hy, const Vec2& center = {0, 0}, Real angle = 0);
  /// @brief A regular polygon of `count` vertices on a circle of `radius` about `center`.
  /// @throws InvalidArgumentError for count < 3 or a radius that is not positive.
  static ShapeDef regular_polygon(int count, Real radius, const Vec2& center = {0, 0});
  /// @brief A disk of `radius` about `center`.
  static ShapeDef circle(Real radius, const Vec2& center = {0, 0});
  /// @brief The points within `radius` of the segment center1-center2.
  static ShapeDef capsule(const Vec2& center1, const Vec2& center2, Real radius);
  /// @brief A two-sided segment.
  static ShapeDef segment(const Vec2& point1, const Vec2& point2);
  /// @brief A chain through `points` (at least 2; 3 when `loop`); collides on the right side of
  /// each segment, so a counter-clockwise loop faces outwards.
  static ShapeDef chain(std::vector<Vec2> points, bool loop = false);
};

/// @brief Checks every field of `def` for its type (finite, in range, enough distinct points).
/// @throws InvalidArgumentError naming the first bad field, NonFiniteInputError for a point
void check_shape_def(const ShapeDef& def);

/// @brief The hull a polygon ShapeDef makes (scale, then hull), in body-local coordinates.
/// @throws InvalidArgumentError for a negative or non-finite density, or a friction or
/// restitution outside [0, max_setting_magnitude]
/// or a bad scale
/// @throws NonFiniteInputError, DegenerateInputError (the hull errors) for bad points
ConvexHull make_shape_hull(const ShapeDef& def);

}  // namespace mink
