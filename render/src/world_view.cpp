#include "mink/render/world_view.hpp"

#include <algorithm>

namespace mink {

void world_bounds(const World& world, Vec2& lower, Vec2& upper) {
  lower = Vec2(1e300, 1e300);
  upper = Vec2(-1e300, -1e300);
  for (BodyId body : world.bodies()) {
    const bool spinning =
        world.body_type(body) == BodyType::kinematic && world.angular_velocity(body) != 0;
    const Pose pose = world.pose(body);
    for (ShapeId shape : world.body_shapes(body)) {
      if (spinning) {
        Real radius = 0;
        for (const Vec2& v : world.shape_hull(shape).vertices()) {
          radius = std::max(radius, v.norm());
        }
        lower = lower.cwiseMin(pose.position - Vec2(radius, radius));
        upper = upper.cwiseMax(pose.position + Vec2(radius, radius));
      } else {
        const Aabb box = world.shape_aabb(shape);
        lower = lower.cwiseMin(box.lower);
        upper = upper.cwiseMax(box.upper);
      }
    }
  }
  if (lower.x() > upper.x()) {
    lower = Vec2(-10, -10);
    upper = Vec2(10, 10);
  }
}

void draw_world_frame(Renderer& renderer, const World& world, std::string_view overlay,
                      std::uint32_t layers) {
  renderer.begin_frame(Color{0.11f, 0.12f, 0.15f, 1});
  renderer.layers = layers;
  world.draw(renderer);
  if (!overlay.empty()) renderer.draw_overlay(overlay);
  renderer.end_frame();
}

}  // namespace mink
