#include "mink/narrowphase/time_of_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "gjk_distance_loop.hpp"
#include "mink/error.hpp"
#include "shape_core.hpp"

namespace mink {

namespace {

bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

void check_sweep(const Sweep& s, const char* name) {
  if (!finite(s.local_center) || !finite(s.center0) || !finite(s.center1) ||
      !std::isfinite(s.angle0) || !std::isfinite(s.angle1)) {
    throw InvalidArgumentError(std::string("time_of_impact: ") + name + " is not finite");
  }
}

Real radius_of(const ShapeGeometry& shape) {
  return detail::core_of(shape).radius;
}

void check(const TimeOfImpactInput& in) {
  if (in.shape_a == nullptr) throw InvalidArgumentError("time_of_impact: shape_a is null");
  if (in.shape_b == nullptr) throw InvalidArgumentError("time_of_impact: shape_b is null");
  check_sweep(in.sweep_a, "sweep_a");
  check_sweep(in.sweep_b, "sweep_b");
  if (!(in.max_fraction >= 0 && in.max_fraction <= 1)) {
    throw InvalidArgumentError("max_fraction must be in [0, 1], got " +
                               std::to_string(in.max_fraction));
  }
  if (!(in.tolerance > 0) || !std::isfinite(in.tolerance)) {
    throw InvalidArgumentError("tolerance must be finite and > 0, got " +
                               std::to_string(in.tolerance));
  }
  const Real radii = radius_of(*in.shape_a) + radius_of(*in.shape_b);
  // GJK measures cores that are apart; overlapping cores have no normal to advance along.
  if (!std::isfinite(in.target) || !(in.target + radii > in.tolerance)) {
    throw InvalidArgumentError(
        "target + radii must exceed the tolerance, got "
        "target " +
        std::to_string(in.target) + " with radii " + std::to_string(radii) + " and tolerance " +
        std::to_string(in.tolerance));
  }
  if (in.max_iterations < 1) {
    throw InvalidArgumentError("max_iterations must be >= 1, got " +
                               std::to_string(in.max_iterations));
  }
}

// A body's motion as the advancement bound needs it.
struct Mover {
  detail::Core core;
  Vec2 local_center{0, 0};
  Vec2 velocity{0, 0};  // of the centre, per unit of the fraction
  Real spin = 0;        // radians per unit of the fraction, signed
  Real reach = 0;       // the longest arm: core point less the turning point

  Mover(const ShapeGeometry& shape, const Sweep& sweep)
      : core(detail::core_of(shape)),
        local_center(sweep.local_center),
        velocity(sweep.center1 - sweep.center0),
        spin(sweep.angle1 - sweep.angle0) {
    Real r2 = 0;
    for (std::size_t i = 0; i < core.size(); ++i) {
      r2 = std::max(r2, (core.point(i) - local_center).squaredNorm());
    }
    reach = std::sqrt(r2);
  }

