#include "mink/geometry/chan.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "mink/geometry/graham.hpp"
#include "mink/geometry/hull_input.hpp"
#include "polar_order.hpp"
#include "wrap_order.hpp"

namespace mink {

namespace {

// An axis-aligned box around one group hull.
struct Box {
  Real min_x, min_y, max_x, max_y;
};

// The group hulls of one round: ring g is vertices[offsets[g] .. offsets[g + 1]), CCW,
// starting at its lowest (x, y) vertex; 1 or 2 vertices when the group is degenerate.
struct GroupHulls {
  std::vector<Vec2> vertices;
  std::vector<std::size_t> offsets;
  std::vector<Box> boxes;
  std::size_t lowest_group = 0;  // the ring holding the lowest (x, y) vertex of all

  std::size_t count() const { return offsets.size() - 1; }
  std::span<const Vec2> ring(std::size_t g) const {
    return std::span<const Vec2>(vertices).subspan(offsets[g], offsets[g + 1] - offsets[g]);
  }
  // Each ring starts at its lowest vertex, so the lowest of all starts its ring.
  const Vec2& lowest() const { return vertices[offsets[lowest_group]]; }
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

// Distinct hull vertices found cheaply: the points extreme in 24 directions, both ways along
// the 12 linear forms below. Their coefficients are 0 or powers of two, so the products are
// exact and a form's rounded value is monotone in its exact value: the exact extreme is among
// the points whose rounded value equals the rounded extreme, and those few are compared
// exactly. Among points tied in a direction the (x, y)-largest is an end of the tied segment,
// so every one returned is a hull vertex, and their number is a lower bound on the hull's.
// Empty if a value overflows.
struct LinearForm {
  Real a, b;  // a x + b y
};
constexpr std::array<LinearForm, 12> kForms = {{{1, 0},
                                                {0, 1},
                                                {1, 1},
                                                {1, -1},
                                                {2, 1},
                                                {1, 2},
                                                {2, -1},
                                                {1, -2},
                                                {4, 1},
                                                {1, 4},
                                                {4, -1},
                                                {1, -4}}};
constexpr std::size_t kFormCount = kForms.size();

// Two points' coordinates side by side, so each form is evaluated for both at once.
using Pair = Real __attribute__((vector_size(2 * sizeof(Real))));
using PairMask = std::int64_t __attribute__((vector_size(2 * sizeof(Real))));

std::vector<Vec2> certified_vertices(std::span<const Vec2> points) {
  // Pass 1: every form's rounded maximum and minimum.
  std::array<Pair, kFormCount> high;
  std::array<Pair, kFormCount> low;
  for (std::size_t f = 0; f < kFormCount; ++f) {
    const Real value = kForms[f].a * points[0].x() + kForms[f].b * points[0].y();
    high[f] = Pair{value, value};
    low[f] = high[f];
  }
  const std::size_t pairs = points.size() / 2;
  for (std::size_t i = 0; i < pairs; ++i) {
    const Pair x = {points[2 * i].x(), points[2 * i + 1].x()};
    const Pair y = {points[2 * i].y(), points[2 * i + 1].y()};
#pragma GCC unroll 12
    for (std::size_t f = 0; f < kFormCount; ++f) {
      const Pair value = kForms[f].a * x + kForms[f].b * y;
      high[f] = value > high[f] ? value : high[f];
      low[f] = value < low[f] ? value : low[f];
    }
  }
  std::array<Real, kFormCount> highest;
  std::array<Real, kFormCount> lowest;
  for (std::size_t f = 0; f < kFormCount; ++f) {
    highest[f] = std::max(high[f][0], high[f][1]);
    lowest[f] = std::min(low[f][0], low[f][1]);
    if (points.size() % 2 != 0) {
      const Vec2& p = points.back();
      const Real value = kForms[f].a * p.x() + kForms[f].b * p.y();
      highest[f] = std::max(highest[f], value);
      lowest[f] = std::min(lowest[f], value);
    }
    if (!std::isfinite(highest[f]) || !std::isfinite(lowest[f])) return {};
    high[f] = Pair{highest[f], highest[f]};
    low[f] = Pair{lowest[f], lowest[f]};
  }

  // Pass 2: the points reaching a rounded extreme, settled exactly. Direction 2 f maximises
  // form f, direction 2 f + 1 minimises it.
  std::array<const Vec2*, 2 * kFormCount> best{};
  const auto offer = [&](std::size_t direction, const Vec2& p) {
    const LinearForm form = kForms[direction / 2];
    const Real sign = direction % 2 == 0 ? 1 : -1;
    const Vec2*& incumbent = best[direction];
    if (incumbent != nullptr) {
      const ExactSum score(sign * form.a * p.x(), sign * form.b * p.y());
      const ExactSum held(sign * form.a * incumbent->x(), sign * form.b * incumbent->y());
      if (score < held || (score == held && !lex_less(*incumbent, p))) return;
    }
    incumbent = &p;
  };
  const auto offer_all = [&](const Vec2& p) {
    for (std::size_t f = 0; f < kFormCount; ++f) {
      const Real value = kForms[f].a * p.x() + kForms[f].b * p.y();
      if (value == highest[f]) offer(2 * f, p);
      if (value == lowest[f]) offer(2 * f + 1, p);
    }
  };
  for (std::size_t i = 0; i < pairs; ++i) {
    const Pair x = {points[2 * i].x(), points[2 * i + 1].x()};
    const Pair y = {points[2 * i].y(), points[2 * i + 1].y()};
    PairMask reaches = {0, 0};
#pragma GCC unroll 12
    for (std::size_t f = 0; f < kFormCount; ++f) {
      const Pair value = kForms[f].a * x + kForms[f].b * y;
      reaches |= (value == high[f]) | (value == low[f]);
    }
    if ((reaches[0] | reaches[1]) == 0) continue;
    offer_all(points[2 * i]);
    offer_all(points[2 * i + 1]);
  }
  if (points.size() % 2 != 0) offer_all(points.back());
  std::vector<Vec2> extremes;
  for (const Vec2* p : best) extremes.push_back(*p);
  std::sort(extremes.begin(), extremes.end(), lex_less);
  extremes.erase(std::unique(extremes.begin(), extremes.end()), extremes.end());
  return extremes;
}

// Chan's algorithm leaves the partition into groups free. Grouping points by angle about a
// point inside the hull makes every group a narrow wedge: its hull is small, so a wrap step
// rules out most groups by their boxes alone, and the last round's rings barely interleave.
// One counting-sort pass on a coarse pseudo-angle; rounding only moves a point to a
// neighbouring sector, which leaves the partition valid.
std::vector<Vec2> order_by_sector(std::span<const Vec2> points, const Vec2& centre) {
  constexpr std::size_t kSectors = 2048;
  constexpr Real kSectorsPerUnit = kSectors / 4.0;  // the pseudo-angle below spans [0, 4)
  std::array<std::size_t, kSectors> start{};
  std::vector<std::uint16_t> sectors(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Real dx = points[i].x() - centre.x();
    const Real dy = points[i].y() - centre.y();
    const Real slope = dy / (std::abs(dx) + std::abs(dy));  // in [-1, 1]; NaN at the centre
    Real angle = dx < 0 ? 2 - slope : slope;
    if (angle < 0) angle += 4;
    const Real scaled = angle * kSectorsPerUnit;
    const std::size_t sector =
        scaled >= 0 && scaled < kSectors ? static_cast<std::size_t>(scaled) : 0;
    sectors[i] = static_cast<std::uint16_t>(sector);
    ++start[sector];
  }
  std::size_t sum = 0;
  for (std::size_t& s : start) sum += std::exchange(s, sum);
  std::vector<Vec2> ordered(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) ordered[start[sectors[i]]++] = points[i];
  return ordered;
}

// The last round's single group is the union of the previous round's rings. Its Graham scan
// needs the polar order about the lowest vertex, and each strictly convex ring, seen from a
// point outside it, is two arcs already in that order (the angle rises from the ring's first
// vertex in polar order to its last, then falls back): merging those arcs replaces the sort.
// Appends the hull ring to `hull`; false when a polar key cannot be trusted (a difference
// overflowed), leaving the caller to sort.
bool graham_scan_of_rings(const GroupHulls& rings, std::vector<Vec2>& hull) {
  const std::size_t ring_count = rings.count();
  const Vec2 pivot = rings.lowest();
  bool reliable = true;
  const auto key_of = [&](const Vec2& p) {
    reliable &= detail::pseudo_angle_reliable(pivot, p);
    return detail::pseudo_angle(pivot, p);
  };
  const auto precedes = [&](const Vec2& a, Real key_a, const Vec2& b, Real key_b) {
    return detail::polar_precedes(pivot, a, key_a, b, key_b);
  };

  // An arc: up to two contiguous pieces of a ring (it may wrap past the ring's end), read
  // forwards or backwards.
  struct Arc {
    const Vec2* at;
    std::size_t left;
    std::ptrdiff_t step;
    const Vec2* then_at;
    std::size_t then_left;
  };
  std::vector<Arc> arcs;
  arcs.reserve(2 * ring_count);
  for (std::size_t g = 0; g < ring_count; ++g) {
    const std::span<const Vec2> ring = rings.ring(g);
    const Vec2* v = ring.data();
    const std::size_t size = ring.size();
    if (v[0] == pivot) {
      // The pivot's own ring (or a duplicate of it) is in polar order after its first vertex.
      if (size > 1) arcs.push_back({v + 1, size - 1, 1, nullptr, 0});
      continue;
    }
    std::size_t first = 0;
    std::size_t last = 0;
    Real first_key = key_of(v[0]);
    Real last_key = first_key;
    for (std::size_t i = 1; i < size; ++i) {
      const Real key = key_of(v[i]);
      if (precedes(v[i], key, v[first], first_key)) {
        first = i;
        first_key = key;
      }
      if (precedes(v[last], last_key, v[i], key)) {
        last = i;
        last_key = key;
      }
    }
    // Rising: first .. last going CCW. Falling: after last .. before first, read backwards.
    if (first <= last) {
      arcs.push_back({v + first, last - first + 1, 1, nullptr, 0});
      if (first > 0) {
        arcs.push_back({v + first - 1, first, -1, v + size - 1, size - 1 - last});
      } else if (last + 1 < size) {
        arcs.push_back({v + size - 1, size - 1 - last, -1, nullptr, 0});
      }
    } else {
      arcs.push_back({v + first, size - first, 1, v, last + 1});
      if (last + 1 < first) arcs.push_back({v + first - 1, first - 1 - last, -1, nullptr, 0});
    }
  }
  if (!reliable) return false;

  // A loser tree over the arcs' next vertices and their keys; an exhausted arc's head is null
  // and loses to everything.
  std::size_t leaves = 1;
  while (leaves < arcs.size()) leaves *= 2;
  std::vector<const Vec2*> head(leaves, nullptr);
  std::vector<Real> head_key(leaves, 0);
  for (std::size_t a = 0; a < arcs.size(); ++a) {
    head[a] = arcs[a].at;
    head_key[a] = key_of(*head[a]);
  }
  const auto beats = [&](std::size_t a, std::size_t b) {
    if (head[a] == nullptr) return false;
    return head[b] == nullptr || precedes(*head[a], head_key[a], *head[b], head_key[b]);
  };
  std::vector<std::size_t> winner(2 * leaves);
  std::vector<std::size_t> loser(leaves);
  for (std::size_t a = 0; a < leaves; ++a) winner[leaves + a] = a;
  for (std::size_t node = leaves - 1; node >= 1; --node) {
    const std::size_t left = winner[2 * node];
    const std::size_t right = winner[2 * node + 1];
    const bool right_wins = beats(right, left);
    winner[node] = right_wins ? right : left;
    loser[node] = right_wins ? left : right;
  }

  const std::size_t base = hull.size();
  hull.push_back(pivot);
  for (std::size_t champion = winner[1]; head[champion] != nullptr;) {
    const Vec2 p = *head[champion];
    if (p != pivot) {
      // Graham's scan: pop right turns and straight continuations.
      while (hull.size() - base >= 2 && orient2d(hull[hull.size() - 2], hull.back(), p) <= 0) {
        hull.pop_back();
      }
      hull.push_back(p);
    }
    Arc& arc = arcs[champion];
    if (--arc.left > 0) {
      arc.at += arc.step;
    } else if (arc.then_left > 0) {
      arc.at = arc.then_at;
      arc.left = std::exchange(arc.then_left, 0);
    } else {
      arc.at = nullptr;
    }
    head[champion] = arc.at;
    if (arc.at != nullptr) head_key[champion] = key_of(*arc.at);
    for (std::size_t node = (leaves + champion) / 2; node >= 1; node /= 2) {
      if (beats(loser[node], champion)) std::swap(loser[node], champion);
    }
  }
  return reliable;
}

// Round t's groups: each run of m candidates, hulled by Graham's scan, with its box.
void build_group_hulls(std::span<const Vec2> candidates, std::size_t m,
                       detail::GrahamScratch& scratch, GroupHulls& groups) {
  groups.vertices.clear();
  groups.vertices.reserve(candidates.size());  // never more hull vertices than points
  groups.offsets.assign(1, 0);
  groups.boxes.clear();
  groups.lowest_group = 0;
  for (std::size_t begin = 0; begin < candidates.size(); begin += m) {
    const std::size_t first_vertex = groups.vertices.size();
    detail::graham_scan(candidates.subspan(begin, std::min(m, candidates.size() - begin)), scratch,
                        groups.vertices);
    groups.offsets.push_back(groups.vertices.size());
    if (lex_less(groups.vertices[first_vertex], groups.lowest())) {
      groups.lowest_group = groups.count() - 1;
    }
    Box box{groups.vertices[first_vertex].x(), groups.vertices[first_vertex].y(),
            groups.vertices[first_vertex].x(), groups.vertices[first_vertex].y()};
    for (std::size_t i = first_vertex + 1; i < groups.vertices.size(); ++i) {
      const Vec2& v = groups.vertices[i];
      box.min_x = std::min(box.min_x, v.x());
      box.min_y = std::min(box.min_y, v.y());
      box.max_x = std::max(box.max_x, v.x());
      box.max_y = std::max(box.max_y, v.y());
    }
    groups.boxes.push_back(box);
  }
}

// Is every point of `box` strictly left of the line from -> to? Then no point in it can be
// the wrap's next vertex while `to` is a candidate. Decided exactly at the box's corner
// farthest to the right of the line.
bool strictly_left_of(const Box& box, const Vec2& from, const Vec2& to) {
  const Vec2 corner(to.y() > from.y() ? box.max_x : box.min_x,
                    to.x() > from.x() ? box.min_y : box.max_y);
  return orient2d(from, to, corner) > 0;
}

// Jarvis's wrap over the group hulls from the lowest (x, y) vertex, at most m steps. Returns
// true with the hull in `hull` when it closed.
bool wrap_group_hulls(const GroupHulls& groups, std::size_t m, std::vector<std::size_t>& tangent,
                      std::vector<Vec2>& hull) {
  const std::size_t group_count = groups.count();
  const Vec2 start = groups.lowest();
  // Each ring starts at its lowest (x, y) vertex, so a ring holding the start holds it at 0.
  tangent.assign(group_count, 0);
  hull.assign(1, start);
  Vec2 current = start;
  std::size_t current_group = groups.lowest_group;
  const Vec2* vertices = groups.vertices.data();
  const std::size_t* offsets = groups.offsets.data();
  for (std::size_t step = 0; step < m; ++step) {
    const Vec2* best = nullptr;
    std::size_t best_group = current_group;
    const auto visit = [&](std::size_t g) {
      const std::span<const Vec2> ring(vertices + offsets[g], offsets[g + 1] - offsets[g]);
      std::size_t candidate = tangent[g];
      if (ring[candidate] == current) {
        // The wrap stands on a vertex of this ring (this group's last answer, or a duplicate
        // of it): the ring's successor is the tangent.
        if (ring.size() == 1) return;
        candidate = candidate + 1 == ring.size() ? 0 : candidate + 1;
      } else {
        candidate = tangent_index(current, ring, candidate);
      }
      tangent[g] = candidate;
      if (best == nullptr || detail::wraps_before(current, ring[candidate], *best)) {
        best = &ring[candidate];
        best_group = g;
      }
    };
    // The group the wrap stands in offers a good first candidate; with it, most groups'
    // boxes lie wholly on the outer side and need no tangent.
    visit(current_group);
    for (std::size_t g = 0; g < group_count; ++g) {
      if (g == current_group) continue;
      if (best != nullptr && strictly_left_of(groups.boxes[g], current, *best)) continue;
      visit(g);
    }
    const Vec2 next = *best;
    if (next == start) return true;
    hull.push_back(next);
    current = next;
    current_group = best_group;
  }
  return false;
}

}  // namespace

namespace detail {
std::size_t chan_group_size(unsigned t, std::size_t limit) noexcept {
  if (t >= 6) return limit;  // 2^(2^6) exceeds any count
  return std::min<std::size_t>(std::size_t{1} << (1u << t), limit);
}
}  // namespace detail

ConvexHull chan_hull(std::span<const Vec2> points) {
  validate_hull_input(points);
  const std::vector<Vec2> extremes = certified_vertices(points);
  // A round with fewer wrap steps than known hull vertices cannot close: skip such rounds.
  const std::size_t known_vertices = extremes.size();
  // The mean of three or more hull vertices lies inside the hull; any centre would do.
  Vec2 centre = points[0];
  if (known_vertices >= 3) {
    centre = Vec2::Zero();
    for (const Vec2& v : extremes) centre += v / static_cast<Real>(known_vertices);
  }
  std::vector<Vec2> ordered = order_by_sector(points, centre);
  detail::GrahamScratch scratch;
  // The group hulls of the last round that did not close: their vertices are the points still
  // in the running, since a point inside any group hull is inside the final one.
  GroupHulls rings;
  GroupHulls next;  // the round being built
  std::vector<std::size_t> tangent;
  std::vector<Vec2> hull;

  for (unsigned t = 1;; ++t) {
    const std::span<const Vec2> candidates = rings.offsets.empty()
                                                 ? std::span<const Vec2>(ordered)
                                                 : std::span<const Vec2>(rings.vertices);
    const std::size_t count = candidates.size();
    const std::size_t m = detail::chan_group_size(t, count);
    if (m < known_vertices && m < count) continue;
    if (m >= count) {
      // One group: its Graham hull is the hull, and the wrap would only walk it again. The
      // hull goes into memory an earlier round has already touched.
      hull.swap(next.vertices);
      hull.clear();
      if (!rings.offsets.empty() && graham_scan_of_rings(rings, hull)) {
        return detail::hull_from_ccw_ring(std::move(hull));
      }
      hull.clear();
      detail::graham_scan(candidates, scratch, hull);
      return detail::hull_from_ccw_ring(std::move(hull));
    }
    build_group_hulls(candidates, m, scratch, next);
    if (wrap_group_hulls(next, m, tangent, hull)) {
      return detail::hull_from_ccw_ring(std::move(hull));
    }
    std::swap(rings, next);
    // The next round writes over the older rings, or after the first round over the
    // sector-ordered copy, which nothing reads any more.
    if (!ordered.empty()) next.vertices.swap(ordered);
  }
}

}  // namespace mink
