#include "mink/narrowphase/prepared_hull.hpp"

#include <algorithm>
#include <cmath>

#include "mink/geometry/polygon.hpp"

namespace mink {

PreparedHull::PreparedHull(ConvexHull hull) : hull_(std::move(hull)) {
  const std::span<const Vec2> v = hull_.vertices();
  const std::size_t n = v.size();
  centroid_ = mink::centroid(v);
  normals_.resize(n);
  std::vector<Real> angles(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 edge = v[i + 1 == n ? 0 : i + 1] - v[i];
    // Scale by a power of two before normalizing so tiny or huge edges neither underflow nor
    // overflow in the squared length.
    const int exponent = std::ilogb(std::max(std::abs(edge.x()), std::abs(edge.y())));
    const Vec2 scaled = Vec2(std::ldexp(edge.x(), -exponent), std::ldexp(edge.y(), -exponent));
    normals_[i] = Vec2(scaled.y(), -scaled.x()).normalized();
    angles[i] = pseudo_angle(normals_[i]);
    radius_ = std::max(radius_, (v[i] - centroid_).norm());
  }
  first_normal_ =
      static_cast<std::size_t>(std::min_element(angles.begin(), angles.end()) - angles.begin());
  sorted_angles_.reserve(n);
  for (std::size_t k = 0; k < n; ++k) sorted_angles_.push_back(angles[(first_normal_ + k) % n]);
}

}  // namespace mink
