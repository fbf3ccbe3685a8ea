#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include "mink/geometry/aabb.hpp"
#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/ray_cast.hpp"

namespace mink {

/// @file
/// @brief The shape kinds as narrowphase geometry, each a convex core (a point, a segment or a
/// hull) plus a radius: the paper's GJK works on the cores, radii are added after.

/// @brief A disk: a point core of `radius`.
struct Circle {
  Vec2 center{0, 0};  ///< local
  Real radius = 0;    ///< > 0
};

/// @brief A stadium: a segment core of `radius`.
struct Capsule {
  Vec2 center1{0, 0};  ///< local
  Vec2 center2{0, 0};  ///< local, distinct from center1
  Real radius = 0;     ///< > 0
};

/// @brief A two-sided line segment (no radius, no area).
struct Segment {
  Vec2 point1{0, 0};  ///< local
  Vec2 point2{0, 0};  ///< local, distinct from point1
};

/// One segment of a chain (a polyline for terrain): one-sided, it only collides with shapes on
/// its right side (the normal is the right perpendicular of point2 - point1, so a
/// counter-clockwise loop faces outwards). The ghost vertices are the neighbouring chain points
/// before point1 and after point2; contacts use them so that a shape sliding across the joint
/// of two segments never catches on it.
struct ChainSegment {
  Vec2 ghost1{0, 0};  ///< the chain point before segment.point1
  Segment segment;    ///< the collision segment
  Vec2 ghost2{0, 0};  ///< the chain point after segment.point2
};

/// @brief A convex polygon (any vertex count, prepared at shape creation), optionally rounded.
struct RoundedPolygon {
  PreparedHull hull;  ///< the core, local
  Real radius = 0;    ///< >= 0: rounding added around the core
};

/// @brief Which alternative a ShapeGeometry holds (the variant's index order).
enum class ShapeKind : std::uint8_t { circle, capsule, segment, chain_segment, polygon };

/// @brief Any shape, in its body's local frame.
using ShapeGeometry = std::variant<Circle, Capsule, Segment, ChainSegment, RoundedPolygon>;

/// @brief The kind of `geometry`.
inline ShapeKind kind_of(const ShapeGeometry& geometry) noexcept {
  return static_cast<ShapeKind>(geometry.index());
}

/// @brief Mass properties of a shape of uniform density.
struct MassData {
  Real mass = 0;                ///< kg (0 for segments and chains: no area)
  Vec2 center{0, 0};            ///< centre of mass, local
  Real rotational_inertia = 0;  ///< about the centre of mass
};

/// @brief Checks what the narrowphase relies on: finite coordinates, radii > 0 for circles and
/// capsules (>= 0 for polygons), distinct capsule centres and segment points.
/// @throws InvalidArgumentError naming the offending input
void validate_shape(const ShapeGeometry& geometry);

/// @brief Exact mass, centroid and inertia for `density` (kg/m^2); rounded polygons included
/// (core, edge rectangles and vertex sectors).
/// @throws InvalidArgumentError for a negative or non-finite density or an invalid shape
/// (see validate_shape)
MassData compute_mass(const ShapeGeometry& geometry, Real density);

/// @brief Tight world box of the posed shape, radius included.
Aabb compute_aabb(const ShapeGeometry& geometry, const Pose& pose);

/// First hit of origin -> origin + translation (world) against the posed shape, entering from
/// outside. A ray starting inside a solid shape does not hit it (as in Box2D); a chain segment is
/// hit only from its right side, a segment from either side.
std::optional<RayHit> ray_cast(const ShapeGeometry& geometry, const Pose& pose, const Vec2& origin,
                               const Vec2& translation);

/// @brief True when `point` (world) lies in the posed shape, boundary included. Segments and
/// chain segments contain no point.
bool contains_point(const ShapeGeometry& geometry, const Pose& pose, const Vec2& point);

/// @brief The point of the posed shape (radius included) nearest `point` (world); `point`
/// itself when inside.
Vec2 closest_point(const ShapeGeometry& geometry, const Pose& pose, const Vec2& point);

/// @brief Distance between two posed shapes, radii included.
struct ShapeDistance {
  Real distance = 0;     ///< surface to surface: negative is not reported (0 when overlapping)
  bool overlap = false;  ///< the shapes (radii included) overlap or touch
  Vec2 point_a{0, 0};    ///< nearest point on A's surface (world) when apart
  Vec2 point_b{0, 0};    ///< nearest point on B's surface (world) when apart
  Vec2 normal{0, 0};     ///< unit, A towards B, when apart
};

/// @brief GJK distance between the cores, less both radii. A chain segment counts as its
/// two-sided segment here.
ShapeDistance shape_distance(const ShapeGeometry& a, const Pose& pose_a, const ShapeGeometry& b,
                             const Pose& pose_b);

}  // namespace mink
