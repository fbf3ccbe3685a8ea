#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

class ConvexHull;

namespace detail {
/// Algorithms hand their CCW, strictly convex ring here; it is rotated to the canonical start.
ConvexHull hull_from_ccw_ring(std::vector<Vec2> ring);
}  // namespace detail

/// A strictly convex polygon: vertices counter-clockwise, no duplicate or collinear vertices,
/// at least three of them, starting at the lowest-x (then lowest-y) vertex. Every hull
/// algorithm returns this one canonical form, so results compare with ==.
class ConvexHull {
 public:
  /// @brief Makes a hull from a ring already in hull form; the ring may start anywhere.
  /// @throws DegenerateInputError (or NonFiniteInputError) naming the first vertex that breaks
  /// one of the invariants above, checked with exact predicates.
  static ConvexHull from_ccw_vertices(std::vector<Vec2> vertices);

  std::span<const Vec2> vertices() const noexcept { return vertices_; }
  std::size_t size() const noexcept { return vertices_.size(); }
  const Vec2& operator[](std::size_t i) const noexcept { return vertices_[i]; }
  bool operator==(const ConvexHull& other) const = default;

 private:
  explicit ConvexHull(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {}
  friend ConvexHull detail::hull_from_ccw_ring(std::vector<Vec2> ring);

  std::vector<Vec2> vertices_;
};

/// True when `ring` is counter-clockwise and strictly convex (exact predicates), at least 3
/// vertices; the start vertex is not checked.
bool is_strictly_convex_ccw(std::span<const Vec2> ring);

enum class HullAlgorithm { chan, divide_conquer, graham, jarvis, monotone_chain };

std::string_view to_string(HullAlgorithm algorithm) noexcept;
/// @brief Accepts the names to_string gives ("chan", "divide-conquer", ...).
/// @throws InvalidArgumentError naming the unknown value otherwise.
HullAlgorithm parse_hull_algorithm(std::string_view name);
std::span<const HullAlgorithm> all_hull_algorithms() noexcept;

struct HullOptions {
  /// Discard points strictly inside the polygon of extreme points first (Akl-Toussaint), when
  /// a sample shows that pays. Off by default: the algorithms as the paper states them.
  bool prefilter = false;
};

/// @brief Builds the hull of `points` with the chosen algorithm.
/// @param points any point set; duplicates, collinear and interior points are allowed
/// @param algorithm which of the paper's algorithms builds it (all give the same hull)
/// @param options Akl-Toussaint prefiltering, off by default
/// @return the canonical hull (see ConvexHull)
/// @throws NonFiniteInputError for a NaN or infinite coordinate
/// @throws DegenerateInputError when fewer than three distinct points are not all collinear
ConvexHull build_hull(std::span<const Vec2> points, HullAlgorithm algorithm,
                      HullOptions options = {});

}  // namespace mink
