#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "mink/broadphase/broadphase.hpp"
#include "mink/geometry/aabb.hpp"
#include "mink/narrowphase/time_of_impact.hpp"

namespace mink::detail {

// What a sweep test reads of a sweep, worked out once: its poses at both ends, and how far its
// turn bends a point's path below the straight line between them, per metre from the centre
// of mass (1 - cos(turn / 2) for a turn within half a revolution; 2 beyond).
struct SweepEnds {
  Pose start, end;
  Real dip = 0;
  SweepEnds() = default;
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

// A body that moved fast this step: its sweep over the step, the box around it, and the
// fraction of the step it may keep (1 when nothing was in the way).
struct FastBody {
  std::uint32_t body = 0;
  std::uint32_t solver_index = 0;
  Sweep sweep;  // valid once has_sweep: found only for a body with something to meet
  bool has_sweep = false;
  // The sweep measured from its start (the frame each pair is swept in) and its ends.
  Sweep local_sweep;
  SweepEnds local_ends;
  void set_sweep(const Sweep& world_sweep) {
    sweep = world_sweep;
    has_sweep = true;
    local_sweep = world_sweep;
    local_sweep.center0 = Vec2(0, 0);
    local_sweep.center1 = world_sweep.center1 - world_sweep.center0;
    local_ends = SweepEnds(local_sweep);
  }
  // The sweep's start and end rotations, for fast bodies meeting each other (set with it then).
  Rotation rotation0{}, rotation1{};
  Aabb box;
  // Each shape's box over the step lies in its broadphase box: the body's contacts then hold
  // every static and kinematic shape the sweep can meet, and no query is needed.
  bool covered = false;
  Real fraction = 1;
  bool bullet = false;
};

// Continuous collision's per-step lists: the fast bodies in body order, and per worker the
// broadphase candidates of the body it is sweeping.
struct ContinuousState {
  // Per solver body, set by finish_body in parallel: whether it moved fast, and then its box
  // over the step and whether its broadphase boxes cover it (FastBody's).
  std::vector<std::uint8_t> fast_mark;
  std::vector<Aabb> fast_box;
  std::vector<std::uint8_t> fast_covered;
  void prepare_marks(std::size_t solver_bodies) {
    fast_mark.assign(solver_bodies, 0);
    fast_box.resize(solver_bodies);
    fast_covered.resize(solver_bodies);
  }
  void mark(std::size_t solver_index, const Aabb& swept, bool covered) {
    fast_mark[solver_index] = 1;
    fast_box[solver_index] = swept;
    fast_covered[solver_index] = covered ? 1 : 0;
  }
  // The step's fast bodies: the first fast_count of `fast`, whose records are kept from step
  // to step (only the fields a step starts from are set anew, not the whole record).
  std::vector<FastBody> fast;
  std::size_t fast_count = 0;
  std::span<FastBody> fast_bodies() { return {fast.data(), fast_count}; }
  std::span<const FastBody> fast_bodies() const { return {fast.data(), fast_count}; }
  // Indices into `fast` of the boxes of common width, by lower x, with the running largest
  // upper x along them; and of the few far wider ones (a fast spinning bar), which would
  // stretch every scan, apart.
  std::vector<std::uint32_t> fast_by_x;
  std::vector<Aabb> fast_boxes_by_x;  // their boxes, in that order: a scan reads no FastBody
  std::vector<Real> fast_reach_x;
  std::vector<std::uint32_t> fast_wide;
  std::vector<Real> widths;  // scratch
  std::vector<std::vector<std::uint32_t>> candidates;
  std::size_t hits = 0;  // fast bodies stopped short this step
};

}  // namespace mink::detail
