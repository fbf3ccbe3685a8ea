#include <cmath>
#include <numbers>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/polygon.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

namespace mink {

namespace {

bool finite(const Vec2& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

// Area, first moment and polar second moment of a region about a fixed point, summed over
// pieces; unit density.
struct Moments {
  Real area = 0;
  Vec2 first{0, 0};
  Real polar = 0;

  // A piece of `area` with centroid `centroid` and polar moment `own` about it, both
  // relative to the reference point.
  void add_piece(Real piece_area, const Vec2& centroid, Real own) {
    area += piece_area;
    first += piece_area * centroid;
    polar += own + piece_area * centroid.squaredNorm();
  }

  MassData mass(Real density, const Vec2& origin) const {
    MassData m;
    m.mass = density * area;
    if (area <= 0) {
      m.center = origin;
      return m;
    }
    const Vec2 offset = first / area;
    m.center = origin + offset;
    m.rotational_inertia = density * (polar - area * offset.squaredNorm());
    return m;
  }
};

MassData polygon_mass(const RoundedPolygon& polygon, Real density) {
  const std::span<const Vec2> v = polygon.hull.vertices();
  const AreaProperties core = area_properties(v);
  const Vec2 c0 = core.centroid;  // everything about the core's centroid, for precision
  Moments sum;
  sum.add_piece(core.area, Vec2(0, 0), core.polar_moment);
  const Real r = polygon.radius;
  if (r > 0) {
    const std::span<const Vec2> normals = polygon.hull.normals();
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i) {
      // The rectangle swept outwards from edge i.
      const Vec2& a = v[i];
      const Vec2& b = v[i + 1 == n ? 0 : i + 1];
      const Real length = (b - a).norm();
      const Real rect_area = length * r;
      const Vec2 rect_centre = 0.5 * (a + b) + (0.5 * r) * normals[i] - c0;
      sum.add_piece(rect_area, rect_centre, rect_area * (length * length + r * r) / 12);
      // The disk sector at vertex i, between the normals of edges i - 1 and i: polar moment
      // r^4 theta / 4 about the vertex, first moment (r^3 / 3)(sin a2 - sin a1, cos a1 - cos a2).
      const Vec2& n1 = normals[i == 0 ? n - 1 : i - 1];
      const Vec2& n2 = normals[i];
      const Real theta = std::atan2(n1.x() * n2.y() - n1.y() * n2.x(), n1.dot(n2));
      const Real sector_area = 0.5 * r * r * theta;
      const Vec2 about_vertex = (r * r * r / 3) * Vec2(n2.y() - n1.y(), n1.x() - n2.x());
      const Vec2 vertex = a - c0;
      sum.area += sector_area;
      sum.first += about_vertex + sector_area * vertex;
      sum.polar += r * r * r * r * theta / 4 + 2 * vertex.dot(about_vertex) +
                   sector_area * vertex.squaredNorm();
    }
  }
  return sum.mass(density, c0);
}

}  // namespace

void validate_shape(const ShapeGeometry& geometry) {
  const auto radius_check = [](Real radius, const char* what, bool zero_allowed) {
    if (!std::isfinite(radius) || radius < 0 || (!zero_allowed && radius == 0)) {
      throw InvalidArgumentError(std::string(what) + " radius must be " +
                                 (zero_allowed ? "finite and >= 0" : "finite and > 0") + ", got " +
                                 std::to_string(radius));
    }
  };
  switch (kind_of(geometry)) {
    case ShapeKind::circle: {
      const auto& c = std::get<Circle>(geometry);
      radius_check(c.radius, "circle", false);
      if (!finite(c.center)) throw InvalidArgumentError("circle centre is not finite");
      break;
    }
    case ShapeKind::capsule: {
      const auto& c = std::get<Capsule>(geometry);
      radius_check(c.radius, "capsule", false);
      if (!finite(c.center1) || !finite(c.center2))
        throw InvalidArgumentError("capsule centre is not finite");
      if (c.center1 == c.center2)
        throw InvalidArgumentError("capsule centres must be distinct (use a circle)");
      break;
    }
    case ShapeKind::segment:
    case ShapeKind::chain_segment: {
      const bool chain = kind_of(geometry) == ShapeKind::chain_segment;
      const Segment& s =
          chain ? std::get<ChainSegment>(geometry).segment : std::get<Segment>(geometry);
      if (!finite(s.point1) || !finite(s.point2))
        throw InvalidArgumentError("segment point is not finite");
      if (s.point1 == s.point2) throw InvalidArgumentError("segment points must be distinct");
      if (chain && (!finite(std::get<ChainSegment>(geometry).ghost1) ||
                    !finite(std::get<ChainSegment>(geometry).ghost2)))
        throw InvalidArgumentError("chain ghost vertex is not finite");
      break;
    }
    case ShapeKind::polygon:
      radius_check(std::get<RoundedPolygon>(geometry).radius, "polygon", true);
      break;
  }
}

MassData compute_mass(const ShapeGeometry& geometry, Real density) {
  if (!std::isfinite(density) || density < 0) {
    throw InvalidArgumentError("density must be finite and >= 0, got " + std::to_string(density));
  }
  validate_shape(geometry);
  MassData m;
  switch (kind_of(geometry)) {
    case ShapeKind::circle: {
      const auto& c = std::get<Circle>(geometry);
      m.mass = density * std::numbers::pi * c.radius * c.radius;
      m.center = c.center;
      m.rotational_inertia = 0.5 * m.mass * c.radius * c.radius;
      return m;
    }
    case ShapeKind::capsule: {
      // A rectangle between two half disks. A half disk's centroid lies 4r / (3 pi) from its
      // flat side; moved to the capsule's centre its polar moment is
      // m_half (r^2 / 2 + L^2 / 4 + L e).
      const auto& c = std::get<Capsule>(geometry);
      const Real r = c.radius;
      const Real length = (c.center2 - c.center1).norm();
      const Real rect_mass = density * 2 * r * length;
      const Real half_mass = density * 0.5 * std::numbers::pi * r * r;
      const Real e = 4 * r / (3 * std::numbers::pi);
      m.mass = rect_mass + 2 * half_mass;
      m.center = 0.5 * (c.center1 + c.center2);
      m.rotational_inertia = rect_mass * (length * length + 4 * r * r) / 12 +
                             2 * half_mass * (0.5 * r * r + 0.25 * length * length + length * e);
      return m;
    }
    case ShapeKind::segment:
      m.center = 0.5 * (std::get<Segment>(geometry).point1 + std::get<Segment>(geometry).point2);
      return m;
    case ShapeKind::chain_segment: {
      const Segment& s = std::get<ChainSegment>(geometry).segment;
      m.center = 0.5 * (s.point1 + s.point2);
      return m;
    }
    case ShapeKind::polygon:
      return polygon_mass(std::get<RoundedPolygon>(geometry), density);
  }
  return m;
}

}  // namespace mink
