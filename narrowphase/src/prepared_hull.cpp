#include "mink/narrowphase/prepared_hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/polygon.hpp"

namespace mink {

PreparedHull::PreparedHull(ConvexHull hull) : hull_(std::move(hull)) {
  const std::span<const Vec2> v = hull_.vertices();
  const std::size_t n = v.size();
  // The centroid of the hull scaled by a power of two to unit size, about its first vertex,
  // so the area neither underflows at tiny coordinates nor overflows at huge ones.
  Real extent = 0;
  for (const Vec2& p : v) {
    extent = std::max({extent, std::abs(p.x() - v[0].x()), std::abs(p.y() - v[0].y())});
  }
  if (!std::isfinite(extent)) {
    // Each vertex is finite, but two lie farther apart than a double holds: no edge, area or
    // distance of this hull can be computed.
    throw InvalidArgumentError("a hull whose vertices lie more than " +
                               std::to_string(std::numeric_limits<Real>::max()) +
                               " apart along an axis (beyond a double)");
  }
  const int scale = std::ilogb(extent);
  std::vector<Vec2> scaled;
  scaled.reserve(n);
  for (const Vec2& p : v) {
    scaled.emplace_back(std::ldexp(p.x() - v[0].x(), -scale), std::ldexp(p.y() - v[0].y(), -scale));
  }
  const Vec2 c = mink::centroid(scaled);
  centroid_ = v[0] + Vec2(std::ldexp(c.x(), scale), std::ldexp(c.y(), scale));
  size_ = n;
  padded_size_ = std::max<std::size_t>(kSupportBlock, n + n % 2);
  // Vertices and normals, then 2 padded_size_ coordinates, n face offsets and n angles as
  // pairs: padded_size_ is even, so they fill whole pairs.
  block_.resize(3 * n + padded_size_);
  std::copy(v.begin(), v.end(), block_.begin());
  Vec2* normals = block_.data() + n;
  Real* xs = reals();
  Real* ys = xs + padded_size_;
  Real* offsets = ys + padded_size_;
  // The normals' angles in edge order, turned below so the smallest comes first.
  Real* sorted = offsets + n;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 edge = v[i + 1 == n ? 0 : i + 1] - v[i];
    // Scale by a power of two before normalizing so tiny or huge edges neither underflow nor
    // overflow in the squared length.
    const int exponent = std::ilogb(std::max(std::abs(edge.x()), std::abs(edge.y())));
    const Vec2 unit_edge(std::ldexp(edge.x(), -exponent), std::ldexp(edge.y(), -exponent));
    normals[i] = Vec2(unit_edge.y(), -unit_edge.x()).normalized();
    sorted[i] = pseudo_angle(normals[i]);
    offsets[i] = normals[i].dot(v[i]);
    radius_ = std::max(radius_, std::hypot(v[i].x() - centroid_.x(), v[i].y() - centroid_.y()));
  }
  for (std::size_t i = 0; i < padded_size_; ++i) {
    xs[i] = v[i < n ? i : 0].x();
    ys[i] = v[i < n ? i : 0].y();
  }
  first_normal_ = static_cast<std::size_t>(std::min_element(sorted, sorted + n) - sorted);
  std::rotate(sorted, sorted + first_normal_, sorted + n);
}

}  // namespace mink
