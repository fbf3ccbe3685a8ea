// The joints' part of a step. After the contacts are prepared: the joints of moving bodies,
// in colour order then slot order, get their frames for the step (a pin only its pin row). In
// every substep stage the solver runs them before the contacts (warm start, solve with bias,
// relax), revolute joints from their rows; after the solve each joint takes back its row's
// impulses, records the force it applied, reports a break, and settles its coordinate.

#include <algorithm>
#include <bit>

#include "joint_solver.hpp"
#include "prefetch.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Joint;

namespace {
constexpr std::size_t kJointAhead = 8;
}  // namespace

namespace detail {

void JointStages::gather(std::uint32_t position, Joint& joint) {
  const JointFrame& frame = joint.frame;
  auto* revolute = std::get_if<RevoluteJoint>(&joint.kind);
  ends_[position] = {{frame.bodies[0], frame.bodies[1]}, revolute != nullptr};
  if (revolute == nullptr) return;
  revolute->direct = false;
  // A revolute joint not prepared as a pin (prepare_joint) has a spring, motor or limit.
  kind_[position] = RowKind::revolute;
}

void JointStages::gather_pin(std::uint32_t position, const JointFrame& frame,
                             const RevoluteJoint& joint) {
  ends_[position] = {{frame.bodies[0], frame.bodies[1]}, true};
  pins_[position] = pin_row(frame, joint.linear_impulse);
  kind_[position] = RowKind::pin;
}

std::size_t JointStages::build_chains(bool enabled) {
  chains_.build(*joints_, *order_, ends_, enabled);
  chained_pins_.clear();
  for (const std::uint32_t position : chains_.chain_positions()) {
    // A chain solves the point row; a chained joint's angle rows, where it has any, stay rows.
    if (kind_[position] == RowKind::pin) chained_pins_.push_back(position);
    kind_[position] =
        kind_[position] == RowKind::revolute ? RowKind::revolute_angles : RowKind::chained;
  }
  revolute_positions_.clear();
  for (std::uint32_t position = 0; position < kind_.size(); ++position) {
    if (kind_[position] != RowKind::revolute && kind_[position] != RowKind::revolute_angles) {
      continue;
    }
    row_slot_[position] = static_cast<std::uint32_t>(revolute_positions_.size());
    revolute_positions_.push_back(position);
  }
  revolute_rows_.resize(revolute_positions_.size());
  return revolute_positions_.size();
}

void JointStages::lay_out(bool wide, TaskRunner& tasks) {
  const std::vector<std::uint32_t>& color_begin = *color_begin_;
  const std::size_t colors = color_begin.size() - 1;  // the overflow last
  units_.clear();
  wide_pins_.clear();
  wide_revolutes_.clear();
  unit_begin_.assign(colors + 1, 0);
  wide_pin_positions_.clear();
  wide_revolute_positions_.clear();
  // A colour's joints of one kind kWideLanes at a time into `rows`, each unit a wide row; a
  // lane left unused reads the first lane's joint.
  const auto batch = [&](auto& rows, std::vector<std::uint32_t>& positions, std::uint32_t unit,
                         std::uint32_t first, std::uint32_t last, RowKind kind) {
    std::uint32_t lane = 0;
    for (std::uint32_t position = first; position < last; ++position) {
      if (kind_[position] != kind) continue;
      if (lane == 0) {
        units_.push_back(unit | static_cast<std::uint32_t>(rows.size()));
        rows.emplace_back();
        positions.insert(positions.end(), kWideLanes, position);
      }
      const auto at = static_cast<std::uint32_t>((rows.size() - 1) * kWideLanes + lane);
      wide_lane_[position] = at;
      positions[at] = position;
      ++rows.back().lanes;
      lane = (lane + 1) % kWideLanes;
    }
  };
  for (std::size_t c = 0; c < colors; ++c) {
    const bool overflow = c + 1 == colors;
    const std::uint32_t first = color_begin[c], last = color_begin[c + 1];
    if (wide && !overflow) {
      batch(wide_pins_, wide_pin_positions_, kWidePinUnit, first, last, RowKind::pin);
      const std::size_t with_point = wide_revolutes_.size();
      batch(wide_revolutes_, wide_revolute_positions_, kWideRevoluteUnit, first, last,
            RowKind::revolute);
      const std::size_t without_point = wide_revolutes_.size();
      batch(wide_revolutes_, wide_revolute_positions_, kWideRevoluteUnit, first, last,
            RowKind::revolute_angles);
      for (std::size_t r = with_point; r < without_point; ++r) wide_revolutes_[r].point = true;
    }
    for (std::uint32_t position = first; position < last; ++position) {
      // A chained pin is all its chain's: nothing of it is solved one at a time.
      if (wide_lane_[position] == kNoLane && kind_[position] != RowKind::chained) {
        units_.push_back(position);
      }
    }
    unit_begin_[c + 1] = static_cast<std::uint32_t>(units_.size());
  }
  // Each wide row's lanes from its joints' rows.
  tasks.parallel_for(static_cast<std::uint32_t>(wide_pins_.size()), 32,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t r = begin; r < end; ++r) {
                         WidePinRows& row = wide_pins_[r];
                         for (int lane = 0; lane < kWideLanes; ++lane) {
                           pack_pin(row, lane, pins_[wide_pin_positions_[r * kWideLanes + lane]]);
                         }
                       }
                     });
  tasks.parallel_for(static_cast<std::uint32_t>(wide_revolutes_.size()), 16,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t r = begin; r < end; ++r) {
                         WideRevoluteRows& row = wide_revolutes_[r];
                         for (int lane = 0; lane < kWideLanes; ++lane) {
                           const std::uint32_t position =
                               wide_revolute_positions_[r * kWideLanes + lane];
                           pack_revolute(row, lane, revolute_rows_[row_slot_[position]]);
                         }
                       }
                     });
}

