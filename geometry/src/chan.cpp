#include "mink/geometry/chan.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "mink/geometry/graham.hpp"
#include "mink/geometry/hull_input.hpp"
#include "wrap_order.hpp"

namespace mink {

namespace {

// The group hulls of one round: ring g is vertices[offsets[g] .. offsets[g + 1]), CCW,
// starting at its lowest (x, y) vertex; 1 or 2 vertices when the group is degenerate.
struct GroupHulls {
  std::vector<Vec2> vertices;
  std::vector<std::size_t> offsets;

  std::size_t count() const { return offsets.size() - 1; }
  std::span<const Vec2> ring(std::size_t g) const {
    return std::span<const Vec2>(vertices).subspan(offsets[g], offsets[g + 1] - offsets[g]);
  }
};

// Index of the vertex of `ring` the wrap from p goes to: every vertex on its left or on its
// line, the farthest on the line. p must lie outside the ring (not be one of its vertices).
//
// Seen from p the vertices' wrap order (detail::wraps_before) is cyclically bitonic along a
// strictly convex ring, with one minimum: the answer. The previous answer is usually at or just
// before the new one, so a few steps from `hint` settle most queries; otherwise a binary search
// on the bitonic sequence takes O(log m) orientation tests.
std::size_t tangent_index(const Vec2& p, std::span<const Vec2> ring, std::size_t hint) {
  const std::size_t size = ring.size();
  const auto before = [&](std::size_t a, std::size_t b) {
    return detail::wraps_before(p, ring[a], ring[b]);
  };
  if (size <= 3) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < size; ++i) {
      if (before(i, best)) best = i;
    }
    return best;
  }
  const auto next = [size](std::size_t i) { return i + 1 == size ? 0 : i + 1; };
  const auto is_answer = [&](std::size_t i) {
    return before(i, next(i)) && before(i, i == 0 ? size - 1 : i - 1);
  };

  const std::size_t walk_limit = std::bit_width(size);
  std::size_t i = hint;
  for (std::size_t step = 0; step < walk_limit; ++step, i = next(i)) {
    if (is_answer(i)) return i;
  }

  if (is_answer(0)) return 0;
  // "c is at or past the answer" is monotone over c in [1, size - 1]; its form depends on
  // whether the sequence rises or falls after vertex 0.
  const bool rises_at_0 = before(0, 1);
  const auto at_or_past = [&](std::size_t c) {
    const bool rises = before(c, next(c));
    return rises_at_0 ? (rises && before(c, 0)) : (rises || before(0, c));
  };
  std::size_t lo = 1;
  std::size_t hi = size - 1;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (at_or_past(mid)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo;
}

// A sum x + y held exactly as the rounded sum and its rounding error (Knuth's two-sum), so
// that sums compare exactly: rounding is monotone, so a larger rounded sum means a larger
// exact sum, and equal rounded sums are told apart by their errors.
struct ExactSum {
  Real sum;
  Real error;

