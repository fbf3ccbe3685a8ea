#include "mink/geometry/akl_toussaint.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "mink/error.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/monotone_chain.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

namespace {

// One edge of the extreme polygon as a half-plane test: (p - origin) x direction <= -margin
// means p is certainly strictly left of the edge.
struct EdgeTest {
  Real origin_x, origin_y, dx, dy, margin;
};

}  // namespace

std::vector<Vec2> akl_toussaint_filter(std::span<const Vec2> points) {
  validate_hull_input(points);
  // Extremes in eight directions: +-x, +-y, +-(x + y), +-(x - y). Floating-point sums only
  // choose which input points span the polygon; the polygon itself is made exactly.
  std::array<std::size_t, 8> extreme{};
  std::array<Real, 8> best;
  best.fill(-INFINITY);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Real x = points[i].x();
    const Real y = points[i].y();
    const std::array<Real, 8> score = {x, x + y, y, y - x, -x, -x - y, -y, x - y};
    for (int k = 0; k < 8; ++k) {
      if (score[k] > best[k]) {
        best[k] = score[k];
        extreme[k] = i;
      }
    }
  }
  std::vector<Vec2> corners;
  for (std::size_t index : extreme) corners.push_back(points[index]);
  std::sort(corners.begin(), corners.end(), lex_less);
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  std::vector<Vec2> polygon;
  try {
    const ConvexHull inner = monotone_chain_hull(corners);
    polygon.assign(inner.vertices().begin(), inner.vertices().end());
  } catch (const DegenerateInputError&) {
    return std::vector<Vec2>(points.begin(), points.end());  // extremes collinear: keep all
  }

  Real min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  for (const Vec2& v : polygon) {
    min_x = std::min(min_x, v.x());
    max_x = std::max(max_x, v.x());
    min_y = std::min(min_y, v.y());
    max_y = std::max(max_y, v.y());
  }
  const Real width = max_x - min_x;
  const Real height = max_y - min_y;
  // Inside the box the floating-point edge test errs by a few ulps of |dx| * height +
  // |dy| * width; demand a
  // margin well above that (and above the underflow level) before dropping a point.
  constexpr Real kRelativeMargin = 1e-14;
  constexpr Real kAbsoluteMargin = 0x1p-1000;
  std::vector<EdgeTest> edges;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    const Real dx = b.x() - a.x();
    const Real dy = b.y() - a.y();
    edges.push_back({a.x(), a.y(), dx, dy,
                     kRelativeMargin * (std::abs(dx) * height + std::abs(dy) * width) +
                         kAbsoluteMargin});
  }

  std::vector<Vec2> survivors;
  survivors.reserve(points.size() / 4);
  for (const Vec2& p : points) {
    // Outside the polygon's bounding box the error bound below does not hold; such a point is
    // outside the polygon anyway.
    bool inside = p.x() >= min_x && p.x() <= max_x && p.y() >= min_y && p.y() <= max_y;
    for (const EdgeTest& e : edges) {
      const Real cross = e.dx * (p.y() - e.origin_y) - e.dy * (p.x() - e.origin_x);
      inside &= cross > e.margin;
    }
    if (!inside) survivors.push_back(p);
  }
  return survivors;
}

}  // namespace mink
