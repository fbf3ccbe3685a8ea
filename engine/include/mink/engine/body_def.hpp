#pragma once

#include <cstdint>

#include "mink/geometry/types.hpp"

namespace mink {

enum class BodyType : std::uint8_t { static_body, kinematic, dynamic };

struct BodyDef {
  BodyType type = BodyType::static_body;
  Vec2 position{0, 0};         // of the body origin, the frame its shapes are given in
  Real angle = 0;              // radians
  Vec2 linear_velocity{0, 0};  // of the body origin (as in Box2D)
  Real angular_velocity = 0;
  Real linear_damping = 0;
  Real angular_damping = 0;
  Real gravity_scale = 1;
  bool allow_sleep = true;
  bool awake = true;
  std::uint64_t user_data = 0;
};

}  // namespace mink