void JointStages::fill_revolute_row(std::uint32_t position, const Joint& joint) {
  revolute_rows_[row_slot_[position]] =
      revolute_row(std::get<RevoluteJoint>(joint.kind), joint.frame);
}

void JointStages::store_row(std::uint32_t position, Joint& joint) const {
  const std::uint32_t lane = wide_lane_[position];
  switch (kind_[position]) {
    case RowKind::record:
    case RowKind::chained:
      return;
    case RowKind::pin: {
      Vec2& impulse = std::get<RevoluteJoint>(joint.kind).linear_impulse;
      if (lane == kNoLane) {
        impulse = Vec2(pins_[position].impulse_x, pins_[position].impulse_y);
      } else {
        const WidePinRows& row = wide_pins_[lane / kWideLanes];
        impulse = Vec2(row.impulse_x[lane % kWideLanes], row.impulse_y[lane % kWideLanes]);
      }
      return;
    }
    case RowKind::revolute:
    case RowKind::revolute_angles: {
      RevoluteRow row = revolute_rows_[row_slot_[position]];
      if (lane != kNoLane) {
        read_impulses(wide_revolutes_[lane / kWideLanes], static_cast<int>(lane % kWideLanes), row);
      }
      detail::store_row(row, std::get<RevoluteJoint>(joint.kind));
      return;
    }
  }
}

