#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "mink/engine/body_def.hpp"
#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "world_grid.hpp"

namespace mink::detail {

// A body record, laid out by who reads it: each step's body passes (solver set-up, write-back,
// box update) find what they read in the first four cache lines, in the order they read it;
// what only the API and the sleep pass touch comes last.
struct alignas(64) Body {
  // Pose: centre of mass and rotation are the state; the origin follows from them.
  Vec2 center{0, 0};
  Rotation rotation{};
  Vec2 origin{0, 0};
  Vec2 velocity{0, 0};  // of the centre of mass
  Real angular_velocity = 0;
  Real inv_mass = 0, inv_inertia = 0;
  Real extent = 0;  // farthest shape point (radius included) from the centre of mass
  BodyType type = BodyType::static_body;
  bool alive = false;
  bool awake = true;
  bool allow_sleep = true;
  bool enabled = true;
  bool fixed_rotation = false;
  bool bullet = false;
  bool mass_override = false;  // set_mass_data's values stand until the shapes change
  Real min_extent = 0;         // thinnest shape's half-width: continuous collision's yardstick
  Real continuous_threshold = 0.5;
  Real sleep_time = 0;

  // What the solver's set-up reads besides the pose and masses.
  Vec2 local_center{0, 0};
  Vec2 force{0, 0};
  Real torque = 0;
  Real linear_damping = 0, angular_damping = 0, gravity_scale = 1;

  // The pose before the step numbered moved_step (for interpolated_pose).
  Vec2 previous_origin{0, 0};
  Rotation previous_rotation{};
  std::uint64_t moved_step = ~std::uint64_t{0};
  std::vector<std::uint32_t> shapes;

  // Contacts this body is in (indices into WorldState::contacts), so a step reaches the
  // contacts of awake bodies without scanning the sleeping ones.
  std::vector<std::uint32_t> contacts;
  // Of those, the contacts with a static or kinematic body: what continuous collision sweeps
  // a fast body against (none: nothing to sweep it against that its contacts hold).
  std::uint32_t fixed_contacts = 0;
  std::uint32_t generation = 0;
  std::vector<std::uint32_t> joints;  // joints this body is in (slots), a gear in all four
  std::uint64_t user_data = 0;

  Real mass = 0, inertia = 0;
  MassData override_mass;
  bool in_awake_list = false;

  Pose pose() const { return {origin, rotation}; }
};

// The centre of mass from the origin, and the origin from the centre, each the other plus an
// offset on the grid (world_grid.hpp), so both stay on it.
inline void place_center(Body& b) {
  b.center = b.origin + on_grid(b.rotation.apply(b.local_center));
}
inline void place_origin(Body& b) {
  b.origin = b.center - on_grid(b.rotation.apply(b.local_center));
}

// `r` turned further by the solver's rotation since the step began, (qc, qs), renormalised.
inline Rotation turned(const Rotation& r, Real qc, Real qs) {
  const Real c = qc * r.cos - qs * r.sin;
  const Real s = qs * r.cos + qc * r.sin;
  const Real inv_length = 1 / std::sqrt(c * c + s * s);
  return {c * inv_length, s * inv_length};
}

// Where a kinematic body's own velocity takes it in a step of `dt` in `substeps` substeps: it
// moves in double precision as the substeps move it, so it arrives where its velocity takes it,
// to the grid step (world_grid.hpp); (qc, qs) is its turn, as the solver's rotation since the
// step began.
struct KinematicMotion {
  Vec2 moved{0, 0};
  Real qc = 1, qs = 0;
};
inline KinematicMotion kinematic_motion(const Body& b, Real dt, int substeps) {
  const Real h = dt / substeps;
  const Real hw = h * b.angular_velocity;
  KinematicMotion m;
  for (int i = 0; i < substeps; ++i) {
    m.moved += h * b.velocity;
    const Real c = m.qc - hw * m.qs, s = m.qs + hw * m.qc;
    const Real inv_length = 1 / std::sqrt(c * c + s * s);
    m.qc = c * inv_length;
    m.qs = s * inv_length;
  }
  m.moved = on_grid(m.moved);
  return m;
}

// What create_body refuses (body.cpp); the scene reader refuses the same.
void check_body_def(const BodyDef& def);

// Moves in a step: awake, enabled and not static.
inline bool moves(const Body& b) {
  return b.type != BodyType::static_body && b.awake && b.enabled;
}

}  // namespace mink::detail
