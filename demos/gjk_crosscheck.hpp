#pragma once

#include <cstdint>
#include <iosfwd>
#include <random>
#include <string>
#include <vector>

#include "mink/geometry/types.hpp"
#include "mink/narrowphase/gjk_distance.hpp"

namespace mink::cli {

// One random pair for the cross-check: two hulls in world coordinates whose vertices are
// floats (so Box2D sees exactly the same polygons), CCW, strictly convex.
struct CrosscheckPair {
  std::vector<Vec2> a;
  std::vector<Vec2> b;
};

// Our signed distance to touching from gjk_distance's result `d` for the same pair: the
// distance when apart, minus the penetration depth when overlapping.
double signed_gap(const DistanceResult& d, const PreparedHull& a, const Pose& pose_a,
                  const PreparedHull& b, const Pose& pose_b);

// Mostly 3..8 vertices (Box2D's polygon limit); one pair in ten has 16 to 1024 vertices, which
// Box2D's distance proxy accepts as a vertex cloud. Offsets put about half the pairs in
// overlap, and one pair in eight is slid to within 1e-5 of touching.
CrosscheckPair random_crosscheck_pair(std::mt19937_64& rng);

struct CrosscheckReport {
  std::uint64_t pairs = 0;
  std::uint64_t overlapping = 0;      // by our verdict
  std::uint64_t verdict_differs = 0;  // all of them, inside the band or not
  std::uint64_t verdict_outside_band = 0;
  std::uint64_t distance_differs = 0;  // both apart, distances further apart than float allows
  double worst_distance_error = 0;     // relative, over pairs both call apart
};

// Compares our verdict and distance (GJK distance query) with Box2D 2.4.1's b2Distance on
// `pairs` random pairs, writing one line per disagreement (with its distance to touching) and
// a summary to `out`. A verdict disagreement outside a `band` of touching, or a distance
// disagreement beyond float precision, fails the check.
CrosscheckReport run_gjk_crosscheck(std::uint64_t pairs, std::uint64_t seed, double band,
                                    std::ostream& out);

}  // namespace mink::cli
