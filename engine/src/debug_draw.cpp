// DebugDraw's default drawing of round shapes: arcs as short polygon edges, fine enough that
// a shape looks round at any zoom a debug view uses.

#include "mink/engine/debug_draw.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace mink {

namespace {

constexpr int kArcSegmentsPerTurn = 32;

// Appends the arc of `radius` about `center` from angle `from` counter-clockwise to `to`.
void append_arc(std::vector<Vec2>& out, const Vec2& center, Real radius, Real from, Real to) {
  const Real sweep = to - from;
  const int steps = std::max(
      1, static_cast<int>(std::ceil(sweep / (2 * std::numbers::pi) * kArcSegmentsPerTurn)));
  for (int i = 0; i <= steps; ++i) {
    const Real a = from + sweep * i / steps;
    out.push_back(center + radius * Vec2(std::cos(a), std::sin(a)));
  }
}

// The outline of a convex polygon grown by `radius`: each vertex becomes an arc between the
// normals of its two edges.
std::vector<Vec2> rounded_outline(std::span<const Vec2> vertices, Real radius) {
  std::vector<Vec2> out;
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = vertices[(i + n - 1) % n];
    const Vec2& v = vertices[i];
    const Vec2& next = vertices[(i + 1) % n];
    const Vec2 in = v - prev, outgoing = next - v;
    Real from = std::atan2(-in.x(), in.y());  // outward normal of the edge into v
    Real to = std::atan2(-outgoing.x(), outgoing.y());
    if (n == 1) to = from + 2 * std::numbers::pi;
    while (to < from) to += 2 * std::numbers::pi;
    append_arc(out, v, radius, from, to);
  }
  return out;
}

}  // namespace

void DebugDraw::draw_solid_circle(const Vec2& center, Real radius, Real angle, Color fill,
                                  Color outline) {
  std::vector<Vec2> ring;
  append_arc(ring, center, radius, 0, 2 * std::numbers::pi);
  ring.pop_back();  // the closing point repeats the first
  draw_polygon(ring, fill, outline);
  draw_segment(center, center + radius * Vec2(std::cos(angle), std::sin(angle)), outline);
}

void DebugDraw::draw_solid_capsule(const Vec2& center1, const Vec2& center2, Real radius,
                                   Color fill, Color outline) {
  const Vec2 axis = center2 - center1;
  const Real along = std::atan2(axis.y(), axis.x());
  std::vector<Vec2> ring;
  const Real quarter = std::numbers::pi / 2;
  append_arc(ring, center2, radius, along - quarter, along + quarter);
  append_arc(ring, center1, radius, along + quarter, along + 3 * quarter);
  draw_polygon(ring, fill, outline);
}

void DebugDraw::draw_rounded_polygon(std::span<const Vec2> vertices, Real radius, Color fill,
                                     Color outline) {
  if (radius <= 0) {
    draw_polygon(vertices, fill, outline);
    return;
  }
  const std::vector<Vec2> ring = rounded_outline(vertices, radius);
  draw_polygon(ring, fill, outline);
}

}  // namespace mink
