#pragma once

#include <span>

#include "mink/geometry/types.hpp"

namespace mink {

/// @brief Checks that every coordinate is finite.
/// @throws NonFiniteInputError naming the first point with a NaN or infinite coordinate.
void require_finite(std::span<const Vec2> points);

/// @brief The precondition every hull algorithm checks first: all coordinates finite and at
/// least three distinct points not all on one line. O(n); usually stops early on the second
/// condition.
/// @throws NonFiniteInputError with the point's index for a NaN or infinite coordinate
/// @throws DegenerateInputError when the points are not three distinct, non-collinear ones
void validate_hull_input(std::span<const Vec2> points);

}  // namespace mink
