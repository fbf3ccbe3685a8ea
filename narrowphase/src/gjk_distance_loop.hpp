#pragma once

// The GJK distance loop, written once for any pair of cores: PairFrame (two prepared hulls,
// the engine's hot path) and CoreFrame (points, segments and hulls of the other shape kinds)
// instantiate it, so the hull path keeps its inlined support scans and pays nothing for the
// generality. The functions have internal linkage (static), as they had in one source file:
// each caller's copy is then called once and inlined whole.

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "mink/narrowphase/simplex.hpp"
#include "pair_frame.hpp"

namespace mink::detail {

// Barycentric weights of the simplex's point nearest the origin, after dropping the vertices
// not needed to express it (Voronoi regions of the segment or triangle).
struct Reduced {
  LocalSimplex simplex;
  std::array<Real, 3> weight{};
};

static inline void keep(Reduced& r, const LocalSimplex& s, std::initializer_list<int> which,
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

static inline Reduced reduce(const LocalSimplex& s) {
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
static Vec2 combine(const Reduced& r, At at) {
  Vec2 sum(0, 0);
  for (int i = 0; i < r.simplex.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sum += r.weight[k] * at(r.simplex.vertices[k]);
  }
  return sum;
}

// Start from the cached vertex pairs when they are still valid indices, else from the support
// point along the centre-to-centre direction (eq. 2).
template <typename Frame>
static LocalSimplex initial_simplex(const Frame& frame, const SimplexCache* cache) {
  LocalSimplex s;
  if (cache != nullptr && cache->count > 0 && cache->count <= 3) {
    for (int i = 0; i < cache->count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const std::uint32_t ia = cache->index_a[k];
      const std::uint32_t ib = cache->index_b[k];
      if (ia >= frame.a_count() || ib >= frame.b_count()) return initial_simplex(frame, nullptr);
      bool repeated = false;
      for (int j = 0; j < s.count; ++j) {
        const LocalVertex& v = s.vertices[static_cast<std::size_t>(j)];
        repeated = repeated || (v.index_a == ia && v.index_b == ib);
      }
      if (!repeated) s.vertices[static_cast<std::size_t>(s.count++)] = frame.vertex(ia, ib);
    }
    return s;
  }
  Vec2 d = frame.initial_direction();
  if (d.x() == 0 && d.y() == 0) d = Vec2(1, 0);
  s.vertices[0] = frame.support(rescaled_direction(d));
  s.count = 1;
  return s;
}

// What the loop finds, in A's local frame.
struct LocalDistance {
  bool overlap = false;
  Real distance = 0;
  Vec2 point_a{0, 0};  // nearest point of A's core
  Vec2 point_b{0, 0};  // nearest point of B's core
  Vec2 gap{0, 0};      // point_b - point_a, recomputed accurately; length `distance`
  int iterations = 0;
  bool reached_iteration_cap = false;
  SimplexCache simplex;
};

// GJK distance on A - B in A's frame by Voronoi-region simplex reduction. Always terminates:
// stops on a repeated vertex, on no progress, or at an iteration cap.
template <typename Frame>
static LocalDistance distance_loop(const Frame& frame, SimplexCache* cache) {
  LocalDistance result;
  LocalSimplex s = initial_simplex(frame, cache);
  // A cold start took one support point; cached vertices cost none.
  result.iterations = cache != nullptr && cache->count > 0 ? 0 : 1;
  Reduced r{};
  const int cap = static_cast<int>(2 * (frame.a_count() + frame.b_count())) + 16;
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
    d = rescaled_direction(d);
    const LocalVertex w = frame.support(d);
    ++result.iterations;
    bool repeated = false;
    for (int i = 0; i < s.count; ++i) {
      const LocalVertex& v = s.vertices[static_cast<std::size_t>(i)];
      repeated = repeated || (v.index_a == w.index_a && v.index_b == w.index_b);
    }
    if (repeated) break;
    // No progress along d (the new vertex is no closer than the simplex): converged.
    const Real simplex_extent = s.vertices[0].point.dot(d);
    if (w.point.dot(d) - simplex_extent <= 1e-15 * std::abs(simplex_extent)) break;
    s.vertices[static_cast<std::size_t>(s.count++)] = w;
  }

  result.point_a = combine(r, [&](const LocalVertex& v) { return frame.a_vertex(v.index_a); });
  result.point_b = combine(r, [&](const LocalVertex& v) { return frame.b_vertex(v.index_b); });
  result.overlap = overlap;
  if (!overlap) {
    const Vec2 p = combine(r, [](const LocalVertex& v) { return v.point; });
    Vec2 gap = -p;
    if (s.count == 2) {
      // Distance to the segment's line: exact up to one rounding per operation, whereas |p|
      // carries the weights' cancellation.
      const Vec2 e = s.vertices[1].point - s.vertices[0].point;
      const Vec2 n = rescaled_direction(Vec2(e.y(), -e.x())).normalized();
      const Real signed_gap = -n.dot(s.vertices[0].point);
      gap = signed_gap * n;
    }
    result.gap = gap;
    result.distance = rescaled_norm(gap);
    if (!(result.distance > 0)) result.overlap = true;
  }
  result.simplex = PairFrame::indices(s);
  if (cache != nullptr) *cache = result.simplex;
  return result;
}

}  // namespace mink::detail
