#include "mink/narrowphase/support.hpp"

#include <algorithm>

namespace mink {

std::size_t support_index_climb(const PreparedHull& hull, const Vec2& direction,
                                std::size_t start) noexcept {
  const std::span<const Vec2> v = hull.vertices();
  const std::size_t n = v.size();
  std::size_t best = start;
  Real best_value = v[best].dot(direction);
  // On a convex polygon the dot products rise to the maximum and fall after it, so one
  // uphill neighbour fixes the walking direction.
  const std::size_t next = best + 1 == n ? 0 : best + 1;
  const std::size_t prev = best == 0 ? n - 1 : best - 1;
  const Real next_value = v[next].dot(direction);
  const Real prev_value = v[prev].dot(direction);
  const bool forward = next_value > best_value;
  if (!forward && !(prev_value > best_value)) return best;
  for (std::size_t steps = 0; steps < n; ++steps) {
    const std::size_t candidate =
        forward ? (best + 1 == n ? 0 : best + 1) : (best == 0 ? n - 1 : best - 1);
    const Real value = v[candidate].dot(direction);
    if (!(value > best_value)) break;
    best = candidate;
    best_value = value;
  }
  return best;
}

std::size_t support_index_binary(const PreparedHull& hull, const Vec2& direction) noexcept {
  // Vertex i is extreme for every direction between the normals of edges i - 1 and i, so the
  // answer is the start of the first edge whose normal angle is not below the direction's.
  const std::span<const Real> angles = hull.sorted_normal_angles();
  const std::size_t n = angles.size();
  const std::size_t k = static_cast<std::size_t>(
      std::lower_bound(angles.begin(), angles.end(), pseudo_angle(direction)) - angles.begin());
  const std::size_t index = (hull.first_normal() + (k == n ? 0 : k)) % n;
  return support_index_climb(hull, direction, index);
}

}  // namespace mink
