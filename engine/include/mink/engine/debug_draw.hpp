#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "mink/geometry/types.hpp"

namespace mink {

struct DrawColor {
  float r = 1, g = 1, b = 1, a = 1;
};

// What World::draw reports, layer by layer; a renderer implements the primitives. Only the
// layers whose flag is set are drawn.
class DebugDraw {
 public:
  enum Flags : std::uint32_t {
    shapes = 1u << 0,
    aabbs = 1u << 1,  // broadphase fat boxes
    contact_points = 1u << 2,
    contact_normals = 1u << 3,
    broadphase_pairs = 1u << 4,  // segments between the centres of paired shapes
    velocities = 1u << 5,
    sleeping = 1u << 6,  // sleeping bodies drawn in their own colour (with `shapes`)
    centers_of_mass = 1u << 7,
  };

  virtual ~DebugDraw() = default;
  virtual void draw_polygon(std::span<const Vec2> vertices, DrawColor color, bool filled) = 0;
  virtual void draw_segment(const Vec2& a, const Vec2& b, DrawColor color) = 0;
  virtual void draw_point(const Vec2& p, float size, DrawColor color) = 0;
  virtual void draw_circle(const Vec2& center, Real radius, DrawColor color) = 0;
  virtual void draw_text(const Vec2& p, std::string_view text, DrawColor color) = 0;

  std::uint32_t flags = shapes;
};

}  // namespace mink
