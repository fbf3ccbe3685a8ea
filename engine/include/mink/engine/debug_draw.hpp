#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "mink/geometry/types.hpp"

namespace mink {

/// @brief A straight (not premultiplied) RGBA colour.
struct Color {
  float r = 1, g = 1, b = 1, a = 1;  ///< each in [0, 1]; a < 1 blends over what is below
};

/// @brief Bit flags: what World::draw emits; a renderer switches layers on and off with
/// DebugDraw::layers.
enum DrawLayer : std::uint32_t {
  draw_shapes = 1u << 0,            ///< every shape's hull, coloured by body type
  draw_aabbs = 1u << 1,             ///< the broadphase boxes
  draw_contact_points = 1u << 2,    ///< manifold points
  draw_contact_normals = 1u << 3,   ///< manifold normals at their points
  draw_broadphase_pairs = 1u << 4,  ///< a segment between the boxes of each pair
  draw_velocities = 1u << 5,        ///< linear velocity of each body
  draw_sleep_state = 1u << 6,       ///< sleeping bodies in their own colour
  draw_centers_of_mass = 1u << 7,   ///< a point at each dynamic body's centre of mass
  draw_joints = 1u << 8,            ///< anchors, axes and limits of each joint
};

/// The only link between the engine and rendering: the engine describes what to draw in
/// world coordinates, the render layer implements this with GL. The engine never includes GL.
class DebugDraw {
 public:
  virtual ~DebugDraw() = default;

  /// @brief A convex polygon, counter-clockwise, filled and outlined.
  virtual void draw_polygon(std::span<const Vec2> vertices, Color fill, Color outline) = 0;
  /// @brief A straight line between two world points.
  virtual void draw_segment(const Vec2& a, const Vec2& b, Color color) = 0;
  /// @brief A dot of `pixels` diameter on screen, whatever the zoom.
  virtual void draw_point(const Vec2& position, float pixels, Color color) = 0;
  /// @brief A circle outline of `radius` world units.
  virtual void draw_circle(const Vec2& center, Real radius, Color color) = 0;
  /// @brief A label anchored at a world position, drawn at a fixed screen size.
  virtual void draw_text(const Vec2& position, std::string_view text, Color color) = 0;

  /// A filled disk with a radius line at `angle` (so rolling shows). By default a polygon of
  /// enough sides to look round, its outline and the line; a renderer may draw it directly.
  virtual void draw_solid_circle(const Vec2& center, Real radius, Real angle, Color fill,
                                 Color outline);
  /// @brief A filled capsule (stadium); by default tessellated like draw_solid_circle.
  virtual void draw_solid_capsule(const Vec2& center1, const Vec2& center2, Real radius, Color fill,
                                  Color outline);
  /// @brief A convex polygon (counter-clockwise) rounded by `radius`; by default tessellated.
  virtual void draw_rounded_polygon(std::span<const Vec2> vertices, Real radius, Color fill,
                                    Color outline);

  /// DrawLayer flags the caller wants drawn.
  std::uint32_t layers = draw_shapes | draw_contact_points | draw_joints;
};

}  // namespace mink
