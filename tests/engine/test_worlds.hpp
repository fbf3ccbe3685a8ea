#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mink/byte_stream.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace mink::test {

// FNV-1a over the bit patterns of every body's position, angle and velocities.
inline std::uint64_t state_hash(const World& world) {
  std::uint64_t hash = 1469598103934665603ull;
  const auto mix = [&](Real value) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xff;
      hash *= 1099511628211ull;
    }
  };
  for (const BodyId id : world.bodies()) {
    mix(world.position(id).x());
    mix(world.position(id).y());
    mix(world.angle(id));
    mix(world.linear_velocity(id).x());
    mix(world.linear_velocity(id).y());
    mix(world.angular_velocity(id));
  }
  return hash;
}

// A long run's step count: `sanitized_steps` under the sanitizers, whose slowdown would make
// the full run take minutes.
inline constexpr int long_run(int steps, int sanitized_steps) {
#ifdef MINK_SANITIZED_BUILD
  static_cast<void>(steps);
  return sanitized_steps;
#else
  static_cast<void>(sanitized_steps);
  return steps;
#endif
}

// Whether the built-in is one of Box2D v3's benchmark scenes (they have tests of their own).
inline bool is_benchmark_scene(std::string_view name) {
  const auto suite = benchmark_suite();
  return std::any_of(suite.begin(), suite.end(),
                     [&](const BenchmarkScene& scene) { return scene.name == name; });
}

// A dynamic body and where it was when listed.
struct Start {
  BodyId id;
  Vec2 position;
};

// Every dynamic body of the world (slot order) where it is now.
inline std::vector<Start> dynamic_bodies(const World& world) {
  std::vector<Start> starts;
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic) starts.push_back({id, world.position(id)});
  }
  return starts;
}

// Default settings with sleeping off, so nothing stops moving under a test's feet.
// The magnitude of WorldDef's default gravity, (0, -10).
inline constexpr Real kGravity = 10;

// Sleep off, so bodies at rest keep being solved; without gravity when asked.
inline WorldDef free_world(bool gravity = true) {
  WorldDef def;
  def.enable_sleep = false;
  if (!gravity) def.gravity = Vec2(0, 0);
  return def;
}

// A dynamic body with one shape.
inline BodyId add_body(World& world, const Vec2& position, const ShapeDef& shape) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  const BodyId body = world.create_body(def);
  world.create_shape(body, shape);
  return body;
}

inline BodyId add_ball(World& world, const Vec2& position, Real radius, Real density = 1) {
  ShapeDef shape = ShapeDef::circle(radius);
  shape.density = density;
  return add_body(world, position, shape);
}

// A static ground box whose top face is y = 0.
inline BodyId add_ground(World& world, Real half_width = 50, Real friction = 0.6) {
  const BodyId ground = world.create_body({});
  ShapeDef shape = ShapeDef::box(half_width, 1, Vec2(0, -1));
  shape.friction = friction;
  world.create_shape(ground, shape);
  return ground;
}

inline BodyId add_box(World& world, const Vec2& position, Real half = 0.5, Real angle = 0,
                      Real friction = 0.6, Real restitution = 0, Real density = 1) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  def.angle = angle;
  const BodyId body = world.create_body(def);
  ShapeDef shape = ShapeDef::box(half, half);
  shape.friction = friction;
  shape.restitution = restitution;
  shape.density = density;
  world.create_shape(body, shape);
  return body;
}

inline bool finite_state(const World& world, BodyId id) {
  const Vec2 p = world.position(id), v = world.linear_velocity(id);
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(world.angle(id)) &&
         std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(world.angular_velocity(id));
}

inline bool all_finite(const World& world) {
  for (const BodyId id : world.bodies()) {
    if (!finite_state(world, id)) return false;
  }
  return true;
}

// The message of the `Expected` error `f` throws, or "no error".
template <typename Expected = Error, typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Expected& e) {
    return e.what();
  }
  return "no error";
}

// A pyramid of `base` boxes, sleeping off, built twice: as is and with `change` applied to
// its world settings; both stepped `steps` times side by side.
template <typename Change>
std::pair<World, World> stepped_twins(int base, int steps, Change&& change) {
  SceneDef scene = pyramid_scene(base);
  scene.world.enable_sleep = false;
  World first = build_world(scene);
  change(scene.world);
  World second = build_world(scene);
  for (int i = 0; i < steps; ++i) {
    first.step();
    second.step();
  }
  return {std::move(first), std::move(second)};
}

// Snapshot bytes with their header's size and checksum made to fit the state after it (36
// bytes of header: magic, format version, fingerprint, size at byte 20, checksum at byte 28).
inline std::vector<std::uint8_t> resealed(std::vector<std::uint8_t> bytes) {
  const std::uint64_t size = bytes.size() - 36;
  std::memcpy(bytes.data() + 20, &size, sizeof size);
  const std::uint64_t checksum = hash_bytes(std::span<const std::uint8_t>(bytes).subspan(36));
  std::memcpy(bytes.data() + 28, &checksum, sizeof checksum);
  return bytes;
}

}  // namespace mink::test
