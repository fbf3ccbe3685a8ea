#pragma once

#include <box2d/b2_math.h>

#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink::interop {

// Box2D's answer for two point sets in one frame: b2Distance on radius-0 proxies
// (b2DistanceProxy::Set(vertices, count, 0), useRadii = false), vertices rounded to float.
struct Box2dDistance {
  bool overlap = false;  // distance exactly 0
  double distance = 0;
  int iterations = 0;
};

// A point rounded to float, as Box2D's.
inline b2Vec2 to_float(const Vec2& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y())};
}
// The points rounded to float, as Box2D's vertices.
std::vector<b2Vec2> to_float(std::span<const Vec2> points);

Box2dDistance box2d_distance(std::span<const Vec2> a, std::span<const Vec2> b);

}  // namespace mink::interop
