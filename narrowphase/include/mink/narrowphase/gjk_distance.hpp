#pragma once

#include <span>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/simplex.hpp"

namespace mink {

/// What gjk_distance found. Points and normal are in world coordinates.
struct DistanceResult {
  bool overlap = false;  ///< the origin is in the final simplex: touching or overlapping
  Real distance = 0;     ///< 0 when overlapping
  Vec2 point_a{0, 0};    ///< closest point on A (world); when overlapping, a point of the simplex
  Vec2 point_b{0, 0};    ///< closest point on B (world)
  Vec2 normal{0, 0};     ///< unit, from A towards B, when apart; zero when overlapping
  int iterations = 0;    ///< support points taken
  bool reached_iteration_cap = false;  ///< stopped at the iteration cap, not by convergence
  SimplexCache simplex;                ///< the final simplex as vertex pairs; EPA starts from it
};

/// GJK distance: the point of A - B nearest the origin by Voronoi-region simplex reduction.
/// With a cache, starts from the previous query's simplex and writes the new one back; a pair
/// that moved little converges in one or two iterations. Always terminates: stops on a repeated
/// vertex, on no progress, or at an iteration cap.
/// @param a, b the hulls, in their local frames
/// @param pose_a, pose_b where the hulls are in the world
/// @param cache optional warm start, read and then overwritten with the final simplex
/// @return distance, closest points and normal in world coordinates
DistanceResult gjk_distance(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                            const Pose& pose_b, SimplexCache* cache = nullptr);

/// @brief Result of hull_distance_brute.
struct BruteDistance {
  Real distance = 0;  ///< between the polygons, >= 0
  Vec2 normal{0, 0};  ///< unit, from A towards B
};

/// Distance between disjoint convex polygons (world vertices, CCW) by scanning every vertex
/// against every edge of the other: the nearest pair always involves a vertex of one and an
/// edge of the other. O(n m): the slow twin of gjk_distance.
BruteDistance hull_distance_brute(std::span<const Vec2> a, std::span<const Vec2> b);

}  // namespace mink