void JointStages::warm_start(SolverBody* bodies, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t u = begin; u < end; ++u) {
    const std::uint32_t i = units_[u];
    if ((i & kWidePinUnit) != 0) {
      const WidePinRows* row = &wide_pins_[i & kUnitIndex];
      warm_start_pins_wide(bodies, row, row + 1);
      continue;
    }
    if ((i & kWideRevoluteUnit) != 0) {
      warm_start_revolutes_wide(bodies, wide_revolutes_[i & kUnitIndex]);
      continue;
    }
    if (kind_[i] == RowKind::pin) {
      warm_start_pin(bodies, pins_[i]);
      continue;
    }
    if (kind_[i] == RowKind::revolute || kind_[i] == RowKind::revolute_angles) {
      warm_start_revolute(bodies, revolute_rows_[row_slot_[i]]);
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

void JointStages::warm_start_chains(SolverBody* bodies, std::uint32_t first, std::uint32_t last) {
  chains_.warm_start(*joints_, bodies, first, last);
}

void JointStages::solve(SolverBody* bodies, bool use_bias, std::uint32_t begin, std::uint32_t end) {
  for (std::uint32_t u = begin; u < end; ++u) {
    const std::uint32_t i = units_[u];
    if ((i & kWidePinUnit) != 0) {
      WidePinRows* row = &wide_pins_[i & kUnitIndex];
      solve_pins_wide(bodies, row, row + 1, use_bias);
      continue;
    }
    if ((i & kWideRevoluteUnit) != 0) {
      solve_revolutes_wide(bodies, wide_revolutes_[i & kUnitIndex], use_bias);
      continue;
    }
    if (kind_[i] == RowKind::pin) {
      solve_pin(bodies, pins_[i], use_bias);
      continue;
    }
    if (kind_[i] == RowKind::revolute || kind_[i] == RowKind::revolute_angles) {
      solve_revolute(bodies, revolute_rows_[row_slot_[i]], use_bias);
      continue;
    }
    Joint& joint = (*joints_)[(*order_)[i]];
    std::visit([&](auto& k) { detail::solve(k, joint.frame, bodies, use_bias); }, joint.kind);
  }
}

}  // namespace detail

void WorldState::prepare_joints() {
  // The joints of moving bodies: marked from the bodies' lists (in parallel, each worker in
  // marks of its own), those with a disabled body or none dynamic unmarked in parallel, word by
  // word, then read off in slot order into their colours (the overflow last), which is the
  // order they are solved in.
  constexpr std::size_t kColors = detail::kGraphColors + 1;
  joint_marks.reset(joints.size(), tasks.workers());
  joint_slot_color.resize(joints.size());
  // A world without joints skips the visit to every moving body's record.
  if (joints.live() > 0) {
    tasks.parallel_for(static_cast<std::uint32_t>(solver_to_body.size()), 256,
                       [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                         for (std::uint32_t k = begin; k < end; ++k) {
                           // The bodies' lists, then what they hold, asked for ahead.
                           detail::prefetch_list_ahead(
                               k, end, kJointAhead, [&](std::size_t i) -> const auto& {
                                 return bodies[solver_to_body[i]].joints;
                               });
                           for (const std::uint32_t j : bodies[solver_to_body[k]].joints) {
                             joint_marks.mark(j, worker);
                           }
                         }
                       });
  }
  tasks.parallel_for(
      static_cast<std::uint32_t>(joint_marks.words()), 16,
      [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t word = begin; word < end; ++word) {
          std::uint64_t kept = joint_marks.word(word);
          for (std::uint64_t bits = kept; bits != 0; bits &= bits - 1) {
            const int bit = std::countr_zero(bits);
            const detail::JointBodies& joint =
                joint_bodies[word * 64 + static_cast<std::uint32_t>(bit)];
            bool enabled = true, dynamic = false;
            for (std::uint32_t k = 0; k < joint.count; ++k) {
              const Body& b = bodies[joint.body[k]];
              enabled = enabled && b.enabled;
              dynamic = dynamic || b.type == BodyType::dynamic;
            }
            if (!enabled || !dynamic) kept &= ~(std::uint64_t{1} << bit);
            joint_slot_color[word * 64 + static_cast<std::uint32_t>(bit)] =
                static_cast<std::uint8_t>(std::min<std::size_t>(joint.color, kColors - 1));
          }
          joint_marks.set_word(word, kept);
        }
      });
  joint_color_begin.assign(kColors + 1, 0);
  step_joints.clear();
  joint_marks.for_each_marked([&](std::uint32_t j) {
    step_joints.push_back(j);
    ++joint_color_begin[joint_slot_color[j] + 1];
  });
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
    const detail::JointBodies& joint = joint_bodies[step_joints[i]];
    std::uint32_t own = 0;
    for (std::uint32_t k = 0; k < joint.count; ++k) own += fixed(joint.body[k]) ? 1 : 0;
    joint_own_slots[i + 1] = joint_own_slots[i] + own;
  }
  const auto first_own = static_cast<std::uint32_t>(solver_bodies.size());
  solver_bodies.resize(first_own + joint_own_slots.back());
  solver_params.resize(solver_bodies.size());
  joint_stages.set(&joints, &step_joints, &joint_color_begin);
  joint_stages.reset(step_joints.size());
  // Joint records, then their bodies' lines that prepare_joint reads (the pose's and the
  // centre of mass's), asked for ahead: records of a kilobyte and bodies scattered.
  const auto prefetch_joint_ahead = [&](std::size_t k, std::size_t end) {
    if (k + kJointAhead < end) {
      detail::prefetch_bytes(&joints[joint_order[k + kJointAhead]], sizeof(Joint));
    }
    if (k + kJointAhead / 2 < end) {
      const detail::JointBodies& jb = joint_bodies[joint_order[k + kJointAhead / 2]];
      for (std::uint32_t b = 0; b < jb.count; ++b) {
        detail::prefetch_line(&bodies[jb.body[b]].center);
        detail::prefetch_line(&bodies[jb.body[b]].local_center);
      }
    }
  };
  // Each joint's frame is its own, so they are made in parallel.
  tasks.parallel_for(static_cast<std::uint32_t>(step_joints.size()), 64,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         prefetch_joint_ahead(k, end);
                         const std::uint32_t j = joint_order[k], i = joint_position[k];
                         if (!prepare_joint(j, i, first_own + joint_own_slots[i], h, soft, true)) {
                           joint_stages.gather(i, joints[j]);
                         }
                       }
                     });
  // Revolute rows are copied once the chains are known (a chain's joints keep their records,
  // which the chain solver reads), in parallel, each from its record; a pin a chain took is
  // prepared again into its record's frame.
  const auto rows = static_cast<std::uint32_t>(joint_stages.build_chains(def.direct_joint_chains));
  for (const std::uint32_t position : joint_stages.chained_pins()) {
    prepare_joint(step_joints[position], position, first_own + joint_own_slots[position], h, soft,
                  false);
  }
  tasks.parallel_for(rows, 64, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
    for (std::uint32_t r = begin; r < end; ++r) {
      if (r + kJointAhead < end) {
        const std::uint32_t ahead = joint_stages.revolute_row_position(r + kJointAhead);
        detail::prefetch_bytes(&joints[step_joints[ahead]], sizeof(Joint));
      }
      const std::uint32_t position = joint_stages.revolute_row_position(r);
      joint_stages.fill_revolute_row(position, joints[step_joints[position]]);
    }
  });
  joint_stages.lay_out(def.simd_solver, tasks);
}

