#pragma once

// Brute-force answers for convex polygons given as CCW world vertices, independent of the
// library's algorithms: plain scans of every vertex-edge pair and every edge normal. Shared by
// the narrowphase tests and the oracle for the `mink` overlap commands.

#include <algorithm>
#include <limits>
#include <span>

#include "mink/geometry/types.hpp"

namespace mink_test {

using mink::Real;
using mink::Vec2;

inline Real point_segment_distance(const Vec2& p, const Vec2& s0, const Vec2& s1) {
  const Vec2 e = s1 - s0;
  const Real len2 = e.squaredNorm();
  const Real t = len2 > 0 ? std::clamp((p - s0).dot(e) / len2, Real(0), Real(1)) : 0;
  return (p - s0 - t * e).norm();
}

// Distance between disjoint convex polygons: the nearest pair always involves a vertex of one
// and an edge of the other.
inline Real scan_distance(std::span<const Vec2> a, std::span<const Vec2> b) {
  Real best = std::numeric_limits<Real>::infinity();
  for (int pass = 0; pass < 2; ++pass) {
    const std::span<const Vec2> p = pass == 0 ? a : b;
    const std::span<const Vec2> q = pass == 0 ? b : a;
    for (const Vec2& v : p) {
      for (std::size_t i = 0; i < q.size(); ++i) {
        best = std::min(best, point_segment_distance(v, q[i], q[(i + 1) % q.size()]));
      }
    }
  }
  return best;
}

struct BruteDepth {
  Real depth;
  Vec2 normal;  // from a towards b
};

// Penetration depth of overlapping convex polygons: the cheapest direction to push b out,
// among the edge normals of both (the only candidates in 2D), scanning every vertex.
inline BruteDepth brute_depth(std::span<const Vec2> a, std::span<const Vec2> b) {
  BruteDepth best{std::numeric_limits<Real>::infinity(), Vec2(0, 0)};
  auto extent = [](std::span<const Vec2> p, const Vec2& u) {
    Real hi = -std::numeric_limits<Real>::infinity();
    for (const Vec2& v : p) hi = std::max(hi, v.dot(u));
    return hi;
  };
  for (int pass = 0; pass < 2; ++pass) {
    const std::span<const Vec2> p = pass == 0 ? a : b;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 e = p[(i + 1) % p.size()] - p[i];
      Vec2 u = Vec2(e.y(), -e.x()).normalized();  // outward normal of p's edge
      if (pass == 1) u = -u;                      // b's outward normal points from b to a
      const Real push = extent(a, u) + extent(b, -u);
      if (push < best.depth) best = {push, u};
    }
  }
  return best;
}

}  // namespace mink_test
