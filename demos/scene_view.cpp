#include "scene_view.hpp"

#include <cmath>

#include "mink/error.hpp"

namespace mink::cli {

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
