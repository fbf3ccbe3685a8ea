#pragma once

// Shared by the test files: CGAL as the reference, mink's canonical hull form, readable
// failure messages.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "mink/geometry/orientation.hpp"
#include "mink/geometry/types.hpp"

namespace mink_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_2;

#ifdef MINK_SANITIZED_BUILD
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

inline CgalPoint to_cgal(const mink::Vec2& p) {
  return CgalPoint(p.x(), p.y());
}
inline mink::Vec2 from_cgal(const CgalPoint& p) {
  return mink::Vec2(p.x(), p.y());
}

// CGAL's exact orientation as -1, 0 or +1 (LEFT_TURN is counter-clockwise, like orient2d).
inline int cgal_orientation(const mink::Vec2& a, const mink::Vec2& b, const mink::Vec2& c) {
  return static_cast<int>(CGAL::orientation(to_cgal(a), to_cgal(b), to_cgal(c)));
}

inline std::string format_point(const mink::Vec2& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.17g, %.17g)", p.x(), p.y());
  return text;
}

inline std::string format_points(std::span<const mink::Vec2> points, std::size_t limit = 12) {
  std::string text = "[";
  for (std::size_t i = 0; i < points.size() && i < limit; ++i) {
    if (i > 0) text += ", ";
    text += format_point(points[i]);
  }
  if (points.size() > limit) text += ", ... (" + std::to_string(points.size()) + " in all)";
  return text + "]";
}

// The ring starting at its vertex `start` (the same polygon, another first vertex).
inline std::vector<mink::Vec2> rotated_start(std::vector<mink::Vec2> ring, std::size_t start) {
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(start), ring.end());
  return ring;
}

// Bit-for-bit equality: output must round-trip every double exactly, signed zeros too.
inline ::testing::AssertionResult same_bits(const std::vector<mink::Vec2>& expected,
                                            const std::vector<mink::Vec2>& actual) {
  const auto bits = [](double value) { return std::bit_cast<std::uint64_t>(value); };
  if (expected.size() != actual.size()) {
    return ::testing::AssertionFailure()
           << "expected " << expected.size() << " vertices, got " << actual.size()
           << "\n  expected " << format_points(expected) << "\n  got      "
           << format_points(actual);
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (bits(expected[i].x()) != bits(actual[i].x()) ||
        bits(expected[i].y()) != bits(actual[i].y())) {
      return ::testing::AssertionFailure()
             << "vertex " << i << ": expected " << format_point(expected[i]) << ", got "
             << format_point(actual[i]);
    }
  }
  return ::testing::AssertionSuccess();
}

// mink's canonical hull form: the CCW ring rotated to start at its lowest (x, y) vertex.
inline std::vector<mink::Vec2> canonical_ring(std::vector<mink::Vec2> ring) {
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), mink::lex_less), ring.end());
  return ring;
}

// CGAL's convex hull (CCW, no collinear vertices) in canonical form; 1 or 2 vertices when the
// points have no area.
inline std::vector<mink::Vec2> reference_hull(std::span<const mink::Vec2> points) {
  std::vector<CgalPoint> input;
  input.reserve(points.size());
  for (const mink::Vec2& p : points) input.push_back(to_cgal(p));
  std::vector<CgalPoint> hull;
  CGAL::convex_hull_2(input.begin(), input.end(), std::back_inserter(hull), Kernel());
  std::vector<mink::Vec2> ring;
  ring.reserve(hull.size());
  for (const CgalPoint& p : hull) ring.push_back(from_cgal(p));
  return canonical_ring(std::move(ring));
}

// Vertex-by-vertex equality with the first difference spelled out, since printing whole
// hulls of thousands of vertices would bury it.
inline ::testing::AssertionResult same_ring(std::span<const mink::Vec2> expected,
                                            std::span<const mink::Vec2> actual) {
  if (expected.size() == actual.size() &&
      std::equal(expected.begin(), expected.end(), actual.begin())) {
    return ::testing::AssertionSuccess();
  }
  auto failure = ::testing::AssertionFailure();
  failure << "expected " << expected.size() << " vertices, got " << actual.size();
  const std::size_t common = std::min(expected.size(), actual.size());
  const auto mismatch = std::mismatch(
      expected.begin(), expected.begin() + static_cast<std::ptrdiff_t>(common), actual.begin());
  const auto index = static_cast<std::size_t>(mismatch.first - expected.begin());
  failure << "; first difference at vertex " << index;
  if (index < expected.size()) failure << ": expected " << format_point(expected[index]);
  if (index < actual.size()) failure << ", got " << format_point(actual[index]);
  failure << "\n  expected " << format_points(expected) << "\n  actual   " << format_points(actual);
  return failure;
}

// Uniform double in [0, 1) from 53 random bits; std::uniform_real_distribution is
// implementation-defined, this is the same everywhere.
inline double unit_double(std::uint64_t random_bits) {
  return static_cast<double>(random_bits >> 11) * 0x1p-53;
}

}  // namespace mink_test
