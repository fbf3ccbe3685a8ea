#include "mink/narrowphase/gjk_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pair_frame.hpp"

namespace mink {

namespace {

using detail::cross;

// Barycentric weights of the simplex's point nearest the origin, after dropping the vertices
// not needed to express it (Voronoi regions of the segment or triangle).
struct Reduced {
  detail::LocalSimplex simplex;
  std::array<Real, 3> weight{};
};

void keep(Reduced& r, const detail::LocalSimplex& s, std::initializer_list<int> which,
          std::initializer_list<Real> weights) {
  r.simplex.count = 0;
  Real sum = 0;
  for (Real w : weights) sum += w;
  auto w = weights.begin();
  for (int i : which) {
    r.simplex.vertices[static_cast<std::size_t>(r.simplex.count)] =
        s.vertices[static_cast<std::size_t>(i)];
    r.weight[static_cast<std::size_t>(r.simplex.count)] = *w++ / sum;
    ++r.simplex.count;
  }
}

Reduced reduce(const detail::LocalSimplex& s) {
  Reduced r;
  const Vec2& w1 = s.vertices[0].point;
  if (s.count == 1) {
    keep(r, s, {0}, {1});
    return r;
  }
  const Vec2& w2 = s.vertices[1].point;
  const Vec2 e12 = w2 - w1;
  const Real d12_1 = w2.dot(e12);
  const Real d12_2 = -w1.dot(e12);
  if (s.count == 2) {
    if (d12_2 <= 0) {
      keep(r, s, {0}, {1});
    } else if (d12_1 <= 0) {
      keep(r, s, {1}, {1});
    } else {
      keep(r, s, {0, 1}, {d12_1, d12_2});
    }
    return r;
  }
  const Vec2& w3 = s.vertices[2].point;
  const Vec2 e13 = w3 - w1;
  const Real d13_1 = w3.dot(e13);
  const Real d13_2 = -w1.dot(e13);
  const Vec2 e23 = w3 - w2;
  const Real d23_1 = w3.dot(e23);
  const Real d23_2 = -w2.dot(e23);
  const Real n123 = cross(e12, e13);
  const Real d123_1 = n123 * cross(w2, w3);
  const Real d123_2 = n123 * cross(w3, w1);
  const Real d123_3 = n123 * cross(w1, w2);
  if (d12_2 <= 0 && d13_2 <= 0) {
    keep(r, s, {0}, {1});
  } else if (d12_1 > 0 && d12_2 > 0 && d123_3 <= 0) {
    keep(r, s, {0, 1}, {d12_1, d12_2});
  } else if (d13_1 > 0 && d13_2 > 0 && d123_2 <= 0) {
    keep(r, s, {0, 2}, {d13_1, d13_2});
  } else if (d12_1 <= 0 && d23_2 <= 0) {
    keep(r, s, {1}, {1});
  } else if (d13_1 <= 0 && d23_1 <= 0) {
    keep(r, s, {2}, {1});
  } else if (d23_1 > 0 && d23_2 > 0 && d123_1 <= 0) {
    keep(r, s, {1, 2}, {d23_1, d23_2});
  } else if (d123_1 + d123_2 + d123_3 > 0) {
    keep(r, s, {0, 1, 2}, {d123_1, d123_2, d123_3});
  } else {
    // A flat triangle that no region claimed (rounding): keep its vertex nearest the origin.
    int nearest = 0;
    for (int i = 1; i < 3; ++i) {
      if (s.vertices[static_cast<std::size_t>(i)].point.squaredNorm() <
          s.vertices[static_cast<std::size_t>(nearest)].point.squaredNorm()) {
        nearest = i;
      }
    }
    keep(r, s, {nearest}, {1});
  }
  return r;
}

// The weighted sum of what `at` gives for each vertex of the reduced simplex.
template <typename At>
Vec2 combine(const Reduced& r, At at) {
  Vec2 sum(0, 0);
  for (int i = 0; i < r.simplex.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sum += r.weight[k] * at(r.simplex.vertices[k]);
  }
  return sum;
}

// Start from the cached vertex pairs when they are still valid indices, else from the support
// point along the centroid direction.
detail::LocalSimplex initial_simplex(const detail::PairFrame& frame, const SimplexCache* cache) {
  detail::LocalSimplex s;
  if (cache != nullptr && cache->count > 0 && cache->count <= 3) {
    for (int i = 0; i < cache->count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const std::uint32_t ia = cache->index_a[k];
      const std::uint32_t ib = cache->index_b[k];
      if (ia >= frame.a().size() || ib >= frame.b().size()) return initial_simplex(frame, nullptr);
      bool repeated = false;
      for (int j = 0; j < s.count; ++j) {
        const detail::LocalVertex& v = s.vertices[static_cast<std::size_t>(j)];
        repeated = repeated || (v.index_a == ia && v.index_b == ib);
      }
      if (!repeated) s.vertices[static_cast<std::size_t>(s.count++)] = frame.vertex(ia, ib);
    }
    return s;
  }
  Vec2 d = frame.relative().apply(frame.b().centroid()) - frame.a().centroid();
  if (d.x() == 0 && d.y() == 0) d = Vec2(1, 0);
  s.vertices[0] = frame.support(detail::rescaled_direction(d));
  s.count = 1;
  return s;
}

}  // namespace

DistanceResult gjk_distance(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                            const Pose& pose_b, SimplexCache* cache) {
  const detail::PairFrame frame(a, pose_a, b, pose_b);
  DistanceResult result;
  detail::LocalSimplex s = initial_simplex(frame, cache);
  // A cold start took one support point; cached vertices cost none.
  result.iterations = cache != nullptr && cache->count > 0 ? 0 : 1;
  Reduced r;
  const int cap = static_cast<int>(2 * (a.size() + b.size())) + 16;
  bool overlap = false;
  for (;;) {
    r = reduce(s);
    s = r.simplex;
    if (s.count == 3) {
      overlap = true;
      break;
    }
    // Search direction: towards the origin, perpendicular to a segment (more accurate than
    // negating the nearest point, which has lost digits to cancellation).
    Vec2 d;
    if (s.count == 2) {
      const Vec2& p = s.vertices[0].point;
      const Vec2 e = s.vertices[1].point - p;
      const Real side = cross(e, -p);
      if (side == 0) {
        overlap = true;  // the origin is on the segment
        break;
      }
      d = side > 0 ? Vec2(-e.y(), e.x()) : Vec2(e.y(), -e.x());
    } else {
      d = -s.vertices[0].point;
      if (d.x() == 0 && d.y() == 0) {
        overlap = true;  // the origin is a vertex of A - B
        break;
      }
    }
    if (result.iterations >= cap) {
      result.reached_iteration_cap = true;
      break;
    }
    d = detail::rescaled_direction(d);
    const detail::LocalVertex w = frame.support(d);
    ++result.iterations;
    bool repeated = false;
    for (int i = 0; i < s.count; ++i) {
      const detail::LocalVertex& v = s.vertices[static_cast<std::size_t>(i)];
      repeated = repeated || (v.index_a == w.index_a && v.index_b == w.index_b);
    }
    if (repeated) break;
    // No progress along d (the new vertex is no closer than the simplex): converged.
    const Real simplex_extent = s.vertices[0].point.dot(d);
    if (w.point.dot(d) - simplex_extent <= 1e-15 * std::abs(simplex_extent)) break;
    s.vertices[static_cast<std::size_t>(s.count++)] = w;
  }

  const Vec2 local_a =
      combine(r, [&](const detail::LocalVertex& v) { return Vec2(a.vertices()[v.index_a]); });
  const Vec2 local_b =
      combine(r, [&](const detail::LocalVertex& v) { return frame.b_vertex(v.index_b); });
  result.overlap = overlap;
  result.point_a = pose_a.apply(local_a);
  result.point_b = pose_a.apply(local_b);
  if (!overlap) {
    const Vec2 p = combine(r, [](const detail::LocalVertex& v) { return v.point; });
    Vec2 gap = -p;
    if (s.count == 2) {
      // Distance to the segment's line: exact up to one rounding per operation, whereas |p|
      // carries the weights' cancellation.
      const Vec2 e = s.vertices[1].point - s.vertices[0].point;
      const Vec2 n = detail::rescaled_direction(Vec2(e.y(), -e.x())).normalized();
      const Real signed_gap = -n.dot(s.vertices[0].point);
      gap = signed_gap * n;
    }
    result.distance = gap.norm();
    if (result.distance > 0) {
      result.normal = pose_a.rotation.apply(gap / result.distance);
    } else {
      result.overlap = true;
    }
  }
  result.simplex = detail::PairFrame::indices(s);
  if (cache != nullptr) *cache = result.simplex;
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
        const Real d = gap.norm();
        if (d < best.distance) {
          best.distance = d;
          const Vec2 u = d > 0 ? Vec2(gap / d) : Vec2(0, 0);
          best.normal = pass == 0 ? Vec2(-u) : u;  // v on A: from B's point to A's
        }
      }
    }
  }
  return best;
}

}  // namespace mink
