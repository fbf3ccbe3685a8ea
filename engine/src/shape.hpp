#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "mink/broadphase/broadphase.hpp"
#include "mink/broadphase/proxy_store.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "prefetch.hpp"

namespace mink::detail {

inline constexpr std::uint32_t kNoChain = std::numeric_limits<std::uint32_t>::max();

// How the broadphase fattens a shape's box: by at most 5 cm and an eighth of its size (Box2D
// v3's margins), with no reach ahead. A box stretched along the body's motion paired fast
// shapes long before they met: a whirling drum of small shapes kept 2.9 times Box2D v3's
// contacts so, and a turning drum of small boxes five times with a fixed 10 cm margin that
// reached four steps ahead. Fast shapes that meet within a step are continuous collision's.
inline constexpr Fattening kBroadphaseFattening{0.05, 0.125, 0};

// A shape record: geometry in its body's frame, material, filter and event flags.
struct Shape {
  ShapeGeometry geometry = Circle{};
  ShapeType type = ShapeType::polygon;
  // Static sharp polygons only: 1 for each edge that another static polygon's edge covers
  // exactly (a seam between tiles); empty when none is. See seam.cpp. Beside the geometry,
  // as every manifold of a sharp polygon asks whether it is empty.
  std::vector<std::uint8_t> internal_edges;
  // Tight box at the current pose, grown by the speculative margin; a fast body's shapes, after
  // a step its sweep found clear, keep theirs bare (finish_body), and say so.
  Aabb aabb;
  bool bare_box = false;
  Real density = 1, friction = 0.6, restitution = 0;
  Filter filter;
  bool sensor = false;
  bool contact_events = true, sensor_events = true, hit_events = false;
  HullAlgorithm algorithm = HullAlgorithm::chan;
  ProxyId proxy = null_proxy;
  std::uint32_t body = 0;
  std::uint32_t chain = kNoChain;  // which create_chain call made it
  bool chain_loop = false;
  std::uint32_t generation = 0;
  bool alive = false;
  std::uint64_t user_data = 0;
};

// Asks for the first `max_bytes` of a polygon's arrays (its vertices come first), which live
// apart from the shape record; nothing for other kinds.
inline void prefetch_polygon(const Shape& shape, std::size_t max_bytes) {
  if (const auto* polygon = std::get_if<RoundedPolygon>(&shape.geometry)) {
    const std::span<const Vec2> block = polygon->hull.storage();
    prefetch_bytes(block.data(), std::min(block.size_bytes(), max_bytes));
  }
}

// Calls visit(point) for each point of the shape's core (a hull's vertices, a capsule's two
// centres, ...): every shape is its core grown by its radius.
template <typename Visit>
void for_each_core_point(const ShapeGeometry& geometry, Visit&& visit) {
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          visit(g.center);
        } else if constexpr (std::is_same_v<G, Capsule>) {
          visit(g.center1);
          visit(g.center2);
        } else if constexpr (std::is_same_v<G, Segment>) {
          visit(g.point1);
          visit(g.point2);
        } else if constexpr (std::is_same_v<G, ChainSegment>) {
          visit(g.segment.point1);
          visit(g.segment.point2);
        } else {
          for (const Vec2& v : g.hull.vertices()) visit(v);
        }
      },
      geometry);
}

// The narrowphase geometry a (checked) ShapeDef describes; polygons are hulled here.
ShapeGeometry make_geometry(const ShapeDef& def);

// What the ShapeDef checks and the setters refuse, as InvalidArgumentError naming `what`
// ("ShapeDef.friction", "set_shape_friction of shape 3"): a density that is negative or not
// finite; a friction or restitution outside [0, max_setting_magnitude] (shape_def.cpp).
void check_density(Real density, const std::string& what);
void check_coefficient(Real value, const std::string& what);

// Throws InvalidArgumentError, naming `what`, when `density` gives the shape a positive mass or
// rotational inertia below min_mass_property (the solver could not invert its body's).
void check_shape_mass(const ShapeGeometry& geometry, Real density, const std::string& what);

// Radius of the shape around its core (0 for segments, chains and sharp polygons).
Real shape_radius(const ShapeGeometry& geometry);

// Largest distance from `center` (body frame) to a point of the shape, radius included.
Real shape_extent(const ShapeGeometry& geometry, const Vec2& center);

// How thin the shape is: half its smallest width, about (a polygon's distance from its
// centroid to the nearest face, a round shape's radius; 0 for segments). A step that moves a
// body by a good part of this could carry it through something: continuous collision's yardstick.
Real shape_min_extent(const ShapeGeometry& geometry);
// The size its broadphase margin follows, measured as Box2D v3 measures it: a circle's radius,
// half a capsule's or segment's length (plus the capsule's radius), a polygon's farthest
// vertex from its centroid. Unlike its box, it does not grow as the shape turns.
Real broadphase_size(const ShapeGeometry& geometry);

// Two polygons without rounding: their contact is collided as two hulls (collide_hulls).
inline bool sharp_polygon_pair(const Shape& a, const Shape& b) {
  return a.type == ShapeType::polygon && b.type == ShapeType::polygon &&
         shape_radius(a.geometry) == 0 && shape_radius(b.geometry) == 0;
}

}  // namespace mink::detail
