#pragma once

#include "mink/engine/ids.hpp"

namespace mink {

/// @brief Two shapes started touching during the last step (closer than the speculative distance).
struct ContactBeginEvent {
  ShapeId shape_a;  ///< one shape of the pair
  ShapeId shape_b;  ///< the other
};

/// @brief Two shapes stopped touching, or one of them was destroyed while touching.
struct ContactEndEvent {
  ShapeId shape_a;  ///< one shape of the pair (may be stale when it was destroyed)
  ShapeId shape_b;  ///< the other
};

/// @brief What the last step did, for tools and tests.
struct StepCounters {
  std::size_t broadphase_pairs = 0;   ///< overlapping box pairs the broadphase reported
  std::size_t contacts = 0;           ///< pairs with a contact record
  std::size_t touching_contacts = 0;  ///< contacts with manifold points within touching distance
  std::size_t awake_bodies = 0;       ///< bodies simulated (not asleep)
  std::size_t islands = 0;  ///< awake islands found by the sleep pass (0 when sleep is off)
  std::size_t constraint_colors = 0;     ///< graph colours the solver used
  std::size_t overflow_constraints = 0;  ///< contacts solved one at a time (colours ran out)
};

/// @brief Wall time of each phase of the last step, in milliseconds (for tuning; never for tests).
struct StepProfile {
  /// broadphase pair update, narrowphase manifolds, sleep islands, contact preparation, the
  /// substepped solve, end-of-step bookkeeping
  double pairs = 0, collide = 0, islands = 0, prepare = 0, solve = 0, finish = 0;
};

}  // namespace mink
