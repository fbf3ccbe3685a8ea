#pragma once

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "mink/narrowphase/simplex.hpp"

namespace mink {

/// @brief What gjk_overlap decided, with the evidence for it.
struct OverlapResult {
  bool overlap = false;                ///< touching counts as overlap
  int iterations = 0;                  ///< support points taken
  bool reached_iteration_cap = false;  ///< then `overlap` came from the face-normal test
  /// When apart: a world direction d with (a - b) . d < 0 for every a in A, b in B.
  Vec2 separating_direction{0, 0};
  SimplexCache simplex;  ///< the final simplex as vertex pairs: see world_simplex
};

/// @brief The paper's GJK boolean (section 6).
///
/// First direction from A's centroid to B's (eq. 2, 3), support points of A - B (eq. 4), line and
/// triangle cases. The triple products of the paper appear in their 2D form, a perpendicular chosen
/// by an exact orientation test, because the cubic triple product overflows or underflows at huge
/// or tiny coordinates. The answer is always defined: past an iteration cap (never reached in the
/// tests) the face-normal separating-axis test decides.
/// @param a, b the hulls, in their local frames
/// @param pose_a, pose_b where the hulls are in the world
OverlapResult gjk_overlap(const PreparedHull& a, const Pose& pose_a, const PreparedHull& b,
                          const Pose& pose_b);

/// Exact verdict by brute force: the hulls (as given, world coordinates) are disjoint iff
/// some edge of one has every vertex of the other strictly on its outer side, decided by exact
/// orientation. O(n m): the slow twin of gjk_overlap.
bool hulls_overlap_exact(std::span<const Vec2> a, std::span<const Vec2> b);

}  // namespace mink
