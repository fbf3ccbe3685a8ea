#pragma once

#include <span>

#include "mink/geometry/types.hpp"

namespace mink {

// Throws NonFiniteInputError naming the first point with a NaN or infinite coordinate.
void require_finite(std::span<const Vec2> points);

// The precondition every hull algorithm checks first: all coordinates finite (else
// NonFiniteInputError with the point's index) and at least three distinct points not all on one
// line (else DegenerateInputError). O(n); usually stops early on the second condition.
void validate_hull_input(std::span<const Vec2> points);

}  // namespace mink
