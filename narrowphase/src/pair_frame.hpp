#pragma once

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/simplex.hpp"
#include "mink/narrowphase/support.hpp"

namespace mink::detail {

// A hull pair seen from A's local frame: B's vertices are mapped by one relative transform,
// so A's support needs no transform at all and B's costs one rotation of the direction.
class PairFrame {
 public:
  PairFrame(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b, const Pose& pose_b)
      : a_(a), b_(b), pose_a_(pose_a) {
    const Rotation& ra = pose_a.rotation;
    const Rotation& rb = pose_b.rotation;
    relative_.rotation = {ra.cos * rb.cos + ra.sin * rb.sin, ra.cos * rb.sin - ra.sin * rb.cos};
    relative_.position = ra.apply_inverse(pose_b.position - pose_a.position);
  }

  const PreparedHull& a() const noexcept { return a_; }
  const PreparedHull& b() const noexcept { return b_; }
  // B's local frame to A's.
  const Pose& relative() const noexcept { return relative_; }
  const Pose& pose_a() const noexcept { return pose_a_; }

  Vec2 b_vertex(std::size_t i) const { return relative_.apply(b_.vertices()[i]); }

  SimplexVertex vertex(std::uint32_t ia, std::uint32_t ib) const {
    SimplexVertex v;
    v.index_a = ia;
    v.index_b = ib;
    v.a = a_.vertices()[ia];
    v.b = b_vertex(ib);
    v.point = v.a - v.b;
    return v;
  }

  // Support point of A - B along d (A's frame): eq. 4 of the paper.
  SimplexVertex support(const Vec2& d) const {
    const auto ia = static_cast<std::uint32_t>(support_index(a_, d));
    const auto ib =
        static_cast<std::uint32_t>(support_index(b_, relative_.rotation.apply_inverse(-d)));
    return vertex(ia, ib);
  }

  // The simplex in world coordinates.
  Simplex to_world(const Simplex& local) const {
    Simplex world = local;
    for (int i = 0; i < local.count; ++i) {
      SimplexVertex& v = world.vertices[static_cast<std::size_t>(i)];
      v.a = pose_a_.apply(v.a);
      v.b = pose_a_.apply(v.b);
      v.point = pose_a_.rotation.apply(v.point);
    }
    return world;
  }

 private:
  const PreparedHull& a_;
  const PreparedHull& b_;
  Pose pose_a_;
  Pose relative_;
};

// Multiplies v by a power of two (exact) so its largest component lies in [1, 2): directions
// keep their sign tests meaningful at huge and tiny coordinates. Zero stays zero.
inline Vec2 rescaled_direction(const Vec2& v) {
  const Real m = std::max(std::abs(v.x()), std::abs(v.y()));
  if (m == 0 || !std::isfinite(m)) return v;
  const int e = std::ilogb(m);
  return Vec2(std::ldexp(v.x(), -e), std::ldexp(v.y(), -e));
}

inline Real cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace mink::detail
