#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "mink/geometry/convex_hull.hpp"

namespace mink {

/// Vertex count of the fixed block the linear support scan handles with no loop: the padded
/// arrays of PreparedHull are at least this long.
inline constexpr std::size_t kSupportBlock = 8;

/// @brief A hull in its shape's local frame, with what queries need precomputed once at shape
/// creation (centroid, edge normals, search structures for large vertex counts).
class PreparedHull {
 public:
  /// Precomputes everything from `hull` (local coordinates). O(n).
  explicit PreparedHull(ConvexHull hull);

  /// @brief The hull itself, in local coordinates.
  const ConvexHull& hull() const noexcept { return hull_; }
  /// @brief The hull's vertices, counter-clockwise, local coordinates.
  std::span<const Vec2> vertices() const noexcept { return {block_.data(), size_}; }
  /// @brief Number of vertices.
  std::size_t size() const noexcept { return size_; }
  /// @brief Area centroid, local coordinates.
  const Vec2& centroid() const noexcept { return centroid_; }

  /// Unit outward normal of edge i, the edge from vertex i to vertex i + 1 (cyclic).
  std::span<const Vec2> normals() const noexcept { return {block_.data() + size_, size_}; }
  /// normals()[i] . vertices()[i]: where edge i's supporting line lies along its normal.
  std::span<const Real> face_offsets() const noexcept {
    return {reals() + 2 * padded_size_, size_};
  }
  /// Largest distance from the centroid to a vertex: the hull's length scale for tolerances.
  Real radius() const noexcept { return radius_; }

  /// Pseudo-angles (see pseudo_angle) of the edge normals in increasing order: entry k is the
  /// normal of edge (k + first_normal()) mod size(). The CCW normals turn once around the
  /// circle, so one rotation of the ring makes them sorted; support_index_binary searches it.
  std::span<const Real> sorted_normal_angles() const noexcept {
    return {reals() + 2 * padded_size_ + size_, size_};
  }
  /// @brief Index of the edge whose normal has the smallest pseudo-angle.
  std::size_t first_normal() const noexcept { return first_normal_; }

  /// The vertices' x and y in separate arrays padded with copies of vertex 0 to an even length
  /// of at least kSupportBlock, so the linear support scan works on two vertices per
  /// instruction and on small hulls as one fixed block with no loop.
  const Real* xs() const noexcept { return reals(); }
  /// @brief The y coordinates, padded like xs().
  const Real* ys() const noexcept { return reals() + padded_size_; }
  /// @brief Length of xs() and ys(), padding included.
  std::size_t padded_size() const noexcept { return padded_size_; }
  /// @brief The one block all the arrays above lie in, for a caller asking for it ahead.
  std::span<const Vec2> storage() const noexcept { return block_; }

 private:
  // The arrays above in one block: vertices, normals, then xs and ys (first, so that they
  // stay 16-byte aligned for the support scan's loads), face offsets and sorted angles as
  // pairs of Reals. One allocation whose neighbouring cache lines hold what a contact needs
  // next, where six allocations scattered a shape's arrays over the heap.
  const Real* reals() const noexcept { return block_[2 * size_].data(); }
  Real* reals() noexcept { return block_[2 * size_].data(); }

  ConvexHull hull_;  // the cold copy, for the queries that take a ConvexHull
  std::vector<Vec2> block_;
  std::size_t size_ = 0;
  std::size_t padded_size_ = 0;
  std::size_t first_normal_ = 0;
  Vec2 centroid_{0, 0};
  Real radius_ = 0;
};

/// A monotone stand-in for atan2(y, x) mapped to [0, 4): increases with the angle measured
/// counter-clockwise from the +x axis, with no trigonometry. Zero vector gives 1 (any value).
inline Real pseudo_angle(const Vec2& v) noexcept {
  const Real sum = std::abs(v.x()) + std::abs(v.y());
  if (sum == 0) return 1;
  const Real p = v.x() / sum;
  return v.y() < 0 ? 3 + p : 1 - p;
}

}  // namespace mink
