#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Graham scan (paper 4.1.1): sort around the lowest-x point by exact orientation, not by
/// atan2, ties by distance; keep left turns. O(n log n).
ConvexHull graham_hull(std::span<const Vec2> points);

namespace detail {
/// Storage the scan reuses from call to call (Chan runs it once per group).
struct GrahamScratch {
  std::vector<Vec2> sorted;
  std::vector<Real> keys;
  std::vector<std::uint64_t> order;
  std::vector<std::uint64_t> buffer;
  std::vector<std::pair<Real, Vec2>> keyed_run;
};

/// The scan on any finite input, degenerate too: appends the CCW ring (1, 2 or more vertices,
/// starting at the lowest-x then lowest-y point) to `ring`.
void graham_scan(std::span<const Vec2> points, GrahamScratch& scratch, std::vector<Vec2>& ring);
}  // namespace detail

}  // namespace mink
