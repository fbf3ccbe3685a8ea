#include "mink/narrowphase/minkowski_difference.hpp"

#include <algorithm>

#include "mink/error.hpp"

namespace mink {

namespace {

// Lowest y, then lowest x: from there every edge angle of a CCW polygon lies in [0, 2 pi) and
// increases, so the two sequences merge like sorted lists.
std::size_t bottom_vertex(std::span<const Vec2> p, Real sign) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const Vec2 q = sign * p[i];
    const Vec2 r = sign * p[best];
    if (q.y() < r.y() || (q.y() == r.y() && q.x() < r.x())) best = i;
  }
  return best;
}

}  // namespace

std::vector<Vec2> minkowski_difference(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (a.size() < 3 || b.size() < 3) {
    throw InvalidArgumentError("minkowski_difference: each polygon needs at least 3 vertices");
  }
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  // -B is B turned by 180 degrees: still counter-clockwise, vertex order unchanged.
  const std::size_t a0 = bottom_vertex(a, 1);
  const std::size_t b0 = bottom_vertex(b, -1);
  auto a_at = [&](std::size_t k) { return a[(a0 + k) % n]; };
  auto nb_at = [&](std::size_t k) { return Vec2(-b[(b0 + k) % m]); };
  std::vector<Vec2> result;
  result.reserve(n + m);
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < n || j < m) {
    result.push_back(a_at(i) + nb_at(j));
    if (i == n) {
      ++j;
      continue;
    }
    if (j == m) {
      ++i;
      continue;
    }
    const Real angle_a = pseudo_angle(a_at(i + 1) - a_at(i));
    const Real angle_b = pseudo_angle(nb_at(j + 1) - nb_at(j));
    if (angle_a <= angle_b) ++i;
    if (angle_b <= angle_a) ++j;
  }
  return result;
}

std::vector<Vec2> minkowski_difference(const PreparedHull& a, const Pose& pose_a,
                                       const PreparedHull& b, const Pose& pose_b) {
  std::vector<Vec2> world_a;
  std::vector<Vec2> world_b;
  for (const Vec2& v : a.vertices()) world_a.push_back(pose_a.apply(v));
  for (const Vec2& v : b.vertices()) world_b.push_back(pose_b.apply(v));
  return minkowski_difference(world_a, world_b);
}

}  // namespace mink
