#pragma once

// A brute-force sampled sweep for time of impact tests. It knows nothing of GJK or of the
// library's advancement: positions come from the sweep's definition (centre and angle linear in
// t), distances from scanning every core point against every core point and edge.
//
// Sampling is adaptive but cannot step over a crossing: no core point moves faster than
// |v_A - v_B| + |w_A| rho_A + |w_B| rho_B (the Lipschitz constant L of the distance, with rho the
// largest distance from a body's turning point to its core), so from a sample g above a
// threshold the next sample may lie (g - threshold) / L later without the distance dipping
// below the threshold in between. Steps never shrink below `resolution` / L, so a dip between
// two samples is at most resolution / 2 deep; past the first sample below the threshold the
// crossing is refined by bisection.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mink/narrowphase/time_of_impact.hpp"
#include "shape_oracle.hpp"

namespace mink_test {

using mink::Sweep;

// A moving shape: its core points about the point it turns about, its radius, its sweep.
struct SweptShape {
  std::vector<Vec2> arm;  // core points less the sweep's local centre, body frame
  Real radius = 0;
  Sweep sweep;
  Real reach = 0;  // the longest arm

  SweptShape(const ShapeGeometry& shape, const Sweep& s) : sweep(s) {
    const WorldCore local = world_core(shape, Pose{});
    radius = local.radius;
    for (const Vec2& p : local.points) {
      arm.push_back(p - s.local_center);
      reach = std::max(reach, arm.back().norm());
    }
  }

  // The core's world points at t, written into `out` (sized once, reused).
  void place(Real t, std::vector<Vec2>& out) const {
    const Real angle = (1 - t) * sweep.angle0 + t * sweep.angle1;
    const Real c = std::cos(angle), s = std::sin(angle);
    const Vec2 centre = (1 - t) * sweep.center0 + t * sweep.center1;
    out.resize(arm.size());
    for (std::size_t i = 0; i < arm.size(); ++i) {
      out[i] = centre + Vec2(c * arm[i].x() - s * arm[i].y(), s * arm[i].x() + c * arm[i].y());
    }
  }

  WorldCore world_at(Real t) const {
    WorldCore core;
    place(t, core.points);
    core.radius = radius;
    return core;
  }
};

// Squared distance from p to the segment a-b.
inline Real point_segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const Vec2 f = p - a;
  const Real along = f.dot(e);
  if (along <= 0) return f.squaredNorm();
  const Real len2 = e.squaredNorm();
  if (along >= len2) return (p - b).squaredNorm();
  return (f - (along / len2) * e).squaredNorm();
}

// Squared distance from p to the core q (a point, a segment or a CCW polygon's boundary).
inline Real point_core_distance2(const Vec2& p, const std::vector<Vec2>& q) {
  if (q.size() == 1) return (p - q[0]).squaredNorm();
  Real best = std::numeric_limits<Real>::infinity();
  const std::size_t edges = q.size() == 2 ? 1 : q.size();
  for (std::size_t i = 0; i < edges; ++i) {
    best = std::min(best, point_segment_distance2(p, q[i], q[i + 1 == q.size() ? 0 : i + 1]));
  }
  return best;
}

// Distance between two disjoint cores: every point of each against the other. Wrong (too
// large) once the cores overlap; the sweep never asks past its first sample below a positive
// threshold, before which they cannot overlap.
inline Real disjoint_core_distance(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const Vec2& v : p) best = std::min(best, point_core_distance2(v, q));
  for (const Vec2& w : q) best = std::min(best, point_core_distance2(w, p));
  return std::sqrt(best);
}

// The first time the surface separation drops below a threshold, as the sampled sweep sees it.
struct Crossing {
  bool found = false;
  Real time = 0;        // a time with separation below the threshold (bisected to the edge)
  int evaluations = 0;  // distance scans made
};

class SweepOracle {
 public:
  SweepOracle(const SweptShape& a, const SweptShape& b) : a_(a), b_(b) {
    const Vec2 relative = (a.sweep.center1 - a.sweep.center0) - (b.sweep.center1 - b.sweep.center0);
    lipschitz_ = relative.norm() + std::abs(a.sweep.angle1 - a.sweep.angle0) * a.reach +
                 std::abs(b.sweep.angle1 - b.sweep.angle0) * b.reach;
  }

  // Surface separation at t, exact for any placement (overlapping cores give minus the depth):
  // for spot checks.
  Real exact_separation(Real t) const { return signed_gap(a_.world_at(t), b_.world_at(t)).gap; }

  // Surface separation at t by the scans alone: right while the cores are apart, too large
  // once they overlap.
  Real scan_separation(Real t) const {
    Crossing unused;
    return gap(t, unused) - a_.radius - b_.radius;
  }

  // The first sample in [from, to] whose separation is below `threshold` (surface terms;
  // threshold + radii must exceed `resolution`), then bisected towards the last sample above.
  // At `from` the cores must be apart.
  Crossing first_below(Real threshold, Real from, Real to, Real resolution) const {
    const Real core_threshold = threshold + a_.radius + b_.radius;
    Crossing c;
    Real t = from;
    Real g = gap(t, c);
    Real previous = t;
    for (;;) {
      if (g < core_threshold) {
        c.found = true;
        Real lo = previous, hi = t;
        for (int k = 0; k < 20 && t > from; ++k) {
          const Real mid = 0.5 * (lo + hi);
          (gap(mid, c) < core_threshold ? hi : lo) = mid;
        }
        c.time = hi;
        return c;
      }
      if (t >= to) return c;
      previous = t;
      const Real margin = std::max(g - core_threshold, resolution);
      t = lipschitz_ > 0 ? std::min(to, t + margin / lipschitz_) : to;
      g = gap(t, c);
    }
  }

  Real lipschitz() const { return lipschitz_; }

 private:
  Real gap(Real t, Crossing& c) const {
    ++c.evaluations;
    a_.place(t, pa_);
    b_.place(t, pb_);
    return disjoint_core_distance(pa_, pb_);
  }

  const SweptShape& a_;
  const SweptShape& b_;
  Real lipschitz_ = 0;
  mutable std::vector<Vec2> pa_, pb_;
};

}  // namespace mink_test
