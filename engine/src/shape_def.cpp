#include "mink/engine/shape_def.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "checks.hpp"
#include "mink/error.hpp"
#include "mink/geometry/transform.hpp"
#include "shape.hpp"

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

ShapeDef ShapeDef::circle(Real radius, const Vec2& center) {
  ShapeDef def;
  def.type = ShapeType::circle;
  def.points = {center};
  def.radius = radius;
  return def;
}

ShapeDef ShapeDef::capsule(const Vec2& center1, const Vec2& center2, Real radius) {
  ShapeDef def;
  def.type = ShapeType::capsule;
  def.points = {center1, center2};
  def.radius = radius;
  return def;
}

ShapeDef ShapeDef::segment(const Vec2& point1, const Vec2& point2) {
  ShapeDef def;
  def.type = ShapeType::segment;
  def.points = {point1, point2};
  return def;
}

ShapeDef ShapeDef::chain(std::vector<Vec2> points, bool loop) {
  ShapeDef def;
  def.type = ShapeType::chain;
  def.points = std::move(points);
  def.loop = loop;
  return def;
}

std::string_view to_string(ShapeType type) noexcept {
  switch (type) {
    case ShapeType::polygon:
      return "polygon";
    case ShapeType::circle:
      return "circle";
    case ShapeType::capsule:
      return "capsule";
    case ShapeType::segment:
      return "segment";
    case ShapeType::chain:
      return "chain";
  }
  return "unknown";
}

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw InvalidArgumentError(message);
}

std::string number(Real value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void check_materials(const ShapeDef& def) {
  detail::check_density(def.density, "ShapeDef.density");
  detail::check_coefficient(def.friction, "ShapeDef.friction");
  detail::check_coefficient(def.restitution, "ShapeDef.restitution");
}

void check_points_finite(const std::vector<Vec2>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      throw NonFiniteInputError(i);
    }
  }
}

void check_point_count(const ShapeDef& def, std::size_t count) {
  require(def.points.size() == count, "ShapeDef.points: a " + std::string(to_string(def.type)) +
                                          " takes " + std::to_string(count) + " point" +
                                          (count == 1 ? "" : "s") + ", got " +
                                          std::to_string(def.points.size()));
}

}  // namespace

void detail::check_density(Real density, const std::string& what) {
  require(std::isfinite(density) && density >= 0,
          what + " must be finite and non-negative, got " + number(density));
}

void detail::check_coefficient(Real value, const std::string& what) {
  require(detail::valid_coefficient(value),
          what + " must be non-negative and within max_setting_magnitude (1e9), got " +
              detail::exact_number(value));
}

void check_shape_def(const ShapeDef& def) {
  check_materials(def);
  require(std::isfinite(def.radius) && def.radius >= 0,
          "ShapeDef.radius must be finite and non-negative, got " + number(def.radius));
  require(
      def.radius <= max_world_coordinate,
      "ShapeDef.radius must not exceed max_world_coordinate (1e15 m), got " + number(def.radius));
  for (std::size_t i = 0; i < def.points.size(); ++i) {
    require(!detail::finite(def.points[i]) || detail::within_world(def.points[i]),
            "ShapeDef.points[" + std::to_string(i) +
                "] lies beyond max_world_coordinate (1e15 m) of its body's origin");
  }
  require(!def.scale || def.type == ShapeType::polygon,
          "ShapeDef.scale applies to polygons only, not to a " + std::string(to_string(def.type)));
  require(!def.loop || def.type == ShapeType::chain, "ShapeDef.loop applies to chains only");
  switch (def.type) {
    case ShapeType::polygon:
      make_shape_hull(def);  // throws the hull errors
      break;
    case ShapeType::circle:
      check_point_count(def, 1);
      check_points_finite(def.points);
      require(def.radius > 0,
              "ShapeDef.radius of a circle must be positive, got " + number(def.radius));
      break;
    case ShapeType::capsule:
    case ShapeType::segment:
      check_point_count(def, 2);
      check_points_finite(def.points);
      require(def.points[0] != def.points[1],
              "ShapeDef.points of a " + std::string(to_string(def.type)) + " must differ");
      if (def.type == ShapeType::capsule) {
        require(def.radius > 0,
                "ShapeDef.radius of a capsule must be positive, got " + number(def.radius));
      } else {
        require(def.radius == 0, "ShapeDef.radius of a segment must be 0 (use a capsule)");
      }
      break;
    case ShapeType::chain: {
      const std::size_t needed = def.loop ? 3 : 2;
      require(def.points.size() >= needed, "ShapeDef.points: a " +
                                               std::string(def.loop ? "looped " : "") +
                                               "chain needs at least " + std::to_string(needed) +
                                               " points, got " + std::to_string(def.points.size()));
      check_points_finite(def.points);
      for (std::size_t i = 0; i + 1 < def.points.size(); ++i) {
        require(def.points[i] != def.points[i + 1], "ShapeDef.points of a chain: points " +
                                                        std::to_string(i) + " and " +
                                                        std::to_string(i + 1) + " are equal");
      }
      require(!def.loop || def.points.front() != def.points.back(),
              "ShapeDef.points of a looped chain: the last point repeats the first (the loop "
              "closes itself)");
      require(def.radius == 0, "ShapeDef.radius of a chain must be 0");
      require(!def.is_sensor, "a chain cannot be a sensor");
      break;
    }
  }
}

ConvexHull make_shape_hull(const ShapeDef& def) {
  if (def.type != ShapeType::polygon) {
    throw InvalidArgumentError("make_shape_hull: a " + std::string(to_string(def.type)) +
                               " is not a polygon");
  }
  check_materials(def);
  if (def.scale) {
    if (!std::isfinite(def.scale->fixed_point.x()) || !std::isfinite(def.scale->fixed_point.y())) {
      throw InvalidArgumentError("ShapeDef.scale.fixed_point must be finite");
    }
    const std::vector<Vec2> scaled =
        scale_about(def.points, def.scale->fixed_point, def.scale->factor);
    // Points within the limit, scaled, may not be.
    for (const Vec2& v : scaled) {
      require(!detail::finite(v) || detail::within_world(v),
              "ShapeDef.scale (factors " + number(def.scale->factor.x()) + ", " +
                  number(def.scale->factor.y()) +
                  ") takes the polygon's points beyond max_world_coordinate (1e15 m) of its "
                  "body's origin");
    }
    return build_hull(scaled, def.algorithm);
  }
  return build_hull(def.points, def.algorithm);
}

}  // namespace mink
