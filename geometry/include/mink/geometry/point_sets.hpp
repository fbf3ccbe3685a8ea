#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "mink/geometry/types.hpp"

namespace mink {

/// Deterministic point distributions, the same on every platform for a given seed (the
/// generator and the conversions to doubles are Minkowski's own, not the standard library's
/// implementation-defined distributions). Used by tests, benchmarks and demos.
enum class PointDistribution {
  uniform_disk,     ///< unit disk
  uniform_square,   ///< [-1, 1]^2
  gaussian,         ///< standard normal in x and y
  on_circle,        ///< unit circle, random angles: nearly every point is a hull vertex
  lattice,          ///< integer grid, many collinear points and duplicates
  clusters,         ///< a few tight Gaussian clusters
  near_collinear,   ///< along a line, perturbed by a few units in the last place
  far_from_origin,  ///< uniform disk of radius 1 centred at (1e9, -3e9)
  tiny,             ///< uniform disk of radius 1e-300 (subnormal differences)
};

std::string_view to_string(PointDistribution distribution) noexcept;
std::span<const PointDistribution> all_point_distributions() noexcept;

std::vector<Vec2> generate_points(PointDistribution distribution, std::size_t count,
                                  std::uint64_t seed);

/// The paper's experiment (section 7): two random sets of 500 points in a 400 x 400 canvas,
/// the first for Chan's algorithm, the second for divide and conquer.
std::pair<std::vector<Vec2>, std::vector<Vec2>> paper_point_sets(std::uint64_t seed,
                                                                 std::size_t count = 500);

}  // namespace mink
