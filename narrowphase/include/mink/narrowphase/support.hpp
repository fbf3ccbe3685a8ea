#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink {

/// @file
/// @brief Support mapping (paper section 5, eq. 4): the vertex of a hull farthest along a
/// direction.
///
/// Directions are in the hull's local frame unless a Pose is given. Ties go to the lowest index
/// in the linear scan; the faster searches return a vertex with the same dot product.

/// @brief Hulls up to this many vertices are scanned; larger ones are searched in O(log n).
inline constexpr std::size_t kLinearSupportLimit = 16;

#if defined(__SSE2__)
namespace detail {
/// The first of 8 points (x and y arrays) farthest along `direction`, in one straight block of
/// two-wide instructions with a branch-free winner: hulls of up to 8 vertices (boxes,
/// Box2D-sized polygons), padded with copies of their first vertex. xs and ys must be 16-byte
/// aligned (PreparedHull's arrays are).
inline std::size_t support_block(const Real* xs, const Real* ys, const Vec2& direction) noexcept {
  const __m128d dx = _mm_set1_pd(direction.x());
  const __m128d dy = _mm_set1_pd(direction.y());
  // Aligned loads (xs and ys are 16-byte aligned), so they fold into the multiplies.
  auto values = [&](std::size_t i) {
    return _mm_add_pd(_mm_mul_pd(_mm_load_pd(xs + i), dx), _mm_mul_pd(_mm_load_pd(ys + i), dy));
  };
  const __m128d v0 = values(0);
  const __m128d v1 = values(2);
  const __m128d v2 = values(4);
  const __m128d v3 = values(6);
  __m128d top = _mm_max_pd(_mm_max_pd(v0, v1), _mm_max_pd(v2, v3));
  top = _mm_max_pd(top, _mm_shuffle_pd(top, top, 1));
  // The four all-ones-or-zero comparison masks narrowed into one byte mask, two bits a vertex.
  const __m128i low = _mm_packs_epi32(_mm_castpd_si128(_mm_cmpeq_pd(v0, top)),
                                      _mm_castpd_si128(_mm_cmpeq_pd(v1, top)));
  const __m128i high = _mm_packs_epi32(_mm_castpd_si128(_mm_cmpeq_pd(v2, top)),
                                       _mm_castpd_si128(_mm_cmpeq_pd(v3, top)));
  const int reached = _mm_movemask_epi8(_mm_packs_epi16(low, high));
  // A NaN direction or coordinate matches no vertex: the bit past the block then gives 8, which
  // the mask turns into the first vertex (no branch on the search's hot path).
  const unsigned bits = static_cast<unsigned>(reached) | (1u << 16);
  return (static_cast<std::size_t>(std::countr_zero(bits)) / 2) & (kSupportBlock - 1);
}

/// A pose broadcast to both lanes, to map x/y arrays two points at a time. The same operations
/// in the same order as Pose::apply, so the same values as mapping the points one by one.
class PoseLanes {
 public:
  explicit PoseLanes(const Pose& pose) noexcept
      : c_(_mm_set1_pd(pose.rotation.cos)),
        s_(_mm_set1_pd(pose.rotation.sin)),
        tx_(_mm_set1_pd(pose.position.x())),
        ty_(_mm_set1_pd(pose.position.y())) {}

  /// Maps (xs[0], ys[0]) and (xs[1], ys[1]) into x and y. xs and ys must be 16-byte aligned.
  void apply(const Real* xs, const Real* ys, __m128d& x, __m128d& y) const noexcept {
    const __m128d px = _mm_load_pd(xs);
    const __m128d py = _mm_load_pd(ys);
    x = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(c_, px), _mm_mul_pd(s_, py)), tx_);
    y = _mm_add_pd(_mm_add_pd(_mm_mul_pd(s_, px), _mm_mul_pd(c_, py)), ty_);
  }

 private:
  __m128d c_, s_, tx_, ty_;
};
}  // namespace detail
#endif

/// Every vertex, first maximum wins: the obviously-correct twin of the searches below, and
/// the fastest way for small hulls. Inline, so GJK's loop keeps the direction in registers. With
/// SSE2 it takes two vertices per instruction: one pass for the largest dot product, one for
/// the first vertex that reaches it (the same products, so the same values, as the scalar
/// loop).
/// @param hull the hull to search
/// @param direction local frame; need not be unit
/// @return index into hull.vertices()
inline std::size_t support_index_linear(const PreparedHull& hull, const Vec2& direction) noexcept {
  const Real* xs = hull.xs();
  const Real* ys = hull.ys();
  const std::size_t n = hull.padded_size();
#if defined(__SSE2__)
  const __m128d dx = _mm_set1_pd(direction.x());
  const __m128d dy = _mm_set1_pd(direction.y());
  auto values = [&](std::size_t i) {
    return _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(xs + i), dx), _mm_mul_pd(_mm_loadu_pd(ys + i), dy));
  };
  if (n == kSupportBlock) return detail::support_block(xs, ys, direction);
  __m128d best = values(0);
  for (std::size_t i = 2; i < n; i += 2) best = _mm_max_pd(best, values(i));
  best = _mm_max_pd(best, _mm_shuffle_pd(best, best, 1));
  if (n <= 64) {
    // Which vertices reach the maximum, as one bit mask built without data-dependent branches
    // (a mispredicted early exit costs more than the whole scan of a small hull).
    std::uint64_t reached = 0;
    for (std::size_t i = 0; i < n; i += 2) {
      reached |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmpeq_pd(values(i), best))) << i;
    }
    return reached == 0 ? 0 : static_cast<std::size_t>(std::countr_zero(reached));
  }
  for (std::size_t i = 0; i < n; i += 2) {
    const int mask = _mm_movemask_pd(_mm_cmpeq_pd(values(i), best));
    if (mask != 0) return i + ((mask & 1) != 0 ? 0 : 1);
  }
  return 0;  // a NaN matches no vertex (as in support_block)
#else
  const Real dx = direction.x();
  const Real dy = direction.y();
  std::size_t best = 0;
  Real best_value = xs[0] * dx + ys[0] * dy;
  for (std::size_t i = 1; i < n; ++i) {
    const Real value = xs[i] * dx + ys[i] * dy;
    if (value > best_value) {
      best = i;
      best_value = value;
    }
  }
  return best;  // a padding copy of vertex 0 never beats vertex 0 itself
#endif
}

/// Binary search of the direction's pseudo-angle among the sorted edge-normal angles, then a
/// short climb to absorb rounding in the pseudo-angles. O(log n).
std::size_t support_index_binary(const PreparedHull& hull, const Vec2& direction) noexcept;

/// Hill climbing from `start` (the previous answer): O(1) when the direction changed little,
/// O(n) at worst.
std::size_t support_index_climb(const PreparedHull& hull, const Vec2& direction,
                                std::size_t start) noexcept;

/// @brief Support vertex index along a local direction: linear scan for small hulls, binary search
/// for large ones.
inline std::size_t support_index(const PreparedHull& hull, const Vec2& direction) noexcept {
  return hull.size() <= kLinearSupportLimit ? support_index_linear(hull, direction)
                                            : support_index_binary(hull, direction);
}

/// @brief The support vertex of the posed hull along a world direction, in world coordinates.
inline Vec2 support_point(const PreparedHull& hull, const Pose& pose, const Vec2& direction) {
  return pose.apply(hull.vertices()[support_index(hull, pose.rotation.apply_inverse(direction))]);
}

}  // namespace mink
