#include "mink/narrowphase/collide.hpp"

#include <array>

#include "collide_chain.hpp"
#include "collide_circles.hpp"
#include "collide_cores.hpp"

namespace mink {

namespace {

using PairFunction = Manifold (*)(const ShapeGeometry&, const Pose&, const ShapeGeometry&,
                                  const Pose&, Real);

// Circle - circle: closed form.
Manifold circles(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b, const Pose& pb,
                 Real margin) {
  return detail::collide_circles(std::get<Circle>(a), pa, std::get<Circle>(b), pb, margin);
}

// Circle (A) - capsule, segment or polygon: closed form.
Manifold circle_and_core(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b,
                         const Pose& pb, Real margin) {
  return detail::collide_circle_core(std::get<Circle>(a), pa, detail::core_of(b), pb, margin);
}

// Every pair of circle, capsule, segment and rounded polygon (a segment is a capsule of radius
// 0): GJK on the cores, the separating-axis test when they overlap, then clipping.
Manifold cores(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b, const Pose& pb,
               Real margin) {
  return detail::collide_cores(detail::core_of(a), pa, detail::core_of(b), pb, margin);
}

// Polygon - polygon: sharp hulls keep the fast face-clipping path; rounded ones the general.
Manifold polygons(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b, const Pose& pb,
                  Real margin) {
  const auto& pa_shape = std::get<RoundedPolygon>(a);
  const auto& pb_shape = std::get<RoundedPolygon>(b);
  if (pa_shape.radius == 0 && pb_shape.radius == 0) {
    return collide_hulls(pa_shape.hull, pa, pb_shape.hull, pb, margin);
  }
  return cores(a, pa, b, pb, margin);
}

// Chain segment (A) - anything but a chain: one-sided, with the ghost vertices' rules.
Manifold chain_and_shape(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b,
                         const Pose& pb, Real margin) {
  return detail::collide_chain_core(std::get<ChainSegment>(a), pa, detail::core_of(b), pb, margin);
}

// Chain - chain: terrain never collides with terrain.
Manifold nothing(const ShapeGeometry&, const Pose&, const ShapeGeometry&, const Pose&, Real) {
  return {};
}

// The pair functions above take the chain (or the circle) first; this calls them the other
// way round and turns the normal back to A -> B.
template <PairFunction f>
Manifold swapped(const ShapeGeometry& a, const Pose& pa, const ShapeGeometry& b, const Pose& pb,
                 Real margin) {
  Manifold m = f(b, pb, a, pa, margin);
  m.normal = -m.normal;
  return m;
}

constexpr std::size_t kKinds = std::variant_size_v<ShapeGeometry>;

// Row: A's kind, column: B's kind, in ShapeKind order (circle, capsule, segment, chain segment,
// polygon).
constexpr std::array<std::array<PairFunction, kKinds>, kKinds> kTable = {{
    {circles, circle_and_core, circle_and_core, swapped<chain_and_shape>, circle_and_core},
    {swapped<circle_and_core>, cores, cores, swapped<chain_and_shape>, cores},
    {swapped<circle_and_core>, cores, cores, swapped<chain_and_shape>, cores},
    {chain_and_shape, chain_and_shape, chain_and_shape, nothing, chain_and_shape},
    {swapped<circle_and_core>, cores, cores, swapped<chain_and_shape>, polygons},
}};

}  // namespace

Manifold collide_shapes(const ShapeGeometry& a, const Pose& pose_a, const ShapeGeometry& b,
                        const Pose& pose_b, Real speculative_distance) {
  return kTable[a.index()][b.index()](a, pose_a, b, pose_b, speculative_distance);
}

}  // namespace mink