  ExactSum(Real x, Real y) : sum(x + y) {
    const Real y_part = sum - x;
    error = (x - (sum - y_part)) + (y - y_part);
  }
  bool operator<(const ExactSum& other) const {
    return sum < other.sum || (sum == other.sum && error < other.error);
  }
  bool operator==(const ExactSum& other) const { return sum == other.sum && error == other.error; }
};

// A lower bound on the number of hull vertices: how many distinct points are extreme in the
// eight directions +-x, +-y, +-(x + y), +-(x - y), compared exactly. Among points tied in a
// direction the (x, y)-largest is an end of the tied segment, so every one counted is a hull
// vertex. Returns 0 if a sum overflows.
std::size_t certified_vertex_count(std::span<const Vec2> points) {
  struct Direction {
    Real a, b;  // maximise a x + b y, with a, b in {-1, 0, 1}: products are exact
  };
  constexpr std::array<Direction, 8> kDirections = {
      {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
  std::array<std::size_t, 8> best{};
  bool sums_finite = true;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec2& p = points[i];
    for (std::size_t k = 0; k < kDirections.size(); ++k) {
      const Direction d = kDirections[k];
      const Vec2& q = points[best[k]];
      const ExactSum score(d.a * p.x(), d.b * p.y());
      const ExactSum incumbent(d.a * q.x(), d.b * q.y());
      sums_finite &= std::isfinite(score.sum);
      if (incumbent < score || (incumbent == score && lex_less(q, p))) best[k] = i;
    }
  }
  if (!sums_finite) return 0;
  std::array<Vec2, 8> extremes;
  for (std::size_t k = 0; k < best.size(); ++k) extremes[k] = points[best[k]];
  std::sort(extremes.begin(), extremes.end(), lex_less);
  return static_cast<std::size_t>(std::unique(extremes.begin(), extremes.end()) - extremes.begin());
}

// m = min(2^(2^t), limit) without overflowing.
std::size_t group_size(unsigned t, std::size_t limit) {
  if (t >= 6) return limit;
  const unsigned exponent = 1u << t;
  if (exponent >= 63) return limit;
  return std::min<std::size_t>(std::size_t{1} << exponent, limit);
}

}  // namespace

ConvexHull chan_hull(std::span<const Vec2> points) {
  validate_hull_input(points);
  // Points still in the running: after a round, only vertices of its group hulls, since a
  // point inside any group hull is inside the final one.
  std::vector<Vec2> candidates(points.begin(), points.end());
  detail::GrahamScratch scratch;
  GroupHulls groups;
  std::vector<std::size_t> tangent;
  // A round with fewer wrap steps than known hull vertices cannot close: skip such rounds.
  const std::size_t known_vertices = certified_vertex_count(points);

  for (unsigned t = 1;; ++t) {
    const std::size_t count = candidates.size();
    const std::size_t m = group_size(t, count);
    if (m < known_vertices && m < count) continue;
    groups.vertices.clear();
    groups.vertices.reserve(count);  // a round's hull vertices never outnumber its points
    groups.offsets.assign(1, 0);
    for (std::size_t begin = 0; begin < count; begin += m) {
      const std::size_t length = std::min(m, count - begin);
      detail::graham_scan(std::span<const Vec2>(candidates).subspan(begin, length), scratch,
                          groups.vertices);
      groups.offsets.push_back(groups.vertices.size());
    }
    const std::size_t group_count = groups.count();
    // One group: its Graham hull is the hull, and the wrap would only walk it again.
    if (group_count == 1) return detail::hull_from_ccw_ring(std::move(groups.vertices));

    Vec2 start = groups.ring(0)[0];
    for (std::size_t g = 1; g < group_count; ++g) {
      if (lex_less(groups.ring(g)[0], start)) start = groups.ring(g)[0];
    }
    // Each ring starts at its lowest (x, y) vertex, so a ring holding the start holds it at 0.
    tangent.assign(group_count, 0);

    std::vector<Vec2> hull{start};
    Vec2 current = start;
    bool closed = false;
    const Vec2* vertices = groups.vertices.data();
    const std::size_t* offsets = groups.offsets.data();
    for (std::size_t step = 0; step < m; ++step) {
      const Vec2* best = nullptr;
      for (std::size_t g = 0; g < group_count; ++g) {
        // With many groups each step touches every ring once, far apart in memory: ask for a
        // ring a few groups ahead so its cache line is there when the loop arrives.
        constexpr std::size_t kPrefetchDistance = 8;
        if (g + kPrefetchDistance < group_count) {
          __builtin_prefetch(vertices + offsets[g + kPrefetchDistance] +
                             tangent[g + kPrefetchDistance]);
        }
        const std::span<const Vec2> ring(vertices + offsets[g], offsets[g + 1] - offsets[g]);
        std::size_t candidate = tangent[g];
        if (ring[candidate] == current) {
          // The wrap stands on a vertex of this ring (this group's last answer, or a
          // duplicate of it): the ring's successor is the tangent.
          if (ring.size() == 1) continue;
          candidate = candidate + 1 == ring.size() ? 0 : candidate + 1;
        } else {
          candidate = tangent_index(current, ring, candidate);
        }
        tangent[g] = candidate;
        if (best == nullptr || detail::wraps_before(current, ring[candidate], *best)) {
          best = &ring[candidate];
        }
      }
      const Vec2 next = *best;
      if (next == start) {
        closed = true;
        break;
      }
      hull.push_back(next);
      current = next;
    }
    if (closed) return detail::hull_from_ccw_ring(std::move(hull));
    candidates.swap(groups.vertices);
  }
}

}  // namespace mink
