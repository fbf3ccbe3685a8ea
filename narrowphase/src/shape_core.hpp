#pragma once

// Every shape kind as a convex core (one point, a segment's two points or a prepared hull) plus
// a radius: the form GJK, the separating-axis test and clipping work on.

#include <array>
#include <cstddef>
#include <cstdint>

#include "mink/narrowphase/shape_geometry.hpp"
#include "mink/narrowphase/support.hpp"
#include "pair_frame.hpp"

namespace mink::detail {

struct Core {
  std::array<Vec2, 2> small{};         // the points when there is no hull
  std::size_t count = 0;               // 1, 2, or the hull's vertex count
  const PreparedHull* hull = nullptr;  // set for polygons
  Real radius = 0;

  std::size_t size() const noexcept { return count; }
  Vec2 point(std::size_t i) const { return hull != nullptr ? hull->vertices()[i] : small[i]; }
  // Where GJK's first direction starts (eq. 2): the hull's centroid or the points' midpoint.
  Vec2 centre() const {
    if (hull != nullptr) return hull->centroid();
    return count == 1 ? small[0] : Vec2(0.5 * (small[0] + small[1]));
  }
  // Index of the point farthest along `d` (local); the first on ties.
  std::uint32_t support(const Vec2& d) const {
    if (hull != nullptr) return static_cast<std::uint32_t>(support_index(*hull, d));
    return count == 2 && small[1].dot(d) > small[0].dot(d) ? 1 : 0;
  }
};

inline Core core_of(const ShapeGeometry& geometry) {
  Core core;
  switch (kind_of(geometry)) {
    case ShapeKind::circle: {
      const auto& c = std::get<Circle>(geometry);
      core.small[0] = c.center;
      core.count = 1;
      core.radius = c.radius;
      break;
    }
    case ShapeKind::capsule: {
      const auto& c = std::get<Capsule>(geometry);
      core.small = {c.center1, c.center2};
      core.count = 2;
      core.radius = c.radius;
      break;
    }
    case ShapeKind::segment: {
      const auto& s = std::get<Segment>(geometry);
      core.small = {s.point1, s.point2};
      core.count = 2;
      break;
    }
    case ShapeKind::chain_segment: {
      const auto& s = std::get<ChainSegment>(geometry).segment;
      core.small = {s.point1, s.point2};
      core.count = 2;
      break;
    }
    case ShapeKind::polygon: {
      const auto& p = std::get<RoundedPolygon>(geometry);
      core.hull = &p.hull;
      core.count = p.hull.size();
      core.radius = p.radius;
      break;
    }
  }
  return core;
}

// Two cores seen from A's local frame, with the interface distance_loop needs.
class CoreFrame {
 public:
  CoreFrame(const Core& a, const Core& b, const Pose& b_to_a) : a_(a), b_(b), relative_(b_to_a) {}

  std::size_t a_count() const noexcept { return a_.size(); }
  std::size_t b_count() const noexcept { return b_.size(); }
  Vec2 a_vertex(std::size_t i) const { return a_.point(i); }
  Vec2 b_vertex(std::size_t i) const { return relative_.apply(b_.point(i)); }
  Vec2 initial_direction() const { return relative_.apply(b_.centre()) - a_.centre(); }
  LocalVertex vertex(std::uint32_t ia, std::uint32_t ib) const {
    return {a_vertex(ia) - b_vertex(ib), ia, ib};
  }
  LocalVertex support(const Vec2& d) const {
    return vertex(a_.support(d), b_.support(relative_.rotation.apply_inverse(-d)));
  }

 private:
  const Core& a_;
  const Core& b_;
  Pose relative_;
};

}  // namespace mink::detail
