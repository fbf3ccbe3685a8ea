// The joints' part of a step. After the contacts are prepared: the joints of moving bodies,
// in colour order then slot order, get their frames for the step. In every substep stage the
// solver runs them before the contacts (warm start, solve with bias, relax), revolute joints
// from their rows; after the solve each joint takes back its row's impulses, records the force
// it applied, reports a break, and settles its coordinate.

#include <algorithm>
#include <bit>

#include "joint_solver.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Joint;

namespace detail {

void JointStages::gather(std::uint32_t position, Joint& joint) {
  const JointFrame& frame = joint.frame;
  auto* revolute = std::get_if<RevoluteJoint>(&joint.kind);
  ends_[position] = {{frame.bodies[0], frame.bodies[1]}, revolute != nullptr};
  if (revolute == nullptr) return;
  revolute->direct = false;
  const RevoluteJointDef& def = revolute->def;
  // Switched off rows have no impulse left (prepare drops them): the warm start's angular
  // impulse is zero, as a pin's.
  if (revolute->angle_rows || def.spring.enabled || def.motor.enabled || def.limit.enabled) {
    kind_[position] = RowKind::revolute;
    return;
  }
  PinRow& row = pins_[position];
  static_cast<PointRowFrame&>(row) = point_row_frame(frame);
  row.impulse = revolute->linear_impulse;
  kind_[position] = RowKind::pin;
}

std::size_t JointStages::build_chains(bool enabled) {
  chains_.build(*joints_, *order_, ends_, enabled);
  for (const std::uint32_t position : chains_.chain_positions()) {
    kind_[position] = RowKind::record;
  }
  revolute_positions_.clear();
  for (std::uint32_t position = 0; position < kind_.size(); ++position) {
    if (kind_[position] != RowKind::revolute) continue;
    row_slot_[position] = static_cast<std::uint32_t>(revolute_positions_.size());
    revolute_positions_.push_back(position);
  }
  revolute_rows_.resize(revolute_positions_.size());
  return revolute_positions_.size();
}

void JointStages::fill_revolute_row(std::uint32_t position, const Joint& joint) {
  fill_row(revolute_rows_[row_slot_[position]], std::get<RevoluteJoint>(joint.kind), joint.frame);
}

void JointStages::store_row(std::uint32_t position, Joint& joint) const {
  switch (kind_[position]) {
    case RowKind::record:
      return;
    case RowKind::pin:
      std::get<RevoluteJoint>(joint.kind).linear_impulse = pins_[position].impulse;
      return;
    case RowKind::revolute:
      detail::store_row(revolute_rows_[row_slot_[position]], std::get<RevoluteJoint>(joint.kind));
      return;
  }
}

void JointStages::warm_start(SolverBody* bodies, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t i = begin; i < end; ++i) {
    if (kind_[i] == RowKind::pin) {
      const PinRow& row = pins_[i];
      warm_start_point(bodies, row, row.impulse, 0);
      continue;
    }
    if (kind_[i] == RowKind::revolute) {
      detail::warm_start(revolute_rows_[row_slot_[i]], bodies);
      continue;
    }
    Joint& joint = (*joints_)[(*order_)[i]];
    std::visit([&](auto& k) { detail::warm_start(k, joint.frame, bodies); }, joint.kind);
  }
}

// The chains' point rows come first in a solve: the one-at-a-time rows after them (motors,
// limits, gears) then end each pass satisfied, as they would alone.
void JointStages::solve_chains(SolverBody* bodies, bool use_bias, std::uint32_t first,
                               std::uint32_t last) {
  chains_.solve(*joints_, bodies, use_bias, first, last);
}

void JointStages::solve(SolverBody* bodies, bool use_bias, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t i = begin; i < end; ++i) {
    if (kind_[i] == RowKind::pin) {
      PinRow& row = pins_[i];
      solve_point(bodies[row.bodies[0].solver], bodies[row.bodies[1].solver], row, use_bias,
                  row.impulse);
      continue;
    }
    if (kind_[i] == RowKind::revolute) {
      detail::solve(revolute_rows_[row_slot_[i]], bodies, use_bias);
      continue;
    }
    Joint& joint = (*joints_)[(*order_)[i]];
    std::visit([&](auto& k) { detail::solve(k, joint.frame, bodies, use_bias); }, joint.kind);
  }
}

}  // namespace detail

