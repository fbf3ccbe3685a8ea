#include "mink/geometry/transform.hpp"

#include <cmath>
#include <sstream>

#include "mink/error.hpp"

namespace mink {

std::vector<Vec2> translate(std::span<const Vec2> points, const Vec2& offset) {
  std::vector<Vec2> moved;
  moved.reserve(points.size());
  for (const Vec2& p : points) moved.push_back(p + offset);
  return moved;
}

std::vector<Vec2> scale_about(std::span<const Vec2> points, const Vec2& fixed_point,
                              const Vec2& factor) {
  if (!std::isfinite(factor.x()) || !std::isfinite(factor.y()) || factor.x() == 0 ||
      factor.y() == 0) {
    std::ostringstream message;
    message << "scale factor (" << factor.x() << ", " << factor.y()
            << ") must be finite and non-zero";
    throw InvalidArgumentError(message.str());
  }
  std::vector<Vec2> scaled;
  scaled.reserve(points.size());
  for (const Vec2& p : points) {
    scaled.push_back((p - fixed_point).cwiseProduct(factor) + fixed_point);
  }
  return scaled;
}

Mat2 rotation(Real radians) {
  const Real c = std::cos(radians);
  const Real s = std::sin(radians);
  Mat2 r;
  r << c, -s, s, c;
  return r;
}

std::vector<Vec2> rotate_about(std::span<const Vec2> points, const Vec2& pivot, Real radians) {
  const Mat2 r = rotation(radians);
  std::vector<Vec2> rotated;
  rotated.reserve(points.size());
  for (const Vec2& p : points) rotated.push_back(r * (p - pivot) + pivot);
  return rotated;
}

}  // namespace mink
