// Queries and debug drawing: broadphase candidates, then exact tests against the hulls.

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"

#include "mink/narrowphase/shape_cast.hpp"
#include "world_state.hpp"

namespace mink {

namespace {

// The box as narrowphase geometry in world coordinates (identity pose): a polygon, or a
// segment or point when it is flat, so exact overlap is one distance test for every kind.
ShapeGeometry box_geometry(const Aabb& box) {
  const Vec2 lo = box.lower, hi = box.upper;
  if (lo.x() < hi.x() && lo.y() < hi.y()) {
    const std::vector<Vec2> corners = {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
    return RoundedPolygon{PreparedHull(build_hull(corners, HullAlgorithm::monotone_chain)), 0};
  }
  if (lo == hi) return Circle{lo, 0};
  return Segment{lo, hi};
}

// The live shapes behind broadphase candidates (a destroyed shape's proxy lingers until the
// next step), with their slot and pose.
template <typename Visit>
void for_each_candidate(const WorldState& w, const std::vector<ProxyId>& proxies, Visit&& visit) {
  for (ProxyId proxy : proxies) {
    const auto index = static_cast<std::uint32_t>(w.broadphase.user_data(proxy));
    if (index >= w.shapes.size()) continue;
    const detail::Shape& s = w.shapes[index];
    if (!s.alive || s.proxy != proxy) continue;
    visit(index, s.geometry, w.bodies[s.body].pose());
  }
}

std::vector<ShapeId> sorted_by_slot(std::vector<ShapeId> found) {
  std::sort(found.begin(), found.end(),
            [](const ShapeId& a, const ShapeId& b) { return a.index < b.index; });
  return found;
}

}  // namespace

std::vector<ShapeId> World::query_aabb(const Aabb& box) const {
  if (!(box.lower.allFinite() && box.upper.allFinite() && box.lower.x() <= box.upper.x() &&
        box.lower.y() <= box.upper.y())) {
    throw InvalidArgumentError("query_aabb: the box must be finite with lower <= upper");
  }
  const WorldState& w = *state_;
  const ShapeGeometry probe = box_geometry(box);
  std::vector<ProxyId> proxies;
  w.broadphase.query(box, proxies);
  std::vector<ShapeId> found;
  for_each_candidate(w, proxies,
                     [&](std::uint32_t index, const ShapeGeometry& geometry, const Pose& pose) {
                       if (shape_distance(probe, Pose{}, geometry, pose).overlap) {
                         found.push_back(w.shape_id(index));
                       }
                     });
  return sorted_by_slot(std::move(found));
}

std::vector<ShapeId> World::query_point(const Vec2& point) const {
  const WorldState& w = *state_;
  std::vector<ProxyId> proxies;
  w.broadphase.query_point(point, proxies);
  std::vector<ShapeId> found;
  for_each_candidate(w, proxies,
                     [&](std::uint32_t index, const ShapeGeometry& geometry, const Pose& pose) {
                       if (contains_point(geometry, pose, point))
                         found.push_back(w.shape_id(index));
                     });
  return sorted_by_slot(std::move(found));
}

std::optional<ShapeRayHit> World::ray_cast(const Vec2& origin, const Vec2& translation) const {
  const WorldState& w = *state_;
  const Vec2 end = origin + translation;
  const Aabb box{origin.cwiseMin(end), origin.cwiseMax(end)};
  std::vector<ProxyId> proxies;
  w.broadphase.query(box, proxies);
  std::optional<ShapeRayHit> best;
  for_each_candidate(
      w, proxies, [&](std::uint32_t index, const ShapeGeometry& geometry, const Pose& pose) {
        const auto hit = mink::ray_cast(geometry, pose, origin, translation);
        // Ties go to the lower slot so the answer does not depend on broadphase order.
        if (hit && (!best || hit->fraction < best->hit.fraction ||
                    (hit->fraction == best->hit.fraction && index < best->shape.index))) {
          best = ShapeRayHit{w.shape_id(index), *hit};
        }
      });
  return best;
}

std::optional<ShapeCastHit> World::cast_shape(const ShapeDef& def, const Pose& pose,
                                              const Vec2& translation, const Filter& filter) const {
  const WorldState& w = *state_;
  if (!(pose.position.allFinite() && std::isfinite(pose.rotation.cos) &&
        std::isfinite(pose.rotation.sin) && translation.allFinite())) {
    throw InvalidArgumentError("cast_shape: the pose and translation must be finite");
  }
  const ShapeGeometry geometry = detail::make_geometry(def);
  const Pose end{pose.position + translation, pose.rotation};
  const Aabb start_box = compute_aabb(geometry, pose), end_box = compute_aabb(geometry, end);
  const Aabb box = start_box.merged(end_box);
  std::vector<ProxyId> proxies;
  w.broadphase.query(box, proxies);
  std::optional<ShapeCastHit> best;
  for_each_candidate(
      w, proxies, [&](std::uint32_t index, const ShapeGeometry& other, const Pose& other_pose) {
        const detail::Shape& s = w.shapes[index];
        if (s.sensor || !should_collide(filter, s.filter)) return;
        ShapeCastInput input;
        input.shape = &geometry;
        input.pose = pose;
        input.translation = translation;
        input.obstacle = &other;
        input.obstacle_pose = other_pose;
        input.max_fraction = best ? best->fraction : 1;
        input.target = slop_target(geometry, other, w.def.linear_slop);
        input.tolerance = 0.25 * w.def.linear_slop;
        const ShapeCastOutput out = shape_cast(input);
        if (out.state == ToiState::separated) return;
        // Ties go to the lower slot so the answer does not depend on broadphase order.
        if (!best || out.fraction < best->fraction ||
            (out.fraction == best->fraction && index < best->shape.index)) {
          best = ShapeCastHit{w.shape_id(index), out.fraction, out.point, out.normal};
        }
      });
  return best;
}

void World::draw(DebugDraw& draw) const {
  const WorldState& w = *state_;
  const Color static_color{0.5f, 0.9f, 0.5f, 1}, kinematic_color{0.5f, 0.5f, 0.9f, 1},
      dynamic_color{0.9f, 0.7f, 0.7f, 1}, sleeping_color{0.6f, 0.6f, 0.6f, 1},
      aabb_color{0.9f, 0.3f, 0.9f, 1}, point_color{1, 0.2f, 0.2f, 1},
      normal_color{0.9f, 0.9f, 0.3f, 1}, pair_color{0.3f, 0.9f, 0.9f, 1},
      velocity_color{1, 1, 1, 1};
  const Color sensor_color{0.9f, 0.9f, 0.3f, 0.25f};
  std::vector<Vec2> polygon;
  if (draw.layers & draw_shapes) {
    for (const detail::Shape& s : w.shapes) {
      if (!s.alive) continue;
      const detail::Body& b = w.bodies[s.body];
      const Pose pose = b.pose();
      Color color = b.type == BodyType::static_body ? static_color
                    : b.type == BodyType::kinematic ? kinematic_color
                                                    : dynamic_color;
      if ((draw.layers & draw_sleep_state) && b.type == BodyType::dynamic && !b.awake) {
        color = sleeping_color;
      }
      if (s.sensor) color = sensor_color;
      const Color outline{color.r * 0.6f, color.g * 0.6f, color.b * 0.6f, 1};
      std::visit(
          [&](const auto& g) {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, Circle>) {
              draw.draw_solid_circle(pose.apply(g.center), g.radius, b.rotation.angle(), color,
                                     outline);
            } else if constexpr (std::is_same_v<G, Capsule>) {
              draw.draw_solid_capsule(pose.apply(g.center1), pose.apply(g.center2), g.radius, color,
                                      outline);
            } else if constexpr (std::is_same_v<G, Segment>) {
              draw.draw_segment(pose.apply(g.point1), pose.apply(g.point2), outline);
            } else if constexpr (std::is_same_v<G, ChainSegment>) {
              draw.draw_segment(pose.apply(g.segment.point1), pose.apply(g.segment.point2),
                                outline);
            } else {
              polygon.clear();
              for (const Vec2& v : g.hull.vertices()) polygon.push_back(pose.apply(v));
              draw.draw_rounded_polygon(polygon, g.radius, color, outline);
            }
          },
          s.geometry);
    }
  }
  if (draw.layers & draw_aabbs) {
    for (const detail::Shape& s : w.shapes) {
      if (!s.alive) continue;
      if (s.proxy == null_proxy) continue;  // a disabled body's shape
      const Aabb& box = w.broadphase.fat_aabb(s.proxy);
      const Vec2 corners[4] = {box.lower, Vec2(box.upper.x(), box.lower.y()), box.upper,
                               Vec2(box.lower.x(), box.upper.y())};
      draw.draw_polygon(corners, Color{0, 0, 0, 0}, aabb_color);
    }
  }
  if (draw.layers & draw_broadphase_pairs) {
    for (const ProxyPair& pair : w.broadphase.pairs()) {
      const Aabb& a = w.broadphase.fat_aabb(pair.a);
      const Aabb& b = w.broadphase.fat_aabb(pair.b);
      draw.draw_segment((a.lower + a.upper) / 2, (b.lower + b.upper) / 2, pair_color);
    }
  }
  if (draw.layers & (draw_contact_points | draw_contact_normals)) {
    for (const detail::Contact& c : w.contacts) {
      for (int j = 0; j < c.manifold.point_count; ++j) {
        const Vec2& p = c.manifold.points[static_cast<std::size_t>(j)].point;
        if (draw.layers & draw_contact_points) draw.draw_point(p, 4, point_color);
        if (draw.layers & draw_contact_normals) {
          draw.draw_segment(p, p + 0.3 * c.manifold.normal, normal_color);
        }
      }
    }
  }
  for (const detail::Body& b : w.bodies) {
    if (!b.alive || b.type == BodyType::static_body) continue;
    if (draw.layers & draw_velocities) {
      draw.draw_segment(b.center, b.center + w.def.time_step * 10 * b.velocity, velocity_color);
    }
    if (draw.layers & draw_centers_of_mass) draw.draw_point(b.center, 3, velocity_color);
  }
  if (draw.layers & draw_joints) {
    for (const detail::Joint& j : w.joints) {
      if (!j.alive) continue;
      const detail::JointBodyState a = w.joint_body_state(j.body[0]);
      const detail::JointBodyState b = w.joint_body_state(j.body[1]);
      std::visit([&](const auto& k) { detail::draw(k, a, b, draw); }, j.kind);
    }
  }
}

}  // namespace mink
