#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "mink/broadphase/broadphase.hpp"
#include "mink/geometry/aabb.hpp"
#include "mink/narrowphase/time_of_impact.hpp"
#include "worker_marks.hpp"

namespace mink::detail {

// What a sweep test reads of a sweep, worked out once: its poses at both ends, and how far its
// turn bends a point's path below the straight line between them, per metre from the centre
// of mass (1 - cos(turn / 2) for a turn within half a revolution; 2 beyond).
struct SweepEnds {
  Pose start, end;
  Real dip = 0;
  SweepEnds() = default;
  SweepEnds(const Pose& start_pose, const Pose& end_pose, Real turn_dip)
      : start(start_pose), end(end_pose), dip(turn_dip) {}
  explicit SweepEnds(const Sweep& sweep) : start(sweep.pose_at(0)), end(sweep.pose_at(1)) {
    const Real turn = std::abs(sweep.angle1 - sweep.angle0);
    dip = turn <= std::numbers::pi ? 1 - std::cos(0.5 * turn) : 2;
  }
  // How far `point` (in the body's frame; `local_center` its centre of mass there) can stray
  // over the step from the straight line between its places at the two ends.
  Real stray(const Vec2& point, const Vec2& local_center) const {
    return dip * (point - local_center).norm();
  }
};

// A fast body's shape at both ends of its step, for the tests that settle most of its pairs
// with still shapes without a time of impact: its core points where the step starts and ends
// (in the frame its pairs are swept in), each with how far its path strays from the line
// between them (SweepEnds::stray), and the same for its middle. The core only up to
// kQuickPoints points (has_core false beyond: its pairs are swept).
inline constexpr std::size_t kQuickPoints = 16;
struct QuickShape {
  std::array<Vec2, kQuickPoints> start, end;
  std::array<Real, kQuickPoints> stray;
  std::size_t count = 0;
  Real radius = 0;
  Vec2 middle_start{0, 0}, middle_end{0, 0};
  Real middle_stray = 0;
  bool has_core = false;
};

// A body that moved fast this step and is left to solve_continuous (ContinuousState::kSwept):
// its sweep over the step, the box around it, and the fraction of the step it may keep.
// finish_body writes it whole while the body's record is at hand: three cache lines.
struct alignas(64) FastBody {
  // The first line holds what every fast body's search reads (most find nothing in their way).
  std::uint32_t body = 0;
  std::uint32_t solver_index = 0;
  bool bullet = false;
  // Each shape's box over the step lies in its broadphase box: the body's contacts then hold
  // every static and kinematic shape the sweep can meet, and no query is needed.
  bool covered = false;
  bool has_sweep = false;
  Aabb box;
  Real fraction = 1;  // 1 when nothing was in the way
  Real slow = 0;      // continuous_threshold * min_extent: what it may travel past others unswept
  Real extent = 0;    // its body's
  Sweep sweep;        // valid once has_sweep: found only for a body with something to meet
  // The sweep's start and end rotations, for fast bodies meeting each other (set with it then).
  Rotation rotation0{}, rotation1{};
};
static_assert(offsetof(FastBody, slow) + sizeof(Real) <= 64);
static_assert(sizeof(FastBody) == 192, "finish_body writes three lines of a FastBody");

inline bool is_still(const Sweep& sweep) {
  return sweep.center0 == sweep.center1 && sweep.angle0 == sweep.angle1;
}

// Another body's sweep in a fast body's frame (measured from where the fast body starts), its
// pose there when the step began, and whether it stood still: found once for all the pairs of
// the two bodies' shapes.
struct FramedSweep {
  Sweep sweep;
  Pose start;
  bool still = false;
  FramedSweep() = default;
  FramedSweep(const Sweep& world_sweep, const Vec2& frame_origin) : sweep(world_sweep) {
    sweep.center0 -= frame_origin;
    sweep.center1 -= frame_origin;
    start = sweep.pose_at(0);
    still = is_still(sweep);
  }
};

// A fast body's sweep measured from its start (the frame each of its pairs is swept in) and
// its ends: found only for a body with a pair to sweep.
struct LocalSweep {
  Sweep sweep;
  SweepEnds ends;
  LocalSweep() = default;
  explicit LocalSweep(const Sweep& world_sweep) : sweep(world_sweep) {
    sweep.center0 = Vec2(0, 0);
    sweep.center1 = world_sweep.center1 - world_sweep.center0;
    ends = SweepEnds(sweep);
  }
};

// Continuous collision's per-step lists: the fast bodies in body order, and per worker the
// broadphase candidates of the body it is sweeping.
struct ContinuousState {
  // Per solver body, set by finish_body in parallel: whether it moved fast (kNotFast, else
  // kSwept or kClear), and its FastBody if it is to be swept (a record kept from step to step,
  // valid only where is_fast is kSwept).
  static constexpr std::uint8_t kNotFast = 0;
  static constexpr std::uint8_t kSwept = 1;  // solve_continuous sweeps it
  // Fast, but finish_body found nothing in its way that the cheap tests leave: nothing to
  // sweep, and no record written (most fast bodies, in free flight).
  static constexpr std::uint8_t kClear = 2;
  std::vector<std::uint8_t> is_fast;
  std::vector<FastBody> fast;
  void prepare_marks(std::size_t solver_bodies, std::uint32_t workers) {
    is_fast.assign(solver_bodies, kNotFast);
    if (fast.size() < solver_bodies) fast.resize(solver_bodies);
    candidates.resize(workers);
    proxies.resize(workers);
    quick.resize(workers);
  }
  // The step's fast bodies to sweep, by solver index (so in body order, as sensors meet them).
  std::vector<std::uint32_t> fast_list;
  FastBody& fast_body(std::size_t k) { return fast[fast_list[k]]; }
  const FastBody& fast_body(std::size_t k) const { return fast[fast_list[k]]; }
  // Places in fast_list of the boxes of common width, by lower x, with the running largest
  // upper x along them; and of the few far wider ones (a fast spinning bar), which would
  // stretch every scan, apart.
  std::vector<std::uint32_t> fast_by_x;
  std::vector<Aabb> fast_boxes_by_x;  // their boxes, in that order: a scan reads no FastBody
  std::vector<Real> fast_reach_x;
  std::vector<std::uint32_t> fast_wide;
  std::vector<Real> widths;   // scratch
  std::vector<Real> lower_x;  // the fast bodies' boxes' lower x, side by side for the sort
  // Per worker: the shapes in the way of the fast body it is looking at, the broadphase's
  // answer for a bullet, and the body's shapes at the ends of its step.
  std::vector<std::vector<std::uint32_t>> candidates;
  std::vector<std::vector<ProxyId>> proxies;
  std::vector<std::vector<QuickShape>> quick;
  // The fast bodies (by solver index) stopped short this step, marked by the workers.
  WorkerMarks stopped;
  std::size_t hits = 0;  // fast bodies stopped short this step
};

// Whether scale (|(x, y)| + reach) > limit, as computed with the square root (moved_fast's
// test, for every body the solver moved). Most bodies are far from the limit either way, and
// bounds on the length from its sides (|x| + |y| above, the larger below) tell without it; the
// slack covers every rounding, so the answer is always the square root's.
inline bool travels_beyond(Real x, Real y, Real reach, Real scale, Real limit) {
  constexpr Real kSlack = 1e-9;
  // Beyond these the squares may underflow or overflow, and the square root then answers
  // otherwise than the bounds.
  constexpr Real kTiny = 1e-80, kHuge = 1e150;
  const Real ax = std::abs(x), ay = std::abs(y), larger = std::max(ax, ay);
  if (limit > kTiny && larger < kHuge) {
    if (scale * (ax + ay + reach) < limit * (1 - kSlack)) return false;
    if (scale * (larger + reach) > limit * (1 + kSlack)) return true;
  }
  return scale * (std::sqrt(x * x + y * y) + reach) > limit;
}

}  // namespace mink::detail
