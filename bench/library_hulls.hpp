#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink::bench {

// CGAL::convex_hull_2 with the Epick kernel (exact predicates, the fair counterpart of
// Minkowski's exact orientation tests). Construction converts the input to CGAL points and
// reserves the output, so build() times the hull alone.
class CgalHullBuilder {
 public:
  explicit CgalHullBuilder(std::span<const Vec2> points);
  ~CgalHullBuilder();
  CgalHullBuilder(CgalHullBuilder&&) noexcept;
  CgalHullBuilder& operator=(CgalHullBuilder&&) noexcept;

  // Builds the hull and returns its vertex count.
  std::size_t build();
  // Vertices of the last build, counter-clockwise.
  std::vector<Vec2> vertices() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Qhull (libqhull_r) with its default options. Construction copies the input into the flat
// coordinate array Qhull reads; build() times qh_new_qhull, reading the hull vertices and
// freeing Qhull's memory.
class QhullHullBuilder {
 public:
  explicit QhullHullBuilder(std::span<const Vec2> points);
  ~QhullHullBuilder();
  QhullHullBuilder(QhullHullBuilder&&) noexcept;
  QhullHullBuilder& operator=(QhullHullBuilder&&) noexcept;

  // Builds the hull and returns its vertex count; throws std::runtime_error when Qhull fails.
  std::size_t build();
  // Vertices of the last build, in Qhull's vertex-list order (not around the hull).
  std::vector<Vec2> vertices() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace mink::bench
