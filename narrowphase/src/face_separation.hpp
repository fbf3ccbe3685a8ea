#pragma once

#include <cstdint>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink::detail {

// The separating-axis test on the face normals of P: for each edge i of P, how far the
// deepest vertex of Q lies outside it. In 2D the Minkowski difference has exactly the face
// normals of P and Q, so the largest value over both hulls is the signed distance along a
// face normal: positive when apart (a lower bound on the distance), minus the penetration
// depth when overlapping.
struct FaceSeparation {
  Real separation = 0;
  std::uint32_t edge = 0;  // edge of P
};

// `q_to_p` maps Q's local frame to P's. Small Q: every vertex against every face. Large Q:
// the deepest vertex turns with the faces like a rotating caliper, so it is climbed to from
// the previous one, O(|P| + |Q|) in all.
FaceSeparation max_face_separation(const PreparedHull& p, const PreparedHull& q,
                                   const Pose& q_to_p);

// The same by brute force over every face and vertex: the slow twin for tests.
FaceSeparation max_face_separation_brute(const PreparedHull& p, const PreparedHull& q,
                                         const Pose& q_to_p);

// Inverse of a rigid transform.
inline Pose inverse(const Pose& pose) {
  Pose inv;
  inv.rotation = {pose.rotation.cos, -pose.rotation.sin};
  inv.position = inv.rotation.apply(-pose.position);
  return inv;
}

}  // namespace mink::detail
