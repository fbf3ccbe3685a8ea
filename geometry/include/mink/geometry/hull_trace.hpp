#pragma once

// The intermediate steps of Chan's and the divide-and-conquer hulls, for figures (paper
// figures 9 and 10) and tests. Computed with the functions the algorithms themselves call
// (Graham scan, Melkman, the common-tangent merge); tests check they agree with the hulls.

#include <cstddef>
#include <span>
#include <vector>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// One of Chan's partitions: `points` split in their given order into ceil(n / m) runs of m
/// (the last may be shorter), each hulled by the Graham scan chan_hull uses.
struct ChanGroups {
  std::size_t group_size = 0;
  std::vector<std::vector<Vec2>> points;  ///< each group's points
  std::vector<std::vector<Vec2>> hulls;   ///< each group's CCW ring (1 or 2 vertices if degenerate)
};

/// @brief Splits `points` into Chan's groups of `group_size` (m) and hulls each.
/// @throws NonFiniteInputError for a non-finite coordinate
/// @throws InvalidArgumentError for m = 0
ChanGroups chan_groups(std::span<const Vec2> points, std::size_t group_size);

/// Chan's rounds as the paper states them: round t uses m = min(2^(2^t), n) on the points still
/// in the running (after a round that did not close, only its group hulls' vertices); its wrap
/// closes when the hull has at most m vertices, since each wrap step adds one vertex. The
/// last round is the one that closes (or has a single group). chan_hull additionally groups
/// points by angular sector rather than input order and skips rounds that provably cannot
/// close; the hull is the same.
struct ChanRound {
  unsigned t = 0;
  ChanGroups groups;
  bool closed = false;
};
struct ChanTrace {
  std::vector<ChanRound> rounds;
  ConvexHull hull;
};
/// @brief Chan's rounds on `points`.
/// @throws NonFiniteInputError, DegenerateInputError like chan_hull.
ChanTrace chan_trace(std::span<const Vec2> points);

/// The top-level merge of divide and conquer (the paper's shape: one split into halves). The
/// points sorted by (x, y) without duplicates, split in two; each half hulled by Melkman; the
/// upper and lower common tangents as index pairs into the half hulls: the hull edge from
/// right_hull[upper_right] to left_hull[upper_left], and from left_hull[lower_left] to
/// right_hull[lower_right].
struct DivideConquerTrace {
  std::vector<Vec2> left_points;
  std::vector<Vec2> right_points;
  std::vector<Vec2> left_hull;
  std::vector<Vec2> right_hull;
  std::size_t upper_left = 0;
  std::size_t upper_right = 0;
  std::size_t lower_left = 0;
  std::size_t lower_right = 0;
  ConvexHull hull;  ///< the merge of the two half hulls
};
/// @brief The top-level merge of divide and conquer on `points`.
/// @throws NonFiniteInputError, DegenerateInputError like divide_conquer_hull.
DivideConquerTrace divide_conquer_trace(std::span<const Vec2> points);

namespace detail {
/// The common tangents of two x-separated CCW rings by brute force: the pair whose line has
/// every vertex of both rings on its left or on it, the farthest-apart pair when several do.
/// {left index, right index} of the upper tangent, then of the lower one.
struct TangentPairs {
  std::size_t upper_left, upper_right, lower_left, lower_right;
};
TangentPairs common_tangents_brute_force(std::span<const Vec2> left, std::span<const Vec2> right);
}  // namespace detail

}  // namespace mink
