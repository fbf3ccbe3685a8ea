#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "mink/geometry/types.hpp"

namespace mink::detail {

// A point of an incident edge being clipped, with the feature id it will carry.
struct ClipVertex {
  Vec2 point{0, 0};
  std::uint32_t id = 0;
};

// Keeps the part of the segment (or single point) `in` with plane . p - limit <= 0. A
// crossing point is added only for a strict sign change, so a vertex exactly on the side line
// is not duplicated. Shared by the sharp polygon manifold and the cores-with-radii one.
inline int clip(const std::array<ClipVertex, 2>& in, int count_in, std::array<ClipVertex, 2>& out,
                const Vec2& plane, Real limit, std::uint32_t crossing_id) {
  int count = 0;
  if (count_in == 0) return 0;
  const Real d0 = plane.dot(in[0].point) - limit;
  if (d0 <= 0) out[static_cast<std::size_t>(count++)] = in[0];
  if (count_in < 2) return count;
  const Real d1 = plane.dot(in[1].point) - limit;
  if (d1 <= 0) out[static_cast<std::size_t>(count++)] = in[1];
  if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0)) {
    const Real t = d0 / (d0 - d1);
    out[static_cast<std::size_t>(count++)] = {in[0].point + t * (in[1].point - in[0].point),
                                              crossing_id};
  }
  return count;
}

}  // namespace mink::detail
