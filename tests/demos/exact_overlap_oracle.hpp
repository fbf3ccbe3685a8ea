#pragma once

// An oracle for `mink overlap` independent of Minkowski: CGAL's hull and CGAL's exact
// predicates for the verdict; brute_force_support.hpp scans for the distance and the depth.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <span>
#include <vector>

#include "brute_force_support.hpp"
#include "mink/geometry/types.hpp"

namespace mink_test {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = ExactKernel::Point_2;
using mink::Real;
using mink::Vec2;

// CCW hull by CGAL, as doubles (the input doubles themselves: no constructions).
inline std::vector<Vec2> cgal_hull(std::span<const Vec2> points) {
  std::vector<ExactPoint> in;
  for (const Vec2& p : points) in.emplace_back(p.x(), p.y());
  std::vector<ExactPoint> out;
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  std::vector<Vec2> hull;
  for (const ExactPoint& p : out) hull.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  return hull;
}

// Closed convex polygons intersect iff no edge of either has the other strictly outside.
inline bool exact_overlap(std::span<const Vec2> a, std::span<const Vec2> b) {
  auto separates = [](std::span<const Vec2> p, std::span<const Vec2> q) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const ExactPoint from(p[i].x(), p[i].y());
      const ExactPoint to(p[(i + 1) % p.size()].x(), p[(i + 1) % p.size()].y());
      const bool all_outside = std::all_of(q.begin(), q.end(), [&](const Vec2& w) {
        return CGAL::orientation(from, to, ExactPoint(w.x(), w.y())) == CGAL::RIGHT_TURN;
      });
      if (all_outside) return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

}  // namespace mink_test
