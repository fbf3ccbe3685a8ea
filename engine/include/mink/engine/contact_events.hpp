#pragma once

#include <cstddef>
#include <cstdint>

#include "mink/engine/ids.hpp"
#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/pose.hpp"

namespace mink {

/// @brief Two shapes started touching during the last step (closer than the speculative distance).
struct ContactBeginEvent {
  ShapeId shape_a;    ///< one shape of the pair
  ShapeId shape_b;    ///< the other
  Manifold manifold;  ///< the contact when it began (normal from A to B, points, separations)
};

/// @brief Two shapes stopped touching, or one of them was destroyed while touching.
struct ContactEndEvent {
  ShapeId shape_a;  ///< one shape of the pair (may be stale when it was destroyed)
  ShapeId shape_b;  ///< the other
};

/// @brief Two shapes met faster than WorldDef::hit_event_threshold (either shape asked for hit
/// events).
struct ContactHitEvent {
  ShapeId shape_a;          ///< one shape of the pair
  ShapeId shape_b;          ///< the other
  Vec2 point{0, 0};         ///< where, world
  Vec2 normal{0, 0};        ///< unit, from A to B
  Real approach_speed = 0;  ///< normal closing speed before the step's solve, m/s, > 0
};

/// @brief A shape began overlapping a sensor.
struct SensorBeginEvent {
  ShapeId sensor;   ///< the sensor shape
  ShapeId visitor;  ///< the shape that entered it
};

/// @brief A shape stopped overlapping a sensor, or one of the two was destroyed.
struct SensorEndEvent {
  ShapeId sensor;   ///< the sensor shape (may be stale when it was destroyed)
  ShapeId visitor;  ///< the shape that left it (may be stale)
};

/// @brief A body moved during the last step: its new pose, for renderers and games that sync
/// only what changed.
struct BodyMoveEvent {
  BodyId body;                  ///< the body
  Pose pose;                    ///< of the body origin, world
  bool fell_asleep = false;     ///< it went to sleep at the end of this step
  std::uint64_t user_data = 0;  ///< the body's user data
};

/// @brief The solve diverged on a body during the last step, or on a body joined to it by
/// joints and contacts: it is put back where the step began, at rest, and the impulses of its
/// joints and contacts start again from zero. A solve diverges on constraints beyond the
/// solver's single precision (a joint anchor kilometres from a light body, masses and
/// inertias a billion times apart): a velocity or turn no number holds, a speed a thousand
/// times the limits (WorldDef::max_linear_speed, an eighth of a turn per substep), or an origin
/// beyond max_world_coordinate. The world stays finite, and the event says so.
struct BodyStoppedEvent {
  BodyId body;                  ///< the body
  bool diverged = false;        ///< its own solve diverged (else it was joined to one that did)
  std::uint64_t user_data = 0;  ///< the body's user data
};

/// @brief A joint's constraint force or torque exceeded its break threshold during the last
/// step (JointBase::break_force, break_torque); what to do is the caller's choice.
struct JointBreakEvent {
  JointId joint;                ///< the joint
  Vec2 force{0, 0};             ///< constraint force on body B, N, world frame
  Real torque = 0;              ///< constraint torque on body B, N m
  std::uint64_t user_data = 0;  ///< the joint's user data
};

/// @brief One contact of a body (World::body_contacts).
struct ContactData {
  ShapeId shape_a;    ///< one shape of the pair
  ShapeId shape_b;    ///< the other
  Manifold manifold;  ///< points, normal from A to B, separations
};

/// @brief What the last step did, for tools and tests.
struct StepCounters {
  std::size_t broadphase_pairs = 0;      ///< overlapping box pairs the broadphase reported
  std::size_t contacts = 0;              ///< pairs with a contact record
  std::size_t touching_contacts = 0;     ///< contacts with manifold points within touching distance
  std::size_t collided_contacts = 0;     ///< contacts the narrowphase visited (of moving bodies)
  std::size_t awake_bodies = 0;          ///< bodies simulated (not asleep)
  std::size_t islands = 0;               ///< awake islands
  std::size_t constraint_colors = 0;     ///< graph colours the solver used
  std::size_t overflow_constraints = 0;  ///< contacts solved one at a time (colours ran out)
  /// Of those, the contacts of stacks with bodies of very different masses (10:1 or more)
  /// that form a path (a column), their pushes solved as one system so that light bodies
  /// under heavy ones hold.
  std::size_t stacked_constraints = 0;
  std::size_t joints = 0;           ///< joints the solver ran (of moving bodies)
  std::size_t fast_bodies = 0;      ///< bodies swept by continuous collision
  std::size_t continuous_hits = 0;  ///< of those, stopped short at a first touch
};

/// @brief Wall time of each phase of the last step, in milliseconds (for tuning; never for tests).
struct StepProfile {
  /// broadphase pair update, narrowphase manifolds, sleep islands, contact preparation, the
  /// substepped solve, continuous collision, end-of-step bookkeeping
  double pairs = 0, collide = 0, islands = 0, prepare = 0, solve = 0, continuous = 0, finish = 0;
};

}  // namespace mink
