#pragma once

#include <cmath>
#include <span>

#include "mink/geometry/types.hpp"

namespace mink {

namespace detail {
/// Exact sign of det[b - a, c - a] for any finite doubles: floating-point expansions when no
/// product underflows or overflows, big-integer arithmetic otherwise.
int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
/// The same sign by big-integer arithmetic alone: slow, obviously exact, the test oracle.
int orient2d_big_integer(const Vec2& a, const Vec2& b, const Vec2& c) noexcept;
}  // namespace detail

namespace detail {
/// The sign of det_left - det_right, for two rounded products of rounded differences, when
/// the floating-point error bound certifies it; 0 when it cannot.
///
/// Shewchuk's stage-A bound (3 + 16 eps) eps with eps = 2^-53, widened by 2^-100 to absorb
/// underflow in the products, which a sum of magnitudes >= 2^-900 keeps below that margin.
/// Overflowed or tiny magnitudes fail the range test.
inline int certified_sign(Real det_left, Real det_right) noexcept {
  const Real det = det_left - det_right;
  const Real det_sum = std::abs(det_left) + std::abs(det_right);
  constexpr Real kRelativeBound = 3.3306690738754716e-16 + 7.888609052210118e-31;
  constexpr Real kSmallestSafeSum = 0x1p-900;
  constexpr Real kLargestSafeSum = 0x1p+1000;
  if (det_sum >= kSmallestSafeSum && det_sum <= kLargestSafeSum &&
      std::abs(det) > kRelativeBound * det_sum) {
    return det > 0 ? 1 : -1;
  }
  return 0;
}
}  // namespace detail

/// @brief Sign of the turn a -> b -> c.
/// @return +1 when c lies strictly left of the directed line a->b (counter-clockwise), -1 when
/// strictly right, 0 when the three points are collinear.
///
/// The sign is exact for all finite inputs: a floating-point filter answers when its error
/// bound allows, otherwise the determinant is evaluated exactly.
inline int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const int sign =
      detail::certified_sign((a.x() - c.x()) * (b.y() - c.y()), (a.y() - c.y()) * (b.x() - c.x()));
  return sign != 0 ? sign : detail::orient2d_exact(a, b, c);
}

/// The plain floating-point determinant, with no guarantee on its sign. Tests use it to show
/// where the filter matters.
inline Real orient2d_naive(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// Whether the points lie on one line, decided exactly; true for fewer than three distinct
/// points.
bool all_on_one_line(std::span<const Vec2> points) noexcept;

/// Lexicographic order on (x, y), the order every hull in Minkowski starts from.
inline bool lex_less(const Vec2& p, const Vec2& q) noexcept {
  return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
}

}  // namespace mink
