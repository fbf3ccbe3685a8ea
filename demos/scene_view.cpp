#include "scene_view.hpp"

#include <algorithm>
#include <cmath>

#include "mink/error.hpp"

namespace mink::cli {

void scene_bounds(const World& world, Vec2& lower, Vec2& upper) {
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

Real kinetic_energy(const World& world) {
  Real energy = 0;
  for (BodyId body : world.bodies()) {
    if (world.body_type(body) != BodyType::dynamic) continue;
    const Real w = world.angular_velocity(body);
    // The world keeps the centre of mass's velocity (a BodyDef gives the origin's).
    const Vec2 v = world.linear_velocity(body);
    energy +=
        0.5 * world.mass(body) * v.squaredNorm() + 0.5 * world.rotational_inertia(body) * w * w;
  }
  return energy;
}

void draw_world_frame(Renderer& renderer, const World& world, const std::string& overlay) {
  renderer.begin_frame(Color{0.11f, 0.12f, 0.15f, 1});
  renderer.layers = draw_shapes | draw_contact_points | draw_sleep_state;
  world.draw(renderer);
  renderer.draw_overlay(overlay);
  renderer.end_frame();
}

void parse_frame_size(const std::string& text, int& width, int& height,
                      const FrameSizeRules& rules) {
  const std::size_t x = text.find('x');
  std::size_t used_w = 0;
  std::size_t used_h = 0;
  try {
    if (x == std::string::npos) throw InvalidArgumentError("");
    width = std::stoi(text.substr(0, x), &used_w);
    height = std::stoi(text.substr(x + 1), &used_h);
  } catch (const std::exception&) {
    throw InvalidArgumentError("--size '" + text + "' is not WIDTHxHEIGHT, e.g. " +
                               std::string(rules.example));
  }
  const bool odd = width % 2 != 0 || height % 2 != 0;
  if (used_w != x || used_h != text.size() - x - 1 || width < 64 || height < 64 || width > 8192 ||
      height > 8192 || (rules.require_even && odd)) {
    throw InvalidArgumentError(
        "--size '" + text + "' must be WIDTHxHEIGHT" +
        (rules.require_even ? ", both even and in 64..8192" : " with both in 64..8192"));
  }
}

}  // namespace mink::cli
