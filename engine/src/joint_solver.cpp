// The joints' part of a step. After the contacts are prepared: the joints of moving bodies,
// in colour order then slot order, get their frames for the step. In every substep stage the
// solver runs them before the contacts (warm start, solve with bias, relax); after the solve
// each joint records the force it applied, reports a break, and settles its coordinate.

#include <algorithm>

#include "joint_solver.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Joint;

namespace detail {

void JointStages::warm_start(SolverBody* bodies) {
  for (const std::uint32_t j : *order_) {
    Joint& joint = (*joints_)[j];
    std::visit([&](auto& k) { detail::warm_start(k, joint.frame, bodies); }, joint.kind);
  }
}

void JointStages::solve(SolverBody* bodies, bool use_bias) {
  // The chains' point rows first: the one-at-a-time rows after them (motors, limits, gears)
  // then end each pass satisfied, as they would alone.
  chains_.solve(*joints_, bodies, use_bias);
  for (const std::uint32_t j : *order_) {
    Joint& joint = (*joints_)[j];
    std::visit([&](auto& k) { detail::solve(k, joint.frame, bodies, use_bias); }, joint.kind);
  }
}

}  // namespace detail

void WorldState::prepare_joints() {
  step_joints.clear();
  for (const std::uint32_t i : solver_to_body) {
    for (const std::uint32_t j : bodies[i].joints) {
      Joint& joint = joints[j];
      if (joint.gathered_step == step_count) continue;
      joint.gathered_step = step_count;
      bool enabled = true, dynamic = false;
      for (int k = 0; k < joint.body_count; ++k) {
        const Body& b = bodies[joint.body[k]];
        enabled = enabled && b.enabled;
        dynamic = dynamic || b.type == BodyType::dynamic;
      }
      if (enabled && dynamic) step_joints.push_back(j);
    }
  }
  std::sort(step_joints.begin(), step_joints.end(), [&](std::uint32_t x, std::uint32_t y) {
    const std::uint8_t cx = joints[x].color, cy = joints[y].color;
    return cx != cy ? cx < cy : x < y;
  });
  counters.joints = step_joints.size();

  const Real h = dt / substeps;
  const Real joint_hertz = std::min(def.joint_hertz, 0.25 * substeps / dt);
  const detail::Softness soft = detail::make_softness(joint_hertz, def.joint_damping_ratio, h);
  for (const std::uint32_t j : step_joints) {
    Joint& joint = joints[j];
    detail::JointFrame& frame = joint.frame;
    frame = detail::JointFrame{};
    frame.h = h;
    frame.inv_h = 1 / h;
    frame.soft = soft;
    for (int k = 0; k < joint.body_count; ++k) {
      const std::uint32_t bi = joint.body[k];
      const Body& b = bodies[bi];
      detail::JointBody& jb = frame.bodies[static_cast<std::size_t>(k)];
      const std::int32_t s = body_solver_index[bi];
      jb.solver = s < 0 ? still_body : s;
      jb.center = b.center;
      jb.rotation = b.rotation;
      jb.local_center = b.local_center;
      if (s >= 0) {
        jb.inv_mass = solver_info[static_cast<std::size_t>(s)].inv_mass;
        jb.inv_inertia = solver_info[static_cast<std::size_t>(s)].inv_inertia;
      }
    }
    if (joint.body_count == 4) {
      // A gear reads its joints' coordinates as the step begins.
      frame.coordinate_a = joint_coordinate(joint.gear_joints[0]);
      frame.coordinate_b = joint_coordinate(joint.gear_joints[1]);
    }
    std::visit([&](auto& k) { detail::prepare(k, frame); }, joint.kind);
  }
  joint_stages.set(&joints, &step_joints);
  joint_stages.chains().build(joints, step_joints, def.direct_joint_chains);
}

void WorldState::finish_joints() {
  joint_break_events.clear();
  for (const std::uint32_t j : step_joints) {
    Joint& joint = joints[j];
    joint.reaction =
        std::visit([&](const auto& k) { return detail::reaction(k, joint.frame); }, joint.kind);
    const JointBase& b = base(joint);
    if (joint.reaction.force.norm() > b.break_force ||
        std::abs(joint.reaction.torque) > b.break_torque) {
      joint_break_events.push_back(
          {joint_id(j), joint.reaction.force, joint.reaction.torque, b.user_data});
    }
    const detail::JointBodyState sa = joint_body_state(joint.body[0]);
    const detail::JointBodyState sb = joint_body_state(joint.body[1]);
    std::visit([&](auto& k) { detail::finish_kind(k, sa, sb); }, joint.kind);
  }
  std::sort(joint_break_events.begin(), joint_break_events.end(),
            [](const JointBreakEvent& x, const JointBreakEvent& y) {
              return x.joint.index < y.joint.index;
            });
}

}  // namespace mink
