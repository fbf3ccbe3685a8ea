#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "contact_solver.hpp"
#include "mink/broadphase/sweep_and_prune.hpp"
#include "mink/engine/contact_events.hpp"
#include "mink/engine/world.hpp"
#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

namespace detail {

// What every step reads sits in the first two cache lines (pose, velocities, inverse masses,
// flags); the rest is touched by the API and the sleep pass only.
struct alignas(64) Body {
  // Pose: centre of mass and rotation are the state; the origin follows from them.
  Vec2 center{0, 0};
  Rotation rotation{};
  Vec2 origin{0, 0};
  Vec2 velocity{0, 0};
  Real angular_velocity = 0;
  Real inv_mass = 0, inv_inertia = 0;
  Real extent = 0;  // farthest shape vertex from the centre of mass
  BodyType type = BodyType::static_body;
  bool alive = false;
  bool awake = true;
  bool allow_sleep = true;

  Vec2 local_center{0, 0};
  Vec2 force{0, 0};
  Real torque = 0;
  Real mass = 0, inertia = 0;
  Real linear_damping = 0, angular_damping = 0, gravity_scale = 1;
  Real sleep_time = 0;
  std::uint64_t user_data = 0;
  std::vector<std::uint32_t> shapes;
  std::uint32_t generation = 0;

  Pose pose() const { return {origin, rotation}; }
};

struct Shape {
  std::optional<PreparedHull> hull;
  Aabb aabb;  // tight box at the current pose, grown by the speculative margin and the sweep
  Real density = 1, friction = 0.6, restitution = 0;
  HullAlgorithm algorithm = HullAlgorithm::chan;
  ProxyId proxy = null_proxy;
  std::uint32_t body = 0;
  std::uint32_t generation = 0;
  bool alive = false;
};

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

// Ordered by use: what building constraints reads comes first, the manifold cache (collide
// only) last.
struct Contact {
  Manifold manifold;
  std::uint32_t body_a = 0, body_b = 0;
  Real normal_impulse[2] = {0, 0};
  Real tangent_impulse[2] = {0, 0};
  Real friction = 0, restitution = 0;
  std::uint32_t shape_a = 0, shape_b = 0;
  ProxyId proxy_a = null_proxy, proxy_b = null_proxy;
  bool touching = false;
  ManifoldCache cache;
};

inline std::uint64_t pair_key(ProxyId a, ProxyId b) {
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

}  // namespace detail

struct WorldState {
  WorldDef def;
  std::vector<detail::Body> bodies;
  std::vector<std::uint32_t> free_bodies;
  std::vector<detail::Shape> shapes;
  std::vector<std::uint32_t> free_shapes;
  std::size_t live_bodies = 0, live_shapes = 0;

  SweepAndPrune broadphase;
  PairEvents pair_events;
  // Proxies of destroyed shapes are released at the start of the next step, before the pair
  // update, so a proxy id is never reused within one pair-update cycle.
  std::vector<ProxyId> pending_proxy_destroys;

  std::vector<detail::Contact> contacts;
  std::unordered_map<std::uint64_t, std::uint32_t> contact_index;

  std::vector<ContactBeginEvent> begin_events;
  std::vector<ContactEndEvent> end_events;
  StepCounters counters;
  StepProfile profile;

  Real time = 0;
  Real accumulator = 0;
  std::uint64_t step_count = 0;

  // Step scratch, kept to avoid allocating every step.
  std::vector<detail::SolverBody> solver_bodies;
  std::vector<detail::SolverBodyParams> solver_params;
  std::vector<std::uint32_t> solver_to_body;
  std::vector<std::int32_t> body_solver_index;
  std::vector<detail::SolverBodyInfo> solver_info;
  std::vector<std::uint32_t> constraint_contacts, sorted_contacts, sort_count;
  std::vector<detail::ConstraintBodies> constraint_bodies, sorted_bodies;
  detail::ContactSolver contact_solver;
  std::vector<std::uint32_t> island_parent;
  std::vector<Real> island_min_sleep;

  detail::Body& body(BodyId id);
  const detail::Body& body(BodyId id) const;
  detail::Shape& shape(ShapeId id);
  const detail::Shape& shape(ShapeId id) const;
  ShapeId shape_id(std::uint32_t index) const { return {index, shapes[index].generation}; }

  void wake(detail::Body& body);
  void update_mass(detail::Body& body);
  void update_shape_aabb(detail::Shape& shape, const detail::Body& body, Real dt);
  void destroy_contact(std::uint32_t index);
  void destroy_shape_contacts(std::uint32_t shape_index);

  void update_pairs();
  void collide();
  void update_islands();
  void prepare_contacts();
  void solve();
  void finish_step();
};

}  // namespace mink
