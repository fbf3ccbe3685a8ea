#pragma once

#include <optional>
#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

/// Akl-Toussaint pre-filter: the points extreme in eight directions span a convex polygon;
/// points certainly strictly inside it cannot be hull vertices and are dropped. Points it is not
/// sure about are kept, so the hull of the result is the hull of the input. Input order is kept.
/// Validates the input like every hull algorithm (NonFiniteInputError, DegenerateInputError).
std::vector<Vec2> akl_toussaint_filter(std::span<const Vec2> points);

/// The same filter, but only when a sample of the points shows it would drop at least half of
/// them; std::nullopt means "not worth it, use the input as it is". Fewer than three points,
/// or a degenerate or non-finite input, throw as above.
std::optional<std::vector<Vec2>> akl_toussaint_filter_if_worthwhile(std::span<const Vec2> points);

}  // namespace mink