void WorldState::prepare_joints() {
  // The joints of moving bodies: marked from the bodies' lists (in parallel, an atomic or per
  // word when other threads mark too), those with a disabled body or none dynamic unmarked in
  // parallel, word by word, then read off in slot order into their colours (the overflow
  // last), which is the order they are solved in.
  constexpr std::size_t kColors = detail::kGraphColors + 1;
  joint_marks.assign((joints.size() + 63) / 64, 0);
  joint_slot_color.resize(joints.size());
  const bool concurrent = tasks.workers() > 1;
  tasks.parallel_for(static_cast<std::uint32_t>(solver_to_body.size()), 256,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         for (const std::uint32_t j : bodies[solver_to_body[k]].joints) {
                           detail::set_mark(joint_marks, j, concurrent);
                         }
                       }
                     });
  tasks.parallel_for(
      static_cast<std::uint32_t>(joint_marks.size()), 16,
      [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t word = begin; word < end; ++word) {
          std::uint64_t kept = joint_marks[word];
          for (std::uint64_t bits = kept; bits != 0; bits &= bits - 1) {
            const int bit = std::countr_zero(bits);
            const Joint& joint = joints[word * 64 + static_cast<std::uint32_t>(bit)];
            bool enabled = true, dynamic = false;
            for (int k = 0; k < joint.body_count; ++k) {
              const Body& b = bodies[joint.body[k]];
              enabled = enabled && b.enabled;
              dynamic = dynamic || b.type == BodyType::dynamic;
            }
            if (!enabled || !dynamic) kept &= ~(std::uint64_t{1} << bit);
            joint_slot_color[word * 64 + static_cast<std::uint32_t>(bit)] =
                static_cast<std::uint8_t>(std::min<std::size_t>(joint.color, kColors - 1));
          }
          joint_marks[word] = kept;
        }
      });
  joint_color_begin.assign(kColors + 1, 0);
  step_joints.clear();
  for (std::size_t word = 0; word < joint_marks.size(); ++word) {
    for (std::uint64_t bits = joint_marks[word]; bits != 0; bits &= bits - 1) {
      const auto j = static_cast<std::uint32_t>(word * 64 + std::countr_zero(bits));
      step_joints.push_back(j);
      ++joint_color_begin[joint_slot_color[j] + 1];
    }
  }
  for (std::size_t c = 1; c <= kColors; ++c) joint_color_begin[c] += joint_color_begin[c - 1];
  // step_joints in colour order; joint_order keeps them in slot order, the order of their
  // records in memory, which the passes over every joint's record follow.
  joint_order.resize(step_joints.size());
  joint_position.resize(step_joints.size());
  {
    std::vector<std::uint32_t>& fill = joint_fill;
    fill.assign(joint_color_begin.begin(), joint_color_begin.end() - 1);
    for (std::size_t k = 0; k < step_joints.size(); ++k) {
      const std::uint32_t j = step_joints[k];
      const std::uint32_t position = fill[joint_slot_color[j]]++;
      joint_order[position] = j;
      joint_position[k] = position;
    }
    step_joints.swap(joint_order);
  }
  counters.joints = step_joints.size();

  const Real h = dt / substeps;
  const Real joint_hertz = std::min(def.joint_hertz, 0.25 * substeps / dt);
  const detail::Softness soft = detail::make_softness(joint_hertz, def.joint_damping_ratio, h);
  // A joint's static, sleeping or kinematic body gets a solver record of the joint's own (a
  // copy that moves as the body does): a colour's joints may share such a body, and run on
  // different workers, and the rows write every body they touch. Slots after the solver's.
  joint_own_slots.assign(step_joints.size() + 1, 0);
  const auto fixed = [&](std::uint32_t body) {
    const std::int32_t s = body_solver_index[body];
    return s < 0 || (solver_info[static_cast<std::size_t>(s)].inv_mass == 0 &&
                     solver_info[static_cast<std::size_t>(s)].inv_inertia == 0);
  };
  for (std::size_t i = 0; i < step_joints.size(); ++i) {
    const Joint& joint = joints[step_joints[i]];
    std::uint32_t own = 0;
    for (int k = 0; k < joint.body_count; ++k) own += fixed(joint.body[k]) ? 1 : 0;
    joint_own_slots[i + 1] = joint_own_slots[i] + own;
  }
  const auto first_own = static_cast<std::uint32_t>(solver_bodies.size());
  solver_bodies.resize(first_own + joint_own_slots.back());
  solver_params.resize(solver_bodies.size());
  joint_stages.set(&joints, &step_joints, &joint_color_begin);
  joint_stages.reset(step_joints.size());
  // Each joint's frame is its own, so they are made in parallel.
  tasks.parallel_for(static_cast<std::uint32_t>(step_joints.size()), 64,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         const std::uint32_t j = joint_order[k], i = joint_position[k];
                         prepare_joint(j, first_own + joint_own_slots[i], h, soft);
                         joint_stages.gather(i, joints[j]);
                       }
                     });
  // Revolute rows are copied once the chains are known (a chain's joints keep their records,
  // which the chain solver reads), in parallel, each from its record.
  const auto rows = static_cast<std::uint32_t>(joint_stages.build_chains(def.direct_joint_chains));
  tasks.parallel_for(rows, 64, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
    for (std::uint32_t r = begin; r < end; ++r) {
      const std::uint32_t position = joint_stages.revolute_row_position(r);
      joint_stages.fill_revolute_row(position, joints[step_joints[position]]);
    }
  });
}

