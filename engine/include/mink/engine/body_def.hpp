#pragma once

#include <cstdint>
#include <string_view>

#include "mink/geometry/types.hpp"

namespace mink {

/// @brief How a body moves.
/// static_body: never moves; kinematic: moves by its set velocity, unaffected by forces and
/// contacts; dynamic: moved by gravity, forces and contacts.
enum class BodyType : std::uint8_t { static_body, kinematic, dynamic };

/// @brief "static", "kinematic" or "dynamic", as scene files spell the type.
std::string_view to_string(BodyType type) noexcept;

/// The smallest positive mass (kg) and rotational inertia (kg m^2) a dynamic body may have,
/// whether its shapes give them (density times area) or World::set_mass_data sets them. The
/// solver works with their inverses in single precision: smaller ones would overflow there and
/// turn the body's state into NaN. A shape, density or mass data that gives less is refused.
inline constexpr Real min_mass_property = 1e-30;
/// The largest mass (kg) and rotational inertia (kg m^2) one shape or World::set_mass_data may
/// give: beyond it, sums over shapes and their lever arms could overflow (a density of 1e300
/// gave an infinite mass).
inline constexpr Real max_mass_property = 1e30;

/// The farthest from the origin (m, on each axis) a body may be placed or a shape's point reach
/// in its body's frame. Positions are doubles, whose resolution there is 0.125 m; farther out,
/// sums of coordinates would overflow and the single-precision solver's squared distances
/// between bodies would too (a body at -2e306 m turned a world NaN).
inline constexpr Real max_world_coordinate = 1e15;

/// The grid (m) a step moves bodies on: each step's motion, and a centre of mass's offset from
/// its body's origin, are rounded to multiples of it, which doubles hold exactly out to
/// position_grid_reach. A body placed on the grid stays on it, so a scene moved by a whole
/// number of grid steps, anywhere within that reach, moves bit for bit as it does at the
/// origin (doubles 10^7 m out are this far apart; at 1 m they are 2.2e-16 m apart, and rounding
/// each motion there more finely than far away made the same scene settle differently).
inline constexpr Real position_grid_step = 0x1p-29;  // 1.9e-9 m
/// How far from the origin (m, on each axis) the multiples of position_grid_step are exact
/// doubles: 2^24 m, 1.7e7 m.
inline constexpr Real position_grid_reach = 0x1p24;

/// Everything World::create_body needs; plain data. Units: metres, radians, seconds.
struct BodyDef {
  BodyType type = BodyType::static_body;  ///< static unless set
  Vec2 position{0, 0};                    ///< of the body origin, the frame its shapes are given in
  Real angle = 0;                         ///< radians
  Vec2 linear_velocity{0, 0};             ///< of the centre of mass, m/s
  Real angular_velocity = 0;              ///< rad/s, counter-clockwise positive
  Real linear_damping = 0;                ///< >= 0, slows linear velocity over time
  Real angular_damping = 0;               ///< >= 0, slows angular velocity over time
  Real gravity_scale = 1;                 ///< multiplies the world's gravity for this body
  bool allow_sleep = true;                ///< false keeps the body awake
  bool awake = true;                      ///< false creates it asleep
  bool enabled = true;                    ///< false: in the world but not simulated or collided
  bool fixed_rotation = false;            ///< true: never rotates (infinite rotational inertia)
  /// Continuous collision against dynamic bodies too, not only against static and kinematic
  /// ones (for small fast bodies).
  bool bullet = false;
  /// How far a step may move the body, as a fraction of its smallest half-width, before it
  /// counts as fast and its motion is swept (continuous collision): a step moving its surface
  /// farther than this (translation plus turn at its extent) is checked for the first touch on
  /// the way. >= 0; 0 sweeps every step; a huge value never does.
  Real continuous_threshold = 0.5;
  std::uint64_t user_data = 0;  ///< anything the caller wants back from World::user_data
};

}  // namespace mink
