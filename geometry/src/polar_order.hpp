#pragma once

// The polar order about a hull's lowest (x, y) point that Graham's scan walks, shared by
// graham.cpp and chan.cpp: a cheap floating-point key, the bound on its rounding, and the exact
// comparison that settles what the keys cannot.

#include <cmath>

#include "mink/geometry/orientation.hpp"

namespace mink::detail {

// A pseudo-angle of p seen from the pivot: strictly increasing with the true angle on
// (-90, 90] degrees, computed with relative error below 6 ulps (plus 2^-1000 absolute, for
// underflow) while the differences stay finite. NaN for the pivot itself.
inline Real pseudo_angle(const Vec2& pivot, const Vec2& p) noexcept {
  const Real dx = p.x() - pivot.x();
  const Real dy = p.y() - pivot.y();
  return dy / (dx + std::abs(dy));
}

// Do the differences stay far enough from overflow for pseudo_angle's error bound to hold?
inline bool pseudo_angle_reliable(const Vec2& pivot, const Vec2& p) noexcept {
  return p.x() - pivot.x() < 0x1p+1000 && std::abs(p.y() - pivot.y()) < 0x1p+1000;
}

// Could rounding have put these two keys (in this order) the wrong way round?
inline bool keys_indistinct(Real earlier, Real later) noexcept {
  constexpr Real kRelativeTolerance = 1e-15;
  constexpr Real kAbsoluteTolerance = 0x1p-1000;
  return later - earlier <=
         kRelativeTolerance * (std::abs(later) + std::abs(earlier)) + kAbsoluteTolerance;
}

// The exact polar order: every other point lies right of or straight above the pivot, a range
// of directions narrower than a half-turn, so orientation is a strict weak order on them.
// Points on one ray from the pivot go nearest first; along such a ray (x, y) order is
// distance order.
inline bool polar_precedes(const Vec2& pivot, const Vec2& a, const Vec2& b) noexcept {
  const int turn = orient2d(pivot, a, b);
  if (turn != 0) return turn > 0;
  return lex_less(a, b);
}

// The same order for two points with their keys: the keys decide where their rounding cannot
// have reversed them, the exact test elsewhere.
inline bool polar_precedes(const Vec2& pivot, const Vec2& a, Real key_a, const Vec2& b,
                           Real key_b) noexcept {
  if (!keys_indistinct(key_a, key_b)) return true;
  if (!keys_indistinct(key_b, key_a)) return false;
  return polar_precedes(pivot, a, b);
}

}  // namespace mink::detail
