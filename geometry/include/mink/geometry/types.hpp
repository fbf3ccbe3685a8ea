#pragma once

#include <Eigen/Core>

namespace mink {

using Real = double;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

}  // namespace mink
