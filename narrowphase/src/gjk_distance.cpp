#include "mink/narrowphase/gjk_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gjk_distance_loop.hpp"
#include "pair_frame.hpp"

namespace mink {

DistanceResult gjk_distance(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                            const Pose& pose_b, SimplexCache* cache) {
  const detail::PairFrame frame(a, pose_a, b, pose_b);
  const detail::LocalDistance local = detail::distance_loop(frame, cache);
  DistanceResult result;
  result.overlap = local.overlap;
  result.iterations = local.iterations;
  result.reached_iteration_cap = local.reached_iteration_cap;
  result.point_a = pose_a.apply(local.point_a);
  result.point_b = pose_a.apply(local.point_b);
  if (!local.overlap) {
    result.distance = local.distance;
    result.normal = pose_a.rotation.apply(detail::rescaled_unit(local.gap));
  }
  result.simplex = local.simplex;
  return result;
}

BruteDistance hull_distance_brute(std::span<const Vec2> a, std::span<const Vec2> b) {
  BruteDistance best{std::numeric_limits<Real>::infinity(), Vec2(0, 0)};
  for (int pass = 0; pass < 2; ++pass) {
    const std::span<const Vec2> p = pass == 0 ? a : b;
    const std::span<const Vec2> q = pass == 0 ? b : a;
    for (const Vec2& v : p) {
      for (std::size_t i = 0; i < q.size(); ++i) {
        const Vec2& s0 = q[i];
        const Vec2 e = q[(i + 1) % q.size()] - s0;
        const Real len2 = e.squaredNorm();
        const Real t = len2 > 0 ? std::clamp((v - s0).dot(e) / len2, Real(0), Real(1)) : 0;
        const Vec2 gap = v - (s0 + t * e);  // from q's nearest point to v
        const Real d = detail::rescaled_norm(gap);
        if (d < best.distance) {
          best.distance = d;
          const Vec2 u = d > 0 ? detail::rescaled_unit(gap) : Vec2(0, 0);
          best.normal = pass == 0 ? Vec2(-u) : u;  // v on A: from B's point to A's
        }
      }
    }
  }
  return best;
}

}  // namespace mink
