#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "contact_solver.hpp"
#include "mink/broadphase/broadphase.hpp"
#include "mink/narrowphase/manifold.hpp"

namespace mink::detail {

// Where a manifold was computed, so it can be carried along while the pair barely moves: the
// pose of B in A's frame, the normal in A's frame, each point's surface points in their own
// body's frame.
struct ManifoldCache {
  Pose relative;
  Vec2 normal{0, 0};
  Vec2 on_a[2] = {Vec2(0, 0), Vec2(0, 0)};
  Vec2 on_b[2] = {Vec2(0, 0), Vec2(0, 0)};
  bool valid = false;
};

// A pair of shapes whose boxes overlap and that may touch. Ordered by use: what building
// constraints reads fills the first two cache lines, the manifold cache (collide only) comes
// last. The set-up reads a contact record for each of its constraints, scattered, so every
// line it needs less is one fewer miss.
struct alignas(64) Contact {
  Manifold manifold;
  // The accumulated impulses and the mixed materials in the solver's precision: the impulses
  // come from its lanes and go back to them, the materials go to them, so nothing is lost.
  SolverReal normal_impulse[2] = {0, 0};
  SolverReal tangent_impulse[2] = {0, 0};
  SolverReal friction = 0, restitution = 0;
  std::uint32_t body_a = 0, body_b = 0;
  // Fastest normal approach over the points before the solve, and where (hit events only).
  Real approach_speed = 0;
  bool hit_events = false;  // either shape asks for hit events
  bool touching = false;
  bool events = true;           // begin/end events (both shapes allow them)
  bool sharp_polygons = false;  // both are polygons without rounding: the direct hull path
  std::uint32_t shape_a = 0, shape_b = 0;
  ProxyId proxy_a = null_proxy, proxy_b = null_proxy;
  // The constraint graph colour while the contact has points.
  std::uint8_t color = 255;
  // Whether each body is static or kinematic (fixed for the solver; it blocks no colour). Set
  // when the contact is made: a body's type change remakes its contacts.
  bool a_fixed = false, b_fixed = false;
  // The last manifold update kept the features (only measured again): the next likely does
  // too, and reads none of the shapes' arrays, which the narrowphase then does not ask for.
  bool features_kept = false;
  Vec2 approach_point{0, 0};
  ManifoldCache cache;
};
// What the solver's set-up reads of a contact: its first two cache lines.
inline constexpr std::size_t kContactSetupBytes = 128;
static_assert(offsetof(Contact, body_b) + sizeof(std::uint32_t) <= kContactSetupBytes);

inline std::uint64_t pair_key(ProxyId a, ProxyId b) {
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

// Mixing rules as in Box2D: geometric mean of friction, the larger restitution.
inline Real mix_friction(Real a, Real b) {
  return std::sqrt(a * b);
}
inline Real mix_restitution(Real a, Real b) {
  return a > b ? a : b;
}

}  // namespace mink::detail
