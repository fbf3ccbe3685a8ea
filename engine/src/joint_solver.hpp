#pragma once

#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "id_pool.hpp"
#include "joint.hpp"
#include "joint_chain_solver.hpp"

namespace mink::detail {

// The joints' part of each substep stage, run by the contact solver's substep loop before its
// contacts: one joint at a time, in the order prepare_joints chose.
class JointStages {
 public:
  void set(IdPool<Joint>* joints, const std::vector<std::uint32_t>* order) {
    joints_ = joints;
    order_ = order;
  }
  bool empty() const { return order_ == nullptr || order_->empty(); }
  void warm_start(SolverBody* bodies);
  void solve(SolverBody* bodies, bool use_bias);
  JointChainSolver& chains() { return chains_; }

 private:
  JointChainSolver chains_;
  IdPool<Joint>* joints_ = nullptr;
  const std::vector<std::uint32_t>* order_ = nullptr;
};

}  // namespace mink::detail
