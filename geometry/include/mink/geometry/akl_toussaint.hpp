#pragma once

#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

// Akl-Toussaint pre-filter: the points extreme in eight directions span a convex polygon;
// points certainly strictly inside it cannot be hull vertices and are dropped. Points it is not
// sure about are kept, so the hull of the result is the hull of the input. Input order is kept.
std::vector<Vec2> akl_toussaint_filter(std::span<const Vec2> points);

}  // namespace mink
