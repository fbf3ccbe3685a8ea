#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "mink/broadphase/aabb.hpp"
#include "mink/engine/body_def.hpp"
#include "mink/engine/contact_events.hpp"
#include "mink/engine/debug_draw.hpp"
#include "mink/engine/ids.hpp"
#include "mink/engine/ray_cast.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/engine/world_def.hpp"
#include "mink/narrowphase/pose.hpp"

namespace mink {

struct WorldState;

struct ShapeRayHit {
  ShapeId shape;
  RayHit hit;
};

struct AdvanceResult {
  int steps = 0;   // fixed steps run by this call
  Real alpha = 0;  // leftover time / time step, in [0, 1): blend previous and current poses
};

// A 2D rigid-body world: bodies with convex shapes, a sweep-and-prune broadphase, GJK-based
// manifolds and a soft-step contact solver. Single threaded; every call is deterministic.
// Any id argument that does not name a live object throws StaleIdError naming the id.
class World {
 public:
  // Throws InvalidArgumentError naming the first bad field.
  explicit World(const WorldDef& def = {});
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  const WorldDef& def() const noexcept;
  void set_gravity(const Vec2& gravity);
  void enable_sleep(bool enabled);

  // Bodies and shapes. Destruction is allowed at any time between steps: contacts of the
  // destroyed shapes end (with end events when they touched) and their neighbours wake.
  BodyId create_body(const BodyDef& def);
  void destroy_body(BodyId id);
  ShapeId create_shape(BodyId body, const ShapeDef& def);
  void destroy_shape(ShapeId id);
  bool is_valid(BodyId id) const noexcept;
  bool is_valid(ShapeId id) const noexcept;
  std::size_t body_count() const noexcept;
  std::size_t shape_count() const noexcept;
  std::vector<BodyId> bodies() const;  // live bodies in slot order

  // Body state. Position is the body origin; the centre of mass is world_center.
  BodyType body_type(BodyId id) const;
  Vec2 position(BodyId id) const;
  Real angle(BodyId id) const;
  Pose pose(BodyId id) const;
  Vec2 world_center(BodyId id) const;
  Vec2 local_center(BodyId id) const;
  Vec2 linear_velocity(BodyId id) const;
  Real angular_velocity(BodyId id) const;
  Real mass(BodyId id) const;
  Real rotational_inertia(BodyId id) const;  // about the centre of mass
  Real linear_damping(BodyId id) const;
  Real angular_damping(BodyId id) const;
  Real gravity_scale(BodyId id) const;
  bool allow_sleep(BodyId id) const;
  bool is_awake(BodyId id) const;
  std::uint64_t user_data(BodyId id) const;
  std::vector<ShapeId> body_shapes(BodyId id) const;

  // Setters wake the body. set_transform moves it without velocity (a teleport).
  void set_transform(BodyId id, const Vec2& position, Real angle);
  void set_linear_velocity(BodyId id, const Vec2& velocity);
  void set_angular_velocity(BodyId id, Real velocity);
  void apply_force(BodyId id, const Vec2& force, const Vec2& world_point);  // until next step
  void apply_torque(BodyId id, Real torque);
  void apply_linear_impulse(BodyId id, const Vec2& impulse, const Vec2& world_point);
  void set_awake(BodyId id, bool awake);

  // Shapes. The hull is in body-local coordinates.
  BodyId shape_body(ShapeId id) const;
  const ConvexHull& shape_hull(ShapeId id) const;
  Real shape_density(ShapeId id) const;
  Real shape_friction(ShapeId id) const;
  Real shape_restitution(ShapeId id) const;
  HullAlgorithm shape_algorithm(ShapeId id) const;
  Aabb shape_aabb(ShapeId id) const;  // tight, at the current pose

  // Time stepping.
  void step();  // exactly one fixed step
  // Runs the whole steps that fit in the accumulated time (at most max_steps_per_advance).
  // Events then cover every step the call ran.
  AdvanceResult advance(Real frame_seconds);
  Real time() const noexcept;
  std::uint64_t step_count() const noexcept;

  // What the last step (or advance) saw.
  std::span<const ContactBeginEvent> contact_begin_events() const noexcept;
  std::span<const ContactEndEvent> contact_end_events() const noexcept;
  const StepCounters& counters() const noexcept;
  const StepProfile& profile() const noexcept;

  // Queries against the current poses, exact (not just the broadphase boxes). Shapes come in
  // slot order.
  std::vector<ShapeId> query_aabb(const Aabb& box) const;
  std::vector<ShapeId> query_point(const Vec2& point) const;
  // Closest hit along origin -> origin + translation, if any.
  std::optional<ShapeRayHit> ray_cast(const Vec2& origin, const Vec2& translation) const;

  void draw(DebugDraw& draw) const;

 private:
  void run_step(bool clear_events);
  std::unique_ptr<WorldState> state_;
};

}  // namespace mink
