#include "mink/geometry/hull_trace.hpp"

#include <algorithm>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/chan.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/graham.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/melkman.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

ChanGroups chan_groups(std::span<const Vec2> points, std::size_t group_size) {
  require_finite(points);
  if (group_size == 0) throw InvalidArgumentError("Chan group size must be at least 1");
  ChanGroups groups;
  groups.group_size = group_size;
  detail::GrahamScratch scratch;
  for (std::size_t begin = 0; begin < points.size(); begin += group_size) {
    const std::span<const Vec2> group =
        points.subspan(begin, std::min(group_size, points.size() - begin));
    groups.points.emplace_back(group.begin(), group.end());
    groups.hulls.emplace_back();
    detail::graham_scan(group, scratch, groups.hulls.back());
  }
  return groups;
}

ChanTrace chan_trace(std::span<const Vec2> points) {
  ConvexHull hull = chan_hull(points);  // validates the input as chan_hull does
  std::vector<ChanRound> rounds;
  std::vector<Vec2> candidates(points.begin(), points.end());
  for (unsigned t = 1;; ++t) {
    const std::size_t count = candidates.size();
    const std::size_t m = detail::chan_group_size(t, count);
    ChanRound round{t, chan_groups(candidates, m), false};
    round.closed = round.groups.hulls.size() == 1 || hull.size() <= m;
    const bool last = round.closed;
    if (!last) {
      std::vector<Vec2> survivors;
      for (const auto& ring : round.groups.hulls)
        survivors.insert(survivors.end(), ring.begin(), ring.end());
      candidates.swap(survivors);
    }
    rounds.push_back(std::move(round));
    if (last) break;
  }
  return ChanTrace{std::move(rounds), std::move(hull)};
}

namespace detail {

TangentPairs common_tangents_brute_force(std::span<const Vec2> left, std::span<const Vec2> right) {
  const auto supporting = [&](const Vec2& from, const Vec2& to) {
    for (const auto ring : {left, right}) {
      for (const Vec2& v : ring) {
        if (orient2d(from, to, v) < 0) return false;
      }
    }
    return true;
  };
  TangentPairs pairs{0, 0, 0, 0};
  bool upper_found = false;
  bool lower_found = false;
  Real upper_length = -1;
  Real lower_length = -1;
  for (std::size_t i = 0; i < left.size(); ++i) {
    for (std::size_t j = 0; j < right.size(); ++j) {
      const Real length = (right[j] - left[i]).squaredNorm();
      if (length > upper_length && supporting(right[j], left[i])) {
        pairs.upper_left = i;
        pairs.upper_right = j;
        upper_length = length;
        upper_found = true;
      }
      if (length > lower_length && supporting(left[i], right[j])) {
        pairs.lower_left = i;
        pairs.lower_right = j;
        lower_length = length;
        lower_found = true;
      }
    }
  }
  if (!upper_found || !lower_found) {
    throw InvalidArgumentError("rings of " + std::to_string(left.size()) + " and " +
                               std::to_string(right.size()) +
                               " vertices have no common tangent: they are not x-separated");
  }
  return pairs;
}

}  // namespace detail

DivideConquerTrace divide_conquer_trace(std::span<const Vec2> points) {
  validate_hull_input(points);
  std::vector<Vec2> sorted(points.begin(), points.end());
  detail::sort_lexicographic(sorted);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  // The split divide_conquer_hull makes with its default leaf size: n / 2 and the rest.
  const std::size_t half = sorted.size() / 2;
  const std::span<const Vec2> all(sorted);
  std::vector<Vec2> left_hull = detail::melkman_sorted_unchecked(all.first(half));
  std::vector<Vec2> right_hull = detail::melkman_sorted_unchecked(all.subspan(half));
  const detail::TangentPairs tangents = detail::common_tangents_brute_force(left_hull, right_hull);
  ConvexHull hull =
      ConvexHull::from_ccw_vertices(detail::merge_by_common_tangents(left_hull, right_hull));
  return DivideConquerTrace{
      std::vector<Vec2>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(half)),
      std::vector<Vec2>(all.begin() + static_cast<std::ptrdiff_t>(half), all.end()),
      std::move(left_hull),
      std::move(right_hull),
      tangents.upper_left,
      tangents.upper_right,
      tangents.lower_left,
      tangents.lower_right,
      std::move(hull)};
}

}  // namespace mink