  // How far the arms reach along the world direction d with the body turned by `rotation`,
  // and at least 0.
  Real arm_reach(const Rotation& rotation, const Vec2& d) const {
    const Vec2 local = rotation.apply_inverse(d);
    return std::max(Real(0), local.dot(core.point(core.support(local)) - local_center));
  }
};

// How long (in fraction) the separation of the cores along the fixed normal n (unit, A towards
// B), now `gap` above the target, surely stays above it. Each body's support along n (along -n
// for B) moves with its centre and gains from turning; an arm p (a core point less the turning
// point, in world axes) turned by phi, |phi| = psi, gains along u at most
// - linear: psi |p|, for any psi;
// - quadratic: u.(R(phi) p - p) = (cos psi - 1) u.p + sin psi sign(phi) u.perp(p)
//   <= psi max(0, sign(phi) u.perp(p)) + psi^2 / 2 max(0, -u.p), for psi up to half a turn
//   (where sin psi >= 0), which is small for arms nearly along u: a thin body pointing at the
//   other gains little by turning, so grazing passes take far fewer steps.
// Since max_q f(q) - max_q g(q) <= max_q (f(q) - g(q)), what bounds every arm bounds the
// support. Either bound may be used alone, so the later of their first crossings is safe.
Real safe_interval(Real gap, const Vec2& n, const Mover& a, const Rotation& ra, const Mover& b,
                   const Rotation& rb) {
  constexpr Real kNever = std::numeric_limits<Real>::infinity();
  if (!(gap > 0)) return 0;  // only a badly rounded normal gets here: no advance is safe
  const Real along = n.dot(a.velocity - b.velocity);
  const Real rate = along + std::abs(a.spin) * a.reach + std::abs(b.spin) * b.reach;
  const Real linear = rate > 0 ? gap / rate : kNever;
  // u.perp(p) = tangent.p for u = n; B's support is along -n, whose tangent is -tangent.
  const Vec2 tangent(n.y(), -n.x());
  const Vec2 forward_a = a.spin >= 0 ? tangent : Vec2(-tangent);
  const Vec2 forward_b = b.spin >= 0 ? Vec2(-tangent) : tangent;
  const Real first = along + std::abs(a.spin) * a.arm_reach(ra, forward_a) +
                     std::abs(b.spin) * b.arm_reach(rb, forward_b);
  const Real second =
      0.5 * (a.spin * a.spin * a.arm_reach(ra, -n) + b.spin * b.spin * b.arm_reach(rb, n));
  // The first positive root of gap - first h - second h^2, in the form that keeps its digits.
  const Real root = first + std::sqrt(first * first + 4 * second * gap);
  const Real quadratic = root > 0 ? 2 * gap / root : kNever;
  // sin psi <= psi and sin psi >= 0 hold up to half a turn only.
  const Real fastest = std::max(std::abs(a.spin), std::abs(b.spin));
  const Real half_turn = fastest > 0 ? std::numbers::pi / fastest : kNever;
  return std::max(linear, std::min(quadratic, half_turn));
}

// The cores at one time: their distance (world), and how far B's core lies beyond A's along
// the normal, the separation the advancement bound speaks of.
struct Measure {
  bool overlap = false;
  Real distance = 0;
  Vec2 core_a{0, 0};
  Vec2 core_b{0, 0};
  Vec2 normal{0, 0};
  Real axis_separation = 0;
};

template <typename Frame>
Measure measure(const Frame& frame, const Pose& pose_a, SimplexCache& cache) {
  const detail::LocalDistance d = detail::distance_loop(frame, &cache);
  Measure m;
  m.overlap = d.overlap;
  m.core_a = pose_a.apply(d.point_a);
  m.core_b = pose_a.apply(d.point_b);
  if (d.overlap) return m;
  m.distance = d.distance;
  const Vec2 n = d.gap / d.distance;
  m.normal = pose_a.rotation.apply(n);
  // From support points, so a lower bound on the distance whatever the normal's rounding.
  m.axis_separation = -frame.support(n).point.dot(n);
  return m;
}

Measure measure_at(const detail::Core& a, const Pose& pose_a, const detail::Core& b,
                   const Pose& pose_b, SimplexCache& cache) {
  if (a.hull != nullptr && b.hull != nullptr) {
    return measure(detail::PairFrame(*a.hull, pose_a, *b.hull, pose_b), pose_a, cache);
  }
  return measure(detail::CoreFrame(a, b, relative_pose(pose_a, pose_b)), pose_a, cache);
}

void describe(TimeOfImpactOutput& out, Real t, const Measure& m, Real radius_a, Real radius_b) {
  out.fraction = t;
  out.separation = (m.overlap ? 0 : m.distance) - radius_a - radius_b;
  if (m.overlap) {
    out.point_a = m.core_a;
    out.point_b = m.core_b;
    return;
  }
  out.normal = m.normal;
  out.point_a = m.core_a + radius_a * m.normal;
  out.point_b = m.core_b - radius_b * m.normal;
}

}  // namespace

Pose Sweep::pose_at(Real t) const {
  Pose pose;
  pose.rotation = Rotation::from_angle(angle0 + t * (angle1 - angle0));
  const Vec2 center = center0 + t * (center1 - center0);
  pose.position = center - pose.rotation.apply(local_center);
  return pose;
}

Real slop_target(const ShapeGeometry& a, const ShapeGeometry& b, Real linear_slop) {
  if (!(linear_slop > 0) || !std::isfinite(linear_slop)) {
    throw InvalidArgumentError("slop_target: linear_slop must be finite and > 0, got " +
                               std::to_string(linear_slop));
  }
  const Real radii = radius_of(a) + radius_of(b);
  return std::max(linear_slop, radii - linear_slop) - radii;
}

TimeOfImpactOutput time_of_impact(const TimeOfImpactInput& in) {
  check(in);
  const Mover a(*in.shape_a, in.sweep_a);
  const Mover b(*in.shape_b, in.sweep_b);
  const Real radius_a = a.core.radius;
  const Real radius_b = b.core.radius;
  const Real target = in.target + radius_a + radius_b;  // between the cores

  TimeOfImpactOutput out;
  SimplexCache cache;  // consecutive times differ little: GJK starts from the last simplex
  Real t = 0;
  for (;;) {
    const Pose pose_a = in.sweep_a.pose_at(t);
    const Pose pose_b = in.sweep_b.pose_at(t);
    const Measure m = measure_at(a.core, pose_a, b.core, pose_b, cache);
    ++out.iterations;
    const Real distance = m.overlap ? 0 : m.distance;
    if (distance < target + in.tolerance) {
      out.state = t == 0 && distance < target - in.tolerance ? ToiState::overlapped : ToiState::hit;
      describe(out, t, m, radius_a, radius_b);
      return out;
    }
    // No time before `next` can bring the cores closer than target.
    const Real next = t + safe_interval(m.axis_separation - target, m.normal, a, pose_a.rotation, b,
                                        pose_b.rotation);
    if (next >= in.max_fraction) {
      out.state = ToiState::separated;
      out.fraction = in.max_fraction;
      return out;
    }
    if (out.iterations >= in.max_iterations) {
      out.state = ToiState::gave_up;
      describe(out, t, m, radius_a, radius_b);
      return out;
    }
    // A normal rounded badly enough to give no advance would stall here; the cap ends that.
    t = std::max(t, next);
  }
}

}  // namespace mink
