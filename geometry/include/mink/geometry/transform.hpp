#pragma once

#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

/// Paper eq. 5: every point moved by `offset`.
std::vector<Vec2> translate(std::span<const Vec2> points, const Vec2& offset);

/// @brief Paper eq. 6: scale by (factor.x, factor.y) about `fixed_point`, which stays where it
/// is.
/// @throws InvalidArgumentError for a zero or non-finite factor (a zero factor flattens a
/// hull).
std::vector<Vec2> scale_about(std::span<const Vec2> points, const Vec2& fixed_point,
                              const Vec2& factor);

/// Rotation by `radians` counter-clockwise about `pivot`.
std::vector<Vec2> rotate_about(std::span<const Vec2> points, const Vec2& pivot, Real radians);

/// The 2x2 rotation matrix for `radians`.
Mat2 rotation(Real radians);

}  // namespace mink
