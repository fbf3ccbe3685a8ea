#include "collide_chain.hpp"

#include <cmath>

#include "collide_cores.hpp"

namespace mink::detail {

namespace {

Real cross2(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

Vec2 right_normal(const Vec2& edge) {
  return rescaled_direction(Vec2(edge.y(), -edge.x())).normalized();
}

// A joint is convex (seen from the chain's right side) when the chain turns left there; a
// turn within rounding of straight counts as flat.
bool convex_turn(const Vec2& before, const Vec2& after) {
  const Real scale = before.norm() * after.norm();
  return scale > 0 && cross2(before, after) > 1e-9 * scale;
}

// `m` lies in the cone from `from` counter-clockwise to `to` (less than a half turn).
bool in_cone(const Vec2& from, const Vec2& m, const Vec2& to) {
  constexpr Real kSlack = 1e-12;
  return cross2(from, m) >= -kSlack && cross2(m, to) >= -kSlack;
}

}  // namespace

bool chain_normal_admissible(const ChainSegment& chain, const Vec2& normal) {
  const Vec2& p1 = chain.segment.point1;
  const Vec2& p2 = chain.segment.point2;
  const Vec2 e0 = p1 - chain.ghost1;
  const Vec2 e1 = p2 - p1;
  const Vec2 e2 = chain.ghost2 - p2;
  const Vec2 n = right_normal(e1);
  // The segment normal itself, up to the rounding of a normal computed elsewhere (a tilted
  // face of the other shape is not it: that one would be forced to the segment normal).
  if (normal.dot(n) >= 1 - 1e-15) return true;
  // Around a convex joint the surface turns from one segment's normal to the next one's, so
  // those in between are real; at a flat or concave joint the neighbour covers the rest.
  if (convex_turn(e0, e1) && in_cone(right_normal(e0), normal, n)) return true;
  if (convex_turn(e1, e2) && in_cone(n, normal, right_normal(e2))) return true;
  return false;
}

Manifold collide_chain_core(const ChainSegment& chain, const Pose& pose_a, const Core& b,
                            const Pose& pose_b, Real speculative_distance) {
  Core a;
  a.small = {chain.segment.point1, chain.segment.point2};
  a.count = 2;
  const Pose b_to_a = relative_pose(pose_a, pose_b);
  const ReferenceFace front = core_face(a, 0, false, b_to_a);
  // One-sided: a shape whose centre is behind the segment passes through it.
  if (front.normal.dot(b_to_a.apply(b.centre()) - front.v1) < 0) return {};
  Manifold m = collide_cores(a, pose_a, b, pose_b, speculative_distance);
  if (m.point_count == 0) return m;
  if (chain_normal_admissible(chain, pose_a.rotation.apply_inverse(m.normal))) return m;
  // A normal the smooth chain surface does not have (it would catch on the joint): the
  // segment's own normal instead, with B's facing feature clipped to this segment.
  return collide_on_face(a, pose_a, b, pose_b, front, speculative_distance);
}

}  // namespace mink::detail
