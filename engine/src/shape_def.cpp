#include "mink/engine/shape_def.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/transform.hpp"

namespace mink {

ShapeDef ShapeDef::box(Real hx, Real hy, const Vec2& center, Real angle) {
  if (!(std::isfinite(hx) && std::isfinite(hy) && hx > 0 && hy > 0)) {
    throw InvalidArgumentError("ShapeDef::box: half extents must be positive and finite, got " +
                               std::to_string(hx) + " x " + std::to_string(hy));
  }
  const Real c = std::cos(angle), s = std::sin(angle);
  ShapeDef def;
  for (const Vec2& corner : {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)}) {
    def.points.emplace_back(center.x() + c * corner.x() - s * corner.y(),
                            center.y() + s * corner.x() + c * corner.y());
  }
  return def;
}

ShapeDef ShapeDef::regular_polygon(int count, Real radius, const Vec2& center) {
  if (count < 3) {
    throw InvalidArgumentError("ShapeDef::regular_polygon: count must be at least 3, got " +
                               std::to_string(count));
  }
  if (!(std::isfinite(radius) && radius > 0)) {
    throw InvalidArgumentError("ShapeDef::regular_polygon: radius must be positive, got " +
                               std::to_string(radius));
  }
  ShapeDef def;
  for (int i = 0; i < count; ++i) {
    const Real a = 2 * std::numbers::pi * i / count;
    def.points.emplace_back(center.x() + radius * std::cos(a), center.y() + radius * std::sin(a));
  }
  return def;
}

ConvexHull make_shape_hull(const ShapeDef& def) {
  const auto check = [](Real value, const char* name) {
    if (!std::isfinite(value) || value < 0) {
      throw InvalidArgumentError(std::string("ShapeDef.") + name +
                                 " must be finite and non-negative, got " + std::to_string(value));
    }
  };
  check(def.density, "density");
  check(def.friction, "friction");
  check(def.restitution, "restitution");
  if (def.scale) {
    if (!std::isfinite(def.scale->fixed_point.x()) || !std::isfinite(def.scale->fixed_point.y())) {
      throw InvalidArgumentError("ShapeDef.scale.fixed_point must be finite");
    }
    return build_hull(scale_about(def.points, def.scale->fixed_point, def.scale->factor),
                      def.algorithm);
  }
  return build_hull(def.points, def.algorithm);
}

}  // namespace mink
