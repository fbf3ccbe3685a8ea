#pragma once

#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/shape_geometry.hpp"
#include "shape_core.hpp"

namespace mink::detail {

// Whether `normal` (chain frame, from the chain towards the other shape) is one the smooth
// chain surface has at this segment: its own normal, or one between it and a neighbour's
// normal at a convex joint (the ghost vertices tell).
bool chain_normal_admissible(const ChainSegment& chain, const Vec2& normal);

// Manifold of a chain segment (A) and any core but another chain's: nothing when B's centre is
// behind the segment; the general manifold when its normal is admissible; else the segment's
// normal with B's facing feature clipped to the segment.
Manifold collide_chain_core(const ChainSegment& chain, const Pose& pose_a, const Core& b,
                            const Pose& pose_b, Real speculative_distance);

}  // namespace mink::detail
