#pragma once

#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "id_pool.hpp"
#include "joint.hpp"
#include "joint_chain_solver.hpp"

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
  const std::vector<std::uint32_t>& color_begin() const { return *color_begin_; }
  // Joints order[begin, end).
  void warm_start(SolverBody* bodies, std::uint32_t begin, std::uint32_t end);
  void solve(SolverBody* bodies, bool use_bias, std::uint32_t begin, std::uint32_t end);
  void solve_chains(SolverBody* bodies, bool use_bias);
  JointChainSolver& chains() { return chains_; }

 private:
  JointChainSolver chains_;
  IdPool<Joint>* joints_ = nullptr;
  const std::vector<std::uint32_t>* order_ = nullptr;
  const std::vector<std::uint32_t>* color_begin_ = nullptr;
};

}  // namespace mink::detail
