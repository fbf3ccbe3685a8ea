#pragma once

#include <span>

#include "mink/geometry/types.hpp"

namespace mink::interop {

// Box2D's answer for two point sets in one frame: b2Distance on radius-0 proxies
// (b2DistanceProxy::Set(vertices, count, 0), useRadii = false), vertices rounded to float.
struct Box2dDistance {
  bool overlap = false;  // distance exactly 0
  double distance = 0;
  int iterations = 0;
};

Box2dDistance box2d_distance(std::span<const Vec2> a, std::span<const Vec2> b);

}  // namespace mink::interop
