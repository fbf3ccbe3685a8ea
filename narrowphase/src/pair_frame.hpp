#pragma once

#include <array>
#include <cmath>

#include "mink/geometry/orientation.hpp"
#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/simplex.hpp"
#include "mink/narrowphase/support.hpp"

namespace mink::detail {

// A support point of A - B in A's frame with the vertex pair it came from: all the loops
// carry. The hull vertices themselves are looked up from the indices when needed.
struct LocalVertex {
  Vec2 point{0, 0};
  std::uint32_t index_a = 0;
  std::uint32_t index_b = 0;
};

struct LocalSimplex {
  std::array<LocalVertex, 3> vertices{};
  int count = 0;
};

// A hull pair seen from A's local frame: B's vertices are mapped by one relative transform,
// so A's support needs no transform at all and B's costs one rotation of the direction.
class PairFrame {
 public:
  PairFrame(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b, const Pose& pose_b)
      : a_(a), b_(b), pose_a_(pose_a) {
    relative_ = mink::relative_pose(pose_a, pose_b);
#if defined(__SSE2__)
    if (b.padded_size() == kSupportBlock) {
      // A small B is mapped into A's frame once, so each support of B in the loops is a plain
      // scan with no rotation of the direction and no transform of the answer. The same
      // operations in the same order as Pose::apply, so b_vertex is unchanged.
      const PoseLanes map(relative_);
      for (std::size_t k = 0; k < kSupportBlock; k += 2) {
        __m128d x, y;
        map.apply(b.xs() + k, b.ys() + k, x, y);
        _mm_store_pd(bx_.data() + k, x);
        _mm_store_pd(by_.data() + k, y);
      }
      mapped_ = true;
      a_block_ = a.padded_size() == kSupportBlock;
    }
#endif
  }

  const PreparedHull& a() const noexcept {
    return a_;
  }
  const PreparedHull& b() const noexcept {
    return b_;
  }
  // B's local frame to A's.
  const Pose& relative() const noexcept {
    return relative_;
  }
  const Pose& pose_a() const noexcept {
    return pose_a_;
  }

  // The interface distance_loop needs (CoreFrame offers the same).
  std::size_t a_count() const noexcept {
    return a_.size();
  }
  std::size_t b_count() const noexcept {
    return b_.size();
  }
  Vec2 a_vertex(std::size_t i) const {
    return a_.vertices()[i];
  }
  // Eq. 2: from A's centroid to B's, in A's frame.
  Vec2 initial_direction() const {
    return relative_.apply(b_.centroid()) - a_.centroid();
  }

  Vec2 b_vertex(std::size_t i) const {
    return mapped_ ? Vec2(bx_[i], by_[i]) : relative_.apply(b_.vertices()[i]);
  }

  LocalVertex vertex(std::uint32_t ia, std::uint32_t ib) const {
    return {a_.vertices()[ia] - b_vertex(ib), ia, ib};
  }

  // Support point of A - B along d (A's frame): eq. 4 of the paper.
  LocalVertex support(const Vec2& d) const {
#if defined(__SSE2__)
    if (a_block_) {
      // Both hulls are single blocks: two straight scans, and the point from the same arrays
      // (copies of the vertices, so the same values as the general path).
      const auto ia = static_cast<std::uint32_t>(detail::support_block(a_.xs(), a_.ys(), d));
      const auto ib = static_cast<std::uint32_t>(
          detail::support_block(bx_.data(), by_.data(), Vec2(-d.x(), -d.y())));
      return {Vec2(a_.xs()[ia] - bx_[ib], a_.ys()[ia] - by_[ib]), ia, ib};
    }
#endif
    const auto ia = static_cast<std::uint32_t>(support_index(a_, d));
#if defined(__SSE2__)
    if (mapped_) {
      const auto ib = static_cast<std::uint32_t>(
          detail::support_block(bx_.data(), by_.data(), Vec2(-d.x(), -d.y())));
      return {a_.vertices()[ia] - Vec2(bx_[ib], by_[ib]), ia, ib};
    }
#endif
    const auto ib =
        static_cast<std::uint32_t>(support_index(b_, relative_.rotation.apply_inverse(-d)));
    return vertex(ia, ib);
  }

  // The vertex pairs of a simplex.
  static SimplexCache indices(const LocalSimplex& s) {
    SimplexCache c;
    c.count = s.count;
    for (int i = 0; i < s.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      c.index_a[k] = s.vertices[k].index_a;
      c.index_b[k] = s.vertices[k].index_b;
    }
    return c;
  }

 private:
  const PreparedHull& a_;
  const PreparedHull& b_;
  Pose pose_a_;
  Pose relative_;
  alignas(16) std::array<Real, kSupportBlock> bx_{};  // B mapped into A's frame, when B is small
  alignas(16) std::array<Real, kSupportBlock> by_{};
  bool mapped_ = false;
  bool a_block_ = false;  // mapped_, and A is one block too
};

// Multiplies v by a power of two (exact) so its largest component lies in [1, 2) when it is
// huge or tiny: directions keep their sign tests meaningful (no overflow to infinity, no
// underflow to zero in dot products) at any coordinates. Ordinary magnitudes pass unchanged,
// which keeps the common case free of libm calls. Zero stays zero.
// The power of two rescaled_direction divides by: 0 for ordinary magnitudes, zero and
// non-finite vectors.
inline int rescale_exponent(const Vec2& v) {
  const Real m = std::max(std::abs(v.x()), std::abs(v.y()));
  if ((m >= 0x1p-200 && m <= 0x1p200) || m == 0 || !std::isfinite(m)) return 0;
  return std::ilogb(m);
}

inline Vec2 rescaled_direction(const Vec2& v) {
  const int e = rescale_exponent(v);
  return e == 0 ? v : Vec2(std::ldexp(v.x(), -e), std::ldexp(v.y(), -e));
}

// |v| without the squares underflowing or overflowing far from unit size; exactly v.norm()
// between 2^-200 and 2^200.
inline Real rescaled_norm(const Vec2& v) {
  return std::ldexp(rescaled_direction(v).norm(), rescale_exponent(v));
}

// v / |v|, likewise safe far from unit size.
inline Vec2 rescaled_unit(const Vec2& v) {
  return rescaled_direction(v).normalized();
}

// orient2d(p, q, origin): the same products and the same filter with c = 0 folded in (the
// generic call subtracts a zero it cannot see is zero), so the same sign.
inline int orient_about_origin(const Vec2& p, const Vec2& q) noexcept {
  const int sign = certified_sign(p.x() * q.y(), p.y() * q.x());
  return sign != 0 ? sign : orient2d_exact(p, q, Vec2(0, 0));
}

inline Real cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace mink::detail
