#pragma once

#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "id_pool.hpp"
#include "joint.hpp"
#include "joint_chain_solver.hpp"
#include "joint_rows.hpp"

namespace mink::detail {

// The joints' part of each substep stage, run by the contact solver's substep loop before its
// contacts, in the order prepare_joints chose: colour by colour (the overflow last), the
// chains' point rows first in each solve. A colour's joints share no moving body, so the
// solver may run any range of a colour on any worker.
class JointStages {
 public:
  // `order`: the joints, by colour; `color_begin`: where each colour starts in it (one past the
  // overflow at the end).
  void set(IdPool<Joint>* joints, const std::vector<std::uint32_t>* order,
           const std::vector<std::uint32_t>* color_begin) {
    joints_ = joints;
    order_ = order;
    color_begin_ = color_begin;
  }
  bool empty() const { return order_ == nullptr || order_->empty(); }
  // Room for each joint of the order; none is a pin until gather() makes it one.
  void reset(std::size_t joint_count) {
    pins_.resize(joint_count);
    ends_.resize(joint_count);
    is_pin_.assign(joint_count, 0);
  }
  // Takes what the step's passes read of the joint at `position` of the order, from its
  // prepared frame, while its record is in cache: its ends for the chains, and, if it is only
  // a point row, a pin row it is then solved from instead of its record. Thread safe across
  // positions.
  void gather(std::uint32_t position, Joint& joint);
  // Finds the chains (JointChainSolver::build); their joints are not pins.
  void build_chains(bool enabled);
  // The pin row at `position` of the order, whose impulse its joint takes back once the
  // substeps are done; nullptr when that joint is not a pin.
  const PinRow* pin_at(std::uint32_t position) const {
    return is_pin_[position] != 0 ? &pins_[position] : nullptr;
  }
  const std::vector<std::uint32_t>& color_begin() const { return *color_begin_; }
  // Joints order[begin, end).
  void warm_start(SolverBody* bodies, std::uint32_t begin, std::uint32_t end);
  void solve(SolverBody* bodies, bool use_bias, std::uint32_t begin, std::uint32_t end);
  void solve_chains(SolverBody* bodies, bool use_bias);

 private:
  JointChainSolver chains_;
  std::vector<PinRow> pins_;          // per position of the order: valid where is_pin_
  std::vector<JointEnds> ends_;       // per position of the order
  std::vector<std::uint8_t> is_pin_;  // bytes, not bits: set from several threads
  IdPool<Joint>* joints_ = nullptr;
  const std::vector<std::uint32_t>* order_ = nullptr;
  const std::vector<std::uint32_t>* color_begin_ = nullptr;
};

}  // namespace mink::detail
