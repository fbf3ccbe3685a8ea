#pragma once

#include "mink/engine/task_system.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

/// The largest magnitude a world setting (gravity per component, rates, speeds, lengths, the
/// time step) or a body's gravity scale may have, and 1 / it the shortest time step: the solver
/// works in single precision and multiplies and squares these, so larger ones would overflow
/// it and turn the world NaN within a step (gravity of 1e175 m/s^2 did).
inline constexpr Real max_setting_magnitude = 1e9;

/// The most substeps a step, and joint passes a substep, may take: each costs solver memory
/// and time per constraint, and a step of 10^8 substeps asked for gigabytes.
inline constexpr int max_substeps = 1000;
inline constexpr int max_joint_iterations = 1000;

/// World settings. Defaults follow Box2D v3 where it has an equivalent (units: metres,
/// kilograms, seconds).
struct WorldDef {
  Vec2 gravity{0, -10};         ///< m/s^2, world frame
  Real time_step = 1.0 / 60.0;  ///< one fixed step; advance() runs whole steps only
  int substeps = 5;             ///< soft-step substeps per step
  /// @name Contact softness
  /// Contact softness: stiffness (cycles per second, capped at a quarter of the substep rate)
  /// and damping ratio of the soft contact spring. A soft contact under load F sags by
  /// F / (m (2 pi hertz)^2): Box2D v3's 30 Hz lets a 100-row pyramid sink by about a metre,
  /// 60 Hz by a quarter of that. Stiff springs need short substeps to stay stable (60 Hz
  /// with 4 substeps sways), hence 5 substeps rather than Box2D v3's 4 (6 is steadier
  /// still, at 20% more solver time).
  /// @{
  Real contact_hertz = 60;          ///< spring stiffness, cycles per second
  Real contact_damping_ratio = 10;  ///< spring damping ratio (1: critical)
  /// @}
  /// @name Joint softness
  /// How rigid joint rows push out their position error: stiffness (capped at a quarter of
  /// the substep rate, like contacts) and damping ratio. Joint springs and soft welds use
  /// their own settings.
  /// @{
  Real joint_hertz = 60;         ///< cycles per second
  Real joint_damping_ratio = 2;  ///< 1: critical
  /// Joint passes per substep in the biased solve (contacts get one).
  int joint_iterations = 1;
  /// Solve chains of revolute joints (each body in at most two) as one exact linear system
  /// instead of one joint at a time, so heavy bodies on light chains do not stretch them.
  /// false: one at a time, as Box2D (the slow twin of the mass-ratio tests).
  bool direct_joint_chains = true;
  /// @}
  /// Sweep fast bodies over each step and stop them at their first touch (continuous
  /// collision): against static and kinematic shapes, bullets against everything, and fast
  /// bodies against each other. false: speculative contacts only.
  bool enable_continuous = true;
  /// Sweep fast bodies against each other too, not only bullets (Box2D v3 and Rapier sweep
  /// non-bullets against static and kinematic shapes only: false matches them).
  bool continuous_fast_pairs = true;
  /// Keep the speculative margin on a fast body's broadphase boxes, so it meets other bodies'
  /// speculative contacts as a slow body does. false: as Box2D v3, a body also counts as fast
  /// when its velocity at the step's end would carry it past its continuous_threshold, and
  /// after a sweep that stops it nowhere its boxes are bare: fewer pairs (Box2D v3's contact
  /// counts), later contacts between fast bodies and others.
  bool fast_body_margin = true;
  /// Fastest speed at which overlap is pushed apart, so deep overlap resolves without popping.
  Real contact_push_max_velocity = 3;
  /// Approach speeds below this do not bounce, whatever the restitution.
  Real restitution_threshold = 1;
  /// Contacts that close faster than this (m/s) report a hit event, when a shape asks for them.
  Real hit_event_threshold = 1;
  /// Allowed overlap; contacts are generated this many times four before shapes touch.
  Real linear_slop = 0.005;
  Real max_linear_speed = 400;           ///< m/s; faster bodies are clamped to it
  bool enable_sleep = true;              ///< let resting bodies sleep (see World::enable_sleep)
  Real time_to_sleep = 0.5;              ///< seconds a body must rest before it may sleep
  Real linear_sleep_tolerance = 0.05;    ///< m/s
  Real angular_sleep_tolerance = 0.035;  ///< rad/s (about 2 degrees per second)
  /// advance() runs at most this many steps per call, dropping the rest of a long frame so a
  /// slow frame cannot snowball into ever slower ones.
  int max_steps_per_advance = 8;
  /// Solve independent contacts eight at a time in SIMD lanes. false runs the same order one
  /// contact at a time (the slow twin; results are bitwise equal).
  bool simd_solver = true;
  /// Keep a contact's manifold features while the pair's relative pose stays within
  /// manifold_reuse_distance of where they were found, updating only the separations. false
  /// runs the narrowphase for every pair every step.
  bool reuse_manifolds = true;
  /// How far (m: the shift of one body relative to the other plus the turn at their extents)
  /// a touching pair may move before its manifold is computed anew; a pair not yet touching
  /// gets at most four linear slops (its contact must not be missed). Box2D v3 recycles its
  /// contacts to the same distance, ten linear slops. Stored points move with their bodies, so
  /// the separations stay exact; what the distance trades is which features touch: a box
  /// sliding off an edge finds its new corner this much later.
  Real manifold_reuse_distance = 0.05;
  /// @name Threads
  /// A step runs its parallel phases (narrowphase, constraint preparation, each colour of the
  /// solver, integration, bounding boxes) on this many workers, the calling thread among them.
  /// The state after a step is bitwise the same at any worker count.
  /// @{
  int worker_count = 1;    ///< 1..256; 1 runs everything on the calling thread
  TaskSystem task_system;  ///< null callbacks: the world's own pool of worker_count - 1 threads
  /// @}
};

}  // namespace mink
