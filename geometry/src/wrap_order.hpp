#pragma once

// The order gift wrapping (Jarvis, Chan) walks by: seen from a hull vertex p, every other point
// lies in a cone narrower than a half-turn, so "more clockwise, then farther along the same
// ray" is a strict total order on distinct points, decided exactly.

#include "mink/geometry/orientation.hpp"

namespace mink::detail {

// For a and b on one ray from p (collinear, same side): is a farther from p than b? Decided
// by coordinate comparisons alone, so it is exact.
inline bool farther_on_ray(const Vec2& p, const Vec2& a, const Vec2& b) noexcept {
  if (a.x() != p.x()) return a.x() > p.x() ? a.x() > b.x() : a.x() < b.x();
  return a.y() > p.y() ? a.y() > b.y() : a.y() < b.y();
}

// Should the wrap from p prefer a over b as the next hull vertex? True when b lies left of the
// line p->a, or on it and nearer than a. Neither a nor b may equal p.
inline bool wraps_before(const Vec2& p, const Vec2& a, const Vec2& b) noexcept {
  const int turn = orient2d(p, a, b);
  if (turn != 0) return turn > 0;
  return farther_on_ray(p, a, b);
}

}  // namespace mink::detail
