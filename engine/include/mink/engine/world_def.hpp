#pragma once

#include "mink/geometry/types.hpp"

namespace mink {

// World settings. Defaults follow Box2D v3 where it has an equivalent (units: metres,
// kilograms, seconds).
struct WorldDef {
  Vec2 gravity{0, -10};
  Real time_step = 1.0 / 60.0;  // one fixed step; advance() runs whole steps only
  int substeps = 4;             // soft-step substeps per step
  // Contact softness: stiffness (cycles per second, capped at a quarter of the substep rate)
  // and damping ratio of the soft contact spring.
  Real contact_hertz = 30;
  Real contact_damping_ratio = 10;
  // Fastest speed at which overlap is pushed apart, so deep overlap resolves without popping.
  Real contact_push_max_velocity = 3;
  // Approach speeds below this do not bounce, whatever the restitution.
  Real restitution_threshold = 1;
  // Allowed overlap; contacts are generated this many times four before shapes touch.
  Real linear_slop = 0.005;
  Real max_linear_speed = 400;
  bool enable_sleep = true;
  Real time_to_sleep = 0.5;
  Real linear_sleep_tolerance = 0.05;    // m/s
  Real angular_sleep_tolerance = 0.035;  // rad/s (about 2 degrees per second)
  // advance() runs at most this many steps per call, dropping the rest of a long frame so a
  // slow frame cannot snowball into ever slower ones.
  int max_steps_per_advance = 8;
};

}  // namespace mink
