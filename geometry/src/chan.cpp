#include "mink/geometry/chan.hpp"

#include <algorithm>
#include <bit>
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
  std::vector<Vec2> scratch;
  GroupHulls groups;
  std::vector<std::size_t> tangent;
  std::vector<std::ptrdiff_t> at_vertex;  // index of the current wrap point in ring g, or -1

  for (unsigned t = 1;; ++t) {
    const std::size_t count = candidates.size();
    const std::size_t m = group_size(t, count);
    groups.vertices.clear();
    groups.offsets.assign(1, 0);
    for (std::size_t begin = 0; begin < count; begin += m) {
      const std::size_t length = std::min(m, count - begin);
      detail::graham_scan(std::span<const Vec2>(candidates).subspan(begin, length), scratch,
                          groups.vertices);
      groups.offsets.push_back(groups.vertices.size());
    }
    const std::size_t group_count = groups.count();

    Vec2 start = groups.ring(0)[0];
    for (std::size_t g = 1; g < group_count; ++g) {
      if (lex_less(groups.ring(g)[0], start)) start = groups.ring(g)[0];
    }
    tangent.assign(group_count, 0);
    at_vertex.assign(group_count, -1);
    for (std::size_t g = 0; g < group_count; ++g) {
      if (groups.ring(g)[0] == start) at_vertex[g] = 0;
    }

    std::vector<Vec2> hull{start};
    Vec2 current = start;
    bool closed = false;
    for (std::size_t step = 0; step < m; ++step) {
      const Vec2* best = nullptr;
      for (std::size_t g = 0; g < group_count; ++g) {
        const std::span<const Vec2> ring = groups.ring(g);
        std::size_t candidate;
        if (at_vertex[g] >= 0) {
          // The wrap stands on a vertex of this ring: its successor is the tangent.
          if (ring.size() == 1) continue;
          candidate = (static_cast<std::size_t>(at_vertex[g]) + 1) % ring.size();
        } else {
          candidate = tangent_index(current, ring, tangent[g]);
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
      // Duplicates of the new wrap point in other groups were their tangents too; mark them.
      for (std::size_t g = 0; g < group_count; ++g) {
        const std::span<const Vec2> ring = groups.ring(g);
        at_vertex[g] = ring[tangent[g]] == next ? static_cast<std::ptrdiff_t>(tangent[g]) : -1;
      }
      current = next;
    }
    if (closed) return detail::hull_from_ccw_ring(std::move(hull));
    if (m >= count) throw std::logic_error("chan_hull: wrap over one group did not close");
    candidates.swap(groups.vertices);
  }
}

}  // namespace mink
