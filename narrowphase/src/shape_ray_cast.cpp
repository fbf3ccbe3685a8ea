#include <cmath>
#include <limits>

#include "mink/narrowphase/shape_geometry.hpp"
#include "shape_core.hpp"

namespace mink {

namespace {

// The nearest entry so far, local coordinates.
struct LocalHit {
  Real fraction = std::numeric_limits<Real>::infinity();
  Vec2 normal{0, 0};

  void offer(Real t, const Vec2& n) {
    if (t >= 0 && t <= 1 && t < fraction) {
      fraction = t;
      normal = n;
    }
  }
};

// Where p + t d enters the disk (c, r), p outside it: from the foot of the perpendicular,
// which loses fewer digits than the textbook quadratic.
void disk_entry(const Vec2& p, const Vec2& d, const Vec2& c, Real r, LocalHit& hit) {
  const Real dd = d.squaredNorm();
  if (dd == 0) return;
  const Vec2 f = p - c;
  const Real foot = -f.dot(d) / dd;
  const Vec2 nearest = f + foot * d;
  const Real h2 = r * r - nearest.squaredNorm();
  if (h2 < 0) return;
  const Real t = foot - std::sqrt(h2 / dd);
  hit.offer(t, (f + t * d) / r);
}

// Where p + t d crosses, from outside, the side of the strip along a -> b pushed out by r
// along the outward unit normal n, within the strip's length.
void side_entry(const Vec2& p, const Vec2& d, const Vec2& a, const Vec2& b, const Vec2& n, Real r,
                LocalHit& hit) {
  const Real approach = n.dot(d);
  if (!(approach < 0)) return;
  const Real t = (r - n.dot(p - a)) / approach;
  const Vec2 e = b - a;
  const Real s = (p + t * d - a).dot(e);
  if (s < 0 || s > e.squaredNorm()) return;
  hit.offer(t, n);
}

Vec2 right_normal(const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  return Vec2(e.y(), -e.x()).normalized();
}

}  // namespace

std::optional<RayHit> ray_cast(const ShapeGeometry& geometry, const Pose& pose, const Vec2& origin,
                               const Vec2& translation) {
  const ShapeKind kind = kind_of(geometry);
  const detail::Core core = detail::core_of(geometry);
  if (kind == ShapeKind::polygon && core.radius == 0) {
    return ray_cast_hull(core.hull->hull(), pose, origin, translation);
  }
  const Vec2 p = pose.apply_inverse(origin);
  const Vec2 d = pose.rotation.apply_inverse(translation);
  LocalHit hit;
  if (kind == ShapeKind::segment || kind == ShapeKind::chain_segment) {
    const Vec2& a = core.small[0];
    const Vec2& b = core.small[1];
    const Vec2 n = right_normal(a, b);
    const Real approach = n.dot(d);
    const Real offset = n.dot(p - a);
    if (approach == 0) return std::nullopt;
    // A chain segment is seen only from its right side, moving towards it.
    if (kind == ShapeKind::chain_segment && !(offset >= 0 && approach < 0)) return std::nullopt;
    const Real t = -offset / approach;
    const Vec2 e = b - a;
    const Real s = (p + t * d - a).dot(e);
    if (s < 0 || s > e.squaredNorm()) return std::nullopt;
    hit.offer(t, approach < 0 ? n : Vec2(-n));
  } else {
    if (contains_point(geometry, pose, origin)) return std::nullopt;  // starts inside
    const Real r = core.radius;
    // The rounded shape is the core swept by a disk: its boundary is made of the core's edges
    // pushed out by r and the disks at its vertices, so the first entry is the first of those.
    for (std::size_t i = 0; i < core.size(); ++i) disk_entry(p, d, core.point(i), r, hit);
    if (core.size() == 2) {
      const Vec2 n = right_normal(core.small[0], core.small[1]);
      side_entry(p, d, core.small[0], core.small[1], n, r, hit);
      side_entry(p, d, core.small[1], core.small[0], -n, r, hit);
    } else if (core.hull != nullptr) {
      const std::size_t n = core.size();
      for (std::size_t i = 0; i < n; ++i) {
        side_entry(p, d, core.point(i), core.point(i + 1 == n ? 0 : i + 1), core.hull->normals()[i],
                   r, hit);
      }
    }
  }
  if (!(hit.fraction <= 1)) return std::nullopt;
  RayHit result;
  result.fraction = hit.fraction;
  result.point = origin + hit.fraction * translation;
  result.normal = pose.rotation.apply(hit.normal.normalized());
  return result;
}

}  // namespace mink
