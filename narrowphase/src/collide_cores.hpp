#pragma once

// The contact manifold of any two cores with radii: the one algorithm behind every pair kind
// except hull against hull with no radius (collide_hulls) and the chain's admissibility rules.

#include <cstdint>

#include "mink/narrowphase/manifold.hpp"
#include "shape_core.hpp"

namespace mink::detail {

// Feature ids, as collide_hulls encodes them: a reference face and an incident vertex (kind 0),
// a side of the reference face crossing the incident edge (kind 1), or the nearest points'
// vertex pair (kind 2). Bit 30 marks B as the reference.
inline constexpr std::uint32_t kFeatureIndexMask = 0x3fff;
inline constexpr std::uint32_t kReferenceOnB = 1u << 30;
enum FeatureKind : std::uint32_t { kVertexInFace = 0, kClipped = 1, kNearest = 2 };

inline std::uint32_t feature_id(std::uint32_t reference, std::uint32_t incident, FeatureKind kind) {
  return (reference & kFeatureIndexMask) | ((incident & kFeatureIndexMask) << 14) |
         (static_cast<std::uint32_t>(kind) << 28);
}

// A face of one of the two cores, in A's frame. A segment core has two faces (both sides:
// face 0 runs point 0 -> 1 with the right normal, face 1 back), a point core none.
struct ReferenceFace {
  Vec2 v1{0, 0};
  Vec2 v2{0, 0};
  Vec2 normal{0, 0};  // outward, unit
  std::uint32_t index = 0;
  bool on_b = false;
};

// Number of faces of a core: hull edges, 2 for a segment, 0 for a point.
inline std::size_t face_count(const Core& core) {
  return core.hull != nullptr ? core.size() : (core.size() == 2 ? 2 : 0);
}

// Face `index` of A (on_b false) or of B, in A's frame.
ReferenceFace core_face(const Core& core, std::uint32_t index, bool on_b, const Pose& b_to_a);

// General manifold of two cores with radii (see collide_shapes for the contract).
Manifold collide_cores(const Core& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                       Real speculative_distance);

// The points of B's feature facing `face` (a face of A), clipped to the face's sides, each with
// its separation along the face normal, radii included; those beyond the speculative distance
// are dropped. Used where only that face's normal is admissible (chain segments).
Manifold collide_on_face(const Core& a, const Pose& pose_a, const Core& b, const Pose& pose_b,
                         const ReferenceFace& face, Real speculative_distance);

}  // namespace mink::detail
