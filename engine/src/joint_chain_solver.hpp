#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "contact_solver.hpp"
#include "id_pool.hpp"
#include "joint.hpp"

namespace mink::detail {

// A direct solve for chains of revolute joints. Gauss-Seidel passes one joint at a time
// and carries a heavy body's weight up a chain of light links only slowly: a heavy weight on
// a light chain stretches it, the known weakness of sequential impulses. Where the revolute
// joints form paths (each moving body in at most two of them, no loop), the point rows of a
// path form a block-tridiagonal system, solved exactly in linear time (block Thomas
// algorithm) in every solve and relax pass, with the same softness as the one-joint rows.
// Their other rows (springs, motors, limits) and every other joint stay one at a time.
// A joint's two bodies as its frame has them for the step, and whether it is a revolute.
struct JointEnds {
  std::array<JointBody, 2> bodies{};
  bool revolute = false;
};

class JointChainSolver {
 public:
  // Finds the paths among `order`'s revolute joints (`ends`: per place in `order`) and marks
  // their joints as solved here (none when not `enabled`: every revolute then solves its own
  // point row). A revolute joint's `direct` must be false until then.
  void build(IdPool<Joint>& joints, const std::vector<std::uint32_t>& order,
             std::span<const JointEnds> ends, bool enabled);
  // Warm starts the point rows of paths [first, last) with their impulses (a chained joint's
  // angle rows warm start their own); as solve(), in any split over workers.
  void warm_start(IdPool<Joint>& joints, SolverBody* bodies, std::uint32_t first,
                  std::uint32_t last);
  // Solves paths [first, last). Paths share no moving body (a body is in at most two of the
  // chained joints, both of one path) and each joint has its own copies of fixed bodies, so
  // any split of the paths over workers gives the same bits.
  void solve(IdPool<Joint>& joints, SolverBody* bodies, bool use_bias, std::uint32_t first,
             std::uint32_t last);
  std::uint32_t path_count() const {
    return path_begin_.empty() ? 0 : static_cast<std::uint32_t>(path_begin_.size() - 1);
  }
  std::size_t chained_joints() const { return chain_joints_.size(); }
  // Where the chained joints are in `order`.
  const std::vector<std::uint32_t>& chain_positions() const { return chain_positions_; }

 private:
  // Per path: [begin, end) into chain_joints_.
  std::vector<std::uint32_t> path_begin_;
  std::vector<std::uint32_t> chain_joints_, chain_positions_;
  // Per chained joint: which side (0: A, 1: B) of it the next joint shares a body on, and
  // which side of the next joint that body is.
  std::vector<std::uint8_t> next_side_, next_other_side_;
  // Scratch per chained joint.
  struct Row {
    Vec2 ra{0, 0}, rb{0, 0};          // anchors from the centres of mass now
    Eigen::Matrix2d diagonal, upper;  // K_ii and K_i,i+1
    Eigen::Matrix2d eliminated;       // the Thomas algorithm's C'_i
    Vec2 rhs{0, 0};
  };
  std::vector<Row> rows_;
};

}  // namespace mink::detail