bool WorldState::prepare_joint(std::uint32_t j, std::uint32_t position, std::uint32_t own_slot,
                               Real h, const detail::Softness& soft, bool may_pin) {
  Joint& joint = joints[j];
  // A revolute joint that is only its point row (most of a large net) is prepared in a frame
  // on the stack and solved from its pin row alone: its record's frame, half a kilobyte a
  // large net would write and read again every step, is not written.
  auto* revolute = std::get_if<detail::RevoluteJoint>(&joint.kind);
  const bool pin = may_pin && revolute != nullptr && !revolute->def.spring.enabled &&
                   !revolute->def.motor.enabled && !revolute->def.limit.enabled;
  detail::JointFrame local;
  detail::JointFrame& frame = pin ? local : joint.frame;
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
  if (pin) {
    detail::prepare_pin(*revolute, frame);
    joint_stages.gather_pin(position, frame, *revolute);
    return true;
  }
  if (joint.body_count == 4) {
    // A gear reads its joints' coordinates as the step begins.
    frame.coordinate_a = joint_coordinate(joint.gear_joints[0]);
    frame.coordinate_b = joint_coordinate(joint.gear_joints[1]);
  }
  std::visit([&](auto& k) { detail::prepare(k, frame); }, joint.kind);
  return false;
}

// A joint's body as the solve left it, with the turn the solver counted (its pose alone gives
// the turn only up to whole turns).
detail::JointBodyState WorldState::finished_body_state(std::uint32_t body) const {
  detail::JointBodyState state = joint_body_state(body);
  state.turned = finished_turn(body);
  return state;
}

Real WorldState::finished_turn(std::uint32_t body) const {
  const std::int32_t s = body_solver_index[body];
  return s < 0 ? 0 : solver_turned[static_cast<std::size_t>(s)];
}

void WorldState::finish_joints() {
  // Each joint's bookkeeping is its own (it reads bodies, writes only itself), so it runs in
  // parallel, in slot order; the breaks are gathered after.
  const Real inv_h = 1 / (dt / substeps);  // as prepare_joint gives the frames
  joint_broke.assign(joint_order.size(), 0);
  tasks.parallel_for(static_cast<std::uint32_t>(joint_order.size()), 64,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) finish_joint(k, inv_h);
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

void WorldState::finish_joint(std::uint32_t k, Real inv_h) {
  const std::uint32_t j = joint_order[k];
  Joint& joint = joints[j];
  joint_stages.store_row(joint_position[k], joint);
  bool stopped_body = false;
  for (int b = 0; b < joint.body_count; ++b) {
    stopped_body = stopped_body || stopped_in_step(body_solver_index[joint.body[b]]);
  }
  if (stopped_body) {
    detail::forget_impulses(joint);
    return;
  }
  // A revolute joint's force from the step's substep length rather than its frame, which a
  // pin's record does not have prepared; it reads only the bodies' rotations to finish (a
  // large net's joints are revolute).
  auto* revolute = std::get_if<detail::RevoluteJoint>(&joint.kind);
  joint.reaction =
      revolute != nullptr
          ? detail::reaction(*revolute, inv_h)
          : std::visit([&](const auto& kind) { return detail::reaction(kind, joint.frame); },
                       joint.kind);
  const JointBase& b = base(joint);
  joint_broke[k] = joint.reaction.force.norm() > b.break_force ||
                   std::abs(joint.reaction.torque) > b.break_torque;
  if (revolute != nullptr) {
    detail::finish_angle(*revolute, bodies[joint.body[0]].rotation, bodies[joint.body[1]].rotation,
                         finished_turn(joint.body[0]), finished_turn(joint.body[1]));
    return;
  }
  const detail::JointBodyState sa = finished_body_state(joint.body[0]);
  const detail::JointBodyState sb = finished_body_state(joint.body[1]);
  std::visit([&](auto& kind) { detail::finish_kind(kind, sa, sb); }, joint.kind);
}

}  // namespace mink
