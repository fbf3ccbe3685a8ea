#pragma once

#include <cmath>

#include "mink/engine/body_def.hpp"

namespace mink::detail {

// Where a scene lies must not change how it moves (position_grid_step in body_def.hpp). A
// double 10^7 m out is 1.9e-9 m from the next one, at 1 m it is 2.2e-16 m: adding the same
// motion to both rounds differently, and a settling stack turns that last bit into
// millimetres. So every offset added to a position (a step's motion, a centre of mass from its
// body's origin, a contact point from the body it is measured from) is first rounded to the
// grid: a position on the grid then stays on it, each addition is exact, and everything else
// the step computes from differences of positions, which are exact too.
inline constexpr Real kGridStep = position_grid_step;

// `offset` rounded to the nearest multiple of kGridStep. Adding and taking away 1.5 * 2^23
// (whose doubles are kGridStep apart) rounds it, exactly, for offsets within 2^22 m; a longer
// one (no step moves a body that far) is left as it is.
inline Real on_grid(Real offset) {
  constexpr Real kRounder = 0x1.8p23;
  static_assert(kGridStep == 0x1p-29, "kRounder's doubles (from 2^23 to 2^24) are 2^-29 apart");
  if (!(std::abs(offset) < 0x1p22)) return offset;
  return (offset + kRounder) - kRounder;
}

inline Vec2 on_grid(const Vec2& offset) {
  return {on_grid(offset.x()), on_grid(offset.y())};
}

}  // namespace mink::detail
