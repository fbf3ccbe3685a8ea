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

// A contact's accumulated impulses per manifold point, in the solver's precision (they come
// from its lanes and go back to them, so nothing is lost). Kept beside the contact records
// (WorldState::contact_impulses, same index) rather than in them: the solver stores them for
// every constraint at the end of each step, and sixteen bytes in a compact array are much
// cheaper to write than a line of a record scattered over a large one.
struct ContactImpulses {
  SolverReal normal[2] = {0, 0};
  SolverReal tangent[2] = {0, 0};
};

// A pair of shapes whose boxes overlap and that may touch. Ordered by use: what the
// narrowphase's seed for the solver reads fills the first two cache lines, the manifold cache
// (collide only) comes last.
struct alignas(64) Contact {
  Manifold manifold;
  // The mixed materials in the solver's precision, which is where they go.
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

// The seed (contact_solver.hpp) of a contact with manifold points and its impulses, its
// bodies' centres of mass where they are now.
inline ContactSeed contact_seed(const Contact& c, const ContactImpulses& impulses,
                                const Vec2& center_a, const Vec2& center_b) {
  ContactSeed s;
  s.nx = static_cast<SolverReal>(c.manifold.normal.x());
  s.ny = static_cast<SolverReal>(c.manifold.normal.y());
  s.dx = static_cast<SolverReal>(center_a.x() - center_b.x());
  s.dy = static_cast<SolverReal>(center_a.y() - center_b.y());
  s.friction = c.friction;
  s.restitution = c.restitution;
  for (int j = 0; j < 2; ++j) {
    ContactSeed::Point& p = s.points[j];
    if (j >= c.manifold.point_count) {
      p = {};
      continue;
    }
    const ManifoldPoint& mp = c.manifold.points[static_cast<std::size_t>(j)];
    p.ax = static_cast<SolverReal>(mp.point.x() - center_a.x());
    p.ay = static_cast<SolverReal>(mp.point.y() - center_a.y());
    p.separation = static_cast<SolverReal>(mp.separation);
    p.normal_impulse = impulses.normal[j];
    p.tangent_impulse = impulses.tangent[j];
  }
  return s;
}

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