void WorldState::prepare_joint(std::uint32_t j, std::uint32_t own_slot, Real h,
                               const detail::Softness& soft) {
  {
    Joint& joint = joints[j];
    detail::JointFrame& frame = joint.frame;
    // Every field set, rather than the whole frame cleared first: a joint's bodies past its
    // body count are never written (zero since it was made), and a net's frames are megabytes.
    frame.anchor_a = frame.anchor_b = frame.delta_center = Vec2(0, 0);
    frame.coordinate_a = frame.coordinate_b = 0;
    frame.h = h;
    frame.inv_h = 1 / h;
    frame.soft = soft;
    for (int k = 0; k < joint.body_count; ++k) {
      const std::uint32_t bi = joint.body[k];
      const Body& b = bodies[bi];
      detail::JointBody& jb = frame.bodies[static_cast<std::size_t>(k)];
      detail::JointBodyStart& start = frame.starts[static_cast<std::size_t>(k)];
      const std::int32_t s = body_solver_index[bi];
      start.center = b.center;
      start.rotation = b.rotation;
      start.local_center = b.local_center;
      jb.inv_mass = jb.inv_inertia = 0;
      if (s >= 0) {
        jb.inv_mass = solver_info[static_cast<std::size_t>(s)].inv_mass;
        jb.inv_inertia = solver_info[static_cast<std::size_t>(s)].inv_inertia;
      }
      if (jb.inv_mass == 0 && jb.inv_inertia == 0) {
        // The joint's own copy: the still body's rest, or a kinematic body's motion.
        jb.solver = static_cast<std::int32_t>(own_slot++);
        solver_bodies[static_cast<std::size_t>(jb.solver)] =
            s < 0 ? detail::SolverBody{} : solver_bodies[static_cast<std::size_t>(s)];
        solver_params[static_cast<std::size_t>(jb.solver)] = detail::SolverBodyParams{};
      } else {
        jb.solver = s;
      }
    }
    if (joint.body_count == 4) {
      // A gear reads its joints' coordinates as the step begins.
      frame.coordinate_a = joint_coordinate(joint.gear_joints[0]);
      frame.coordinate_b = joint_coordinate(joint.gear_joints[1]);
    }
    std::visit([&](auto& k) { detail::prepare(k, frame); }, joint.kind);
  }
}

// A joint's body as the solve left it, with the turn the solver counted (its pose alone gives
// the turn only up to whole turns).
detail::JointBodyState WorldState::finished_body_state(std::uint32_t body) const {
  detail::JointBodyState state = joint_body_state(body);
  const std::int32_t s = body_solver_index[body];
  if (s >= 0) state.turned = detail::delta_angle(solver_bodies[static_cast<std::size_t>(s)]);
  return state;
}

void WorldState::finish_joints() {
  // Each joint's bookkeeping is its own (it reads bodies, writes only itself), so it runs in
  // parallel, in slot order; the breaks are gathered after.
  joint_broke.assign(joint_order.size(), 0);
  tasks.parallel_for(static_cast<std::uint32_t>(joint_order.size()), 64,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) finish_joint(k);
                     });
  joint_break_events.clear();
  for (std::size_t k = 0; k < joint_order.size(); ++k) {
    if (joint_broke[k] == 0) continue;
    const std::uint32_t j = joint_order[k];
    const Joint& joint = joints[j];
    joint_break_events.push_back(
        {joint_id(j), joint.reaction.force, joint.reaction.torque, base(joint).user_data});
  }
  std::sort(joint_break_events.begin(), joint_break_events.end(),
            [](const JointBreakEvent& x, const JointBreakEvent& y) {
              return x.joint.index < y.joint.index;
            });
}

void WorldState::finish_joint(std::uint32_t k) {
  const std::uint32_t j = joint_order[k];
  Joint& joint = joints[j];
  joint_stages.store_row(joint_position[k], joint);
  joint.reaction =
      std::visit([&](const auto& kind) { return detail::reaction(kind, joint.frame); }, joint.kind);
  const JointBase& b = base(joint);
  joint_broke[k] = joint.reaction.force.norm() > b.break_force ||
                   std::abs(joint.reaction.torque) > b.break_torque;
  const detail::JointBodyState sa = finished_body_state(joint.body[0]);
  const detail::JointBodyState sb = finished_body_state(joint.body[1]);
  std::visit([&](auto& kind) { detail::finish_kind(kind, sa, sb); }, joint.kind);
}

}  // namespace mink
