// The contact solver: Box2D v3's "soft step", written for this engine.
//
// Why this scheme. Sequential impulses with Baumgarte bias (Box2D 2.x) either jitter or pump
// energy into deep stacks, and a separate position pass (2.x's NGS) costs as much as the
// velocity pass while still leaving the stack bouncing. The soft step instead makes each
// contact a stiff, heavily damped spring (damping ratio 10, stiffness capped at a quarter of
// the substep rate) solved over several substeps of one step:
//   per substep: integrate velocities, warm start with the accumulated impulses, one
//   Gauss-Seidel pass with the soft bias ("solve"), integrate positions, one pass without the
//   bias ("relax", so the push-out does not turn into bounce); restitution once at the end.
//   Friction is solved in the relax pass only, against velocities free of the push-out.
// Substeps give most of the benefit of smaller time steps (stiffness, stacking) at the price
// of one iteration each, and the contact separation is updated each substep from the bodies'
// position change without recomputing manifolds. Contacts with a body that does not move get
// twice the stiffness (nothing on the other side to fight). Positive separations
// (speculative points) use bias = s / h, which lets a body close the gap exactly in one
// substep and no further: fast bodies stop at thin ones instead of tunnelling. Where touching
// bodies differ in mass tenfold or more, one contact at a time fails (a light box under heavy
// ones gives way): where the contacts linked to them form a path (a column), they are a
// stack, put in the overflow, whose normal rows are solved together there
// (contact_stack_solver.hpp).
//
// Settings (WorldDef): 5 substeps and 60 Hz where Box2D v3 uses 4 and 30 Hz. A soft contact
// under load sags by load / (effective mass * omega^2); at 30 Hz the bottom of the 100-row
// pyramid compresses so much that the top sinks about a metre, at 60 Hz about 0.2 m. 60 Hz
// with 4 substeps makes the pyramid sway (the spring is too stiff for the substep); 5 is
// the fewest that stays steady.
//
// Speed: Gauss-Seidel is a chain of dependent updates, so one constraint at a time the CPU
// mostly waits on latency. As in Box2D v3, the constraint graph is coloured so that no two
// constraints of a colour share a moving body; a colour is then solved eight constraints at a
// time in SIMD lanes (GCC vector extensions, compiled for x86-64-v4, AVX2 and baseline x86-64
// and picked at load time). No fused multiply-add is used, so every build and the one-at-a-time
// twin give bitwise equal results. Bodies and constraints are flat arrays of floats, no
// virtual calls, no allocation once the scratch arrays have grown.

#include "contact_solver.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "constraint_graph.hpp"
#include "contact_kernels.hpp"
#include "contact_stack_solver.hpp"
#include "joint_solver.hpp"
#include "run_counts.hpp"
#include "task_runner.hpp"

namespace mink::detail {

namespace {

constexpr std::size_t kColorCount = kGraphColors;

}  // namespace

std::size_t ContactSolver::color_count() const noexcept {
  std::size_t used = 0;
  for (std::size_t c = 0; c < kColorCount && c + 1 < color_begin_.size(); ++c) {
    used += color_begin_[c + 1] > color_begin_[c] ? 1 : 0;
  }
  return used;
}

namespace {
constexpr std::uint32_t kScalar = 1u << 31;
}  // namespace

void ContactSolver::begin(std::span<const ConstraintBodies> constraints, std::int32_t still,
                          bool wide, TaskRunner& tasks) {
  wide_mode_ = wide;
  bouncy_ = false;
  stack_members_.clear();
  stack_begin_.clear();
  still_ = still;
  restitution_.clear();
  findings_.resize(tasks.workers());
  for (WorkerFindings& f : findings_) {
    f.bouncy = false;
    f.restitution.clear();
  }
  // Colours come from the constraint graph, which keeps them from step to step. The
  // constraints are laid out colour by colour, in their order within each, in one run per
  // worker (run_counts.hpp).
  const auto count = static_cast<std::uint32_t>(constraints.size());
  const std::uint32_t runs = tasks.workers();
  const auto run_first = [&](std::uint32_t run) {
    return static_cast<std::uint32_t>(run_begin(count, run, runs));
  };
  color_of_.resize(count);
  slot_.resize(count);
  static_assert(kColorCount + 1 <= kRunColorStride);
  run_colors_.assign(runs * kRunColorStride, 0);
  tasks.parallel_for(runs, 1, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
    for (std::uint32_t run = begin; run < end; ++run) {
      // Counted locally: the arrays written in the loop could alias the shared ones. An entry
      // of no colour (kNoColor) is no constraint, counted nowhere.
      std::array<std::uint32_t, kNoColor + 1> counts{};
      for (std::uint32_t i = run_first(run), last = run_first(run + 1); i < last; ++i) {
        color_of_[i] = constraints[i].color;
        ++counts[constraints[i].color];
      }
      std::copy_n(counts.begin(), kColorCount + 1, run_colors_.begin() + run * kRunColorStride);
    }
  });
  // Each run's first position per colour; the first run's are where the colours begin.
  const std::uint32_t placed = place_runs(run_colors_, runs, kRunColorStride, kColorCount + 1);
  order_.resize(placed);
  color_begin_.assign(run_colors_.begin(), run_colors_.begin() + kColorCount + 1);
  color_begin_.push_back(placed);
  overflow_count_ = placed - color_begin_[kColorCount];
  wide_begin_.assign(kColorCount + 1, 0);
  for (std::size_t c = 0; c < kColorCount; ++c) {
    const std::uint32_t count = color_begin_[c + 1] - color_begin_[c];
    wide_begin_[c + 1] = wide_begin_[c] + (count + kWideLanes - 1) / kWideLanes;
  }
  // Slots: position within the colour gives the batch and the lane directly.
  tasks.parallel_for(runs, 1, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
    for (std::uint32_t run = begin; run < end; ++run) {
      std::array<std::uint32_t, kColorCount + 1> next;
      std::copy_n(run_colors_.begin() + run * kRunColorStride, next.size(), next.begin());
      for (std::uint32_t i = run_first(run), last = run_first(run + 1); i < last; ++i) {
        const std::uint8_t color = color_of_[i];
        if (color == kNoColor) continue;
        const std::uint32_t position = next[color]++;
        order_[position] = i;
        if (!wide) {
          slot_[i] = kScalar | position;
        } else if (color == kColorCount) {
          slot_[i] = kScalar | (position - color_begin_[kColorCount]);
        } else {
          const std::uint32_t offset = position - color_begin_[color];
          slot_[i] = kWideLanes * (wide_begin_[color] + offset / kWideLanes) + offset % kWideLanes;
        }
      }
    }
  });
  if (wide) {
    scalar_.resize(overflow_count_);
    wide_.resize(wide_begin_[kColorCount]);
    batch_first_.resize(wide_.size());
    for (std::size_t c = 0; c < kColorCount; ++c) {
      for (std::uint32_t w = wide_begin_[c]; w < wide_begin_[c + 1]; ++w) {
        batch_first_[w] = color_begin_[c] + kWideLanes * (w - wide_begin_[c]);
      }
    }
  } else {
    scalar_.resize(placed);
    wide_.clear();
    batch_first_.clear();
  }
}

std::span<const std::uint32_t> ContactSolver::batch(std::uint32_t batch) const noexcept {
  const std::uint32_t first = batch_first_[batch];
  // The colour's end bounds its last batch.
  const std::uint32_t color = color_of_[order_[first]];
  const std::uint32_t end = std::min<std::uint32_t>(first + kWideLanes, color_begin_[color + 1]);
  return {order_.data() + first, end - first};
}

std::span<const std::uint32_t> ContactSolver::overflow() const noexcept {
  const std::uint32_t first = color_begin_[kColorCount];
  return {order_.data() + first, order_.size() - first};
}

void ContactSolver::build_batch(std::uint32_t batch, std::span<const BatchLane> lanes,
                                std::uint32_t two_points, const Softness& soft,
                                const Softness& fixed_soft, std::uint32_t worker) {
  build_wide(wide_[batch], lanes.data(), static_cast<int>(lanes.size()), two_points, still_, soft,
             fixed_soft);
  WorkerFindings& found = findings_[worker];
  for (std::uint32_t lane = 0; lane < lanes.size(); ++lane) {
    const BatchLane& in = lanes[lane];
    if (in.seed->restitution <= 0) continue;
    found.bouncy = true;
    found.restitution.push_back({kWideLanes * batch + lane,
                                 in.seed->restitution,
                                 {in.relative_velocity[0], in.relative_velocity[1]}});
  }
}

void ContactSolver::set(std::uint32_t index, const ContactConstraint& constraint,
                        std::uint32_t worker) {
  WorkerFindings& found = findings_[worker];
  found.bouncy = found.bouncy || constraint.restitution > 0;
  scalar_[slot_[index] & ~kScalar] = constraint;
}

void ContactSolver::set_stacks(std::span<const std::uint32_t> members,
                               std::span<const std::uint32_t> stack_begin) {
  stack_members_.assign(members.begin(), members.end());
  stack_begin_.assign(stack_begin.begin(), stack_begin.end());
}

std::size_t ContactSolver::stacked_count() const noexcept {
  return stack_solver_ ? stack_solver_->direct_constraints() : 0;
}

void ContactSolver::finish() {
  stacked_.assign(stack_members_.empty() ? 0 : scalar_.size(), 0);
  for (std::uint32_t& member : stack_members_) {
    member = slot_[member] & ~kScalar;
    stacked_[member] = 1;
  }
  if (!stack_solver_) stack_solver_ = std::make_unique<ContactStackSolver>();
  stack_solver_->build(scalar_, stack_members_, stack_begin_);
  // Bounce in colour order, as the one-at-a-time twin does. A worker takes its ranges of
  // batches in order, so each worker's bounces come in order (sorted here when a task system
  // ran them otherwise), and the workers' lists are merged one into the next, rather than
  // sorted whole: where most contacts bounce, sorting them took longer than building them.
  const auto by_slot = [](const Bounce& x, const Bounce& y) { return x.slot < y.slot; };
  for (WorkerFindings& f : findings_) {
    bouncy_ = bouncy_ || f.bouncy;
    if (!std::is_sorted(f.restitution.begin(), f.restitution.end(), by_slot)) {
      std::sort(f.restitution.begin(), f.restitution.end(), by_slot);
    }
    merged_.resize(restitution_.size() + f.restitution.size());
    std::merge(restitution_.begin(), restitution_.end(), f.restitution.begin(), f.restitution.end(),
               merged_.begin(), by_slot);
    restitution_.swap(merged_);
  }
}

void ContactSolver::impulses(std::uint32_t index, SolverReal normal[2],
                             SolverReal tangent[2]) const {
  const std::uint32_t slot = slot_[index];
  if (slot & kScalar) {
    const ContactConstraint& c = scalar_[slot & ~kScalar];
    for (int j = 0; j < 2; ++j) {
      normal[j] = c.points[j].normal_impulse;
      tangent[j] = c.points[j].tangent_impulse;
    }
    return;
  }
  const WideConstraint& w = wide_[slot / kWideLanes];
  for (int j = 0; j < 2; ++j) {
    normal[j] = w.points[j].normal_impulse[slot % kWideLanes];
    tangent[j] = w.points[j].tangent_impulse[slot % kWideLanes];
  }
}

// What one stage of a substep does; the colour stages carry their colour. Not in an anonymous
// namespace: ContactSolver::Stage, a member of a class with linkage, holds one.
enum class StageKind : std::uint8_t {
  integrate_velocities,
  joint_chains_warm_start,
  joint_warm_start,
  joint_chains_solve,
  joint_chains_relax,
  warm_start,
  joint_solve,
  solve,
  integrate_positions,
  joint_relax,
  relax,
  restitution,  // once, after the substeps: a colour's bouncing constraints
};

// Every substep is the same list of stages; stage s of the substeps is stage s % per-substep of
// it, and restitution's stages follow the last substep.
struct ContactSolver::Stage {
  StageKind kind;
  std::uint32_t color;  // colour stages: kColorCount is the overflow
  std::uint32_t begin, end, block_size;
};

// Defined once Stage is complete: clang needs its size for the vector of stages.
ContactSolver::ContactSolver() = default;
ContactSolver::~ContactSolver() = default;
ContactSolver::ContactSolver(ContactSolver&&) noexcept = default;
ContactSolver& ContactSolver::operator=(ContactSolver&&) noexcept = default;

namespace {

std::uint32_t block_count(std::uint32_t items, std::uint32_t block_size) {
  return (items + block_size - 1) / block_size;
}

}  // namespace

void ContactSolver::solve(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
                          const SolverSettings& settings, JointStages* joints, TaskRunner& tasks) {
  // Largest impulses are only needed when something bounces.
  max_impulse_.assign(bouncy_ && wide_mode_ ? wide_.size() : 0, WideMaxImpulse{});
  const std::uint32_t workers = tasks.workers();
  // Blocks: about four per worker, so uneven blocks even out, but not so small that taking
  // one costs more than running it. The split never changes a result: a colour's
  // constraints share no moving body, and bodies integrate alone.
  const auto split = [&](std::uint32_t items, std::uint32_t smallest) {
    return std::max(smallest, (items + 4 * workers - 1) / (4 * workers));
  };
  const auto body_count = static_cast<std::uint32_t>(bodies.size());
  stages_.clear();
  const auto colour_stages = [&](StageKind kind) {
    for (std::uint32_t c = 0; c < kColorCount; ++c) {
      const std::uint32_t begin = wide_mode_ ? wide_begin_[c] : color_begin_[c];
      const std::uint32_t end = wide_mode_ ? wide_begin_[c + 1] : color_begin_[c + 1];
      if (end > begin)
        stages_.push_back({kind, c, begin, end, split(end - begin, wide_mode_ ? 8 : 32)});
    }
    // The overflow: one at a time, after the colours.
    const std::uint32_t begin = wide_mode_ ? 0 : color_begin_[kColorCount];
    const auto end = static_cast<std::uint32_t>(scalar_.size());
    if (end > begin) stages_.push_back({kind, kColorCount, begin, end, end - begin});
  };
  const bool with_joints = joints != nullptr;
  // Joints colour by colour as the contacts (a colour's joints share no moving body either),
  // the chains' direct solve first in each solve, the overflow one at a time.
  const auto joint_stages = [&](StageKind kind) {
    if (!with_joints) return;
    const std::vector<std::uint32_t>& begin = joints->unit_begin();
    for (std::uint32_t c = 0; c <= kColorCount; ++c) {
      const std::uint32_t first = begin[c], last = begin[c + 1];
      if (last == first) continue;
      const std::uint32_t size = c == kColorCount ? last - first : split(last - first, 16);
      stages_.push_back({kind, c, first, last, size});
    }
  };
  // The chains' paths are independent of each other, so they are split over the workers.
  const std::uint32_t paths = with_joints ? joints->chain_paths() : 0;
  const auto chain_stage = [&](StageKind kind) {
    if (paths > 0) stages_.push_back({kind, 0, 0, paths, split(paths, 4)});
  };
  stages_.push_back({StageKind::integrate_velocities, 0, 0, body_count, split(body_count, 64)});
  chain_stage(StageKind::joint_chains_warm_start);
  joint_stages(StageKind::joint_warm_start);
  colour_stages(StageKind::warm_start);
  for (int i = 0; with_joints && i < settings.joint_iterations; ++i) {
    chain_stage(StageKind::joint_chains_solve);
    joint_stages(StageKind::joint_solve);
  }
  colour_stages(StageKind::solve);
  stages_.push_back({StageKind::integrate_positions, 0, 0, body_count, split(body_count, 64)});
  chain_stage(StageKind::joint_chains_relax);
  joint_stages(StageKind::joint_relax);
  colour_stages(StageKind::relax);
  const std::size_t per_substep = stages_.size();
  stage_blocks_.clear();
  for (int substep = 0; substep < settings.substeps; ++substep) {
    for (std::size_t i = 0; i < per_substep; ++i) {
      const Stage& st = stages_[i];
      stage_blocks_.push_back(block_count(st.end - st.begin, st.block_size));
    }
  }
  // Restitution, once the substeps are done: the bouncing constraints colour by colour (in slot
  // order, so a colour's are a range of them), each colour's in parallel as its solve is.
  bounce_stages_.clear();
  if (bouncy_ && wide_mode_) {
    const auto by_slot = [](const Bounce& b, std::uint32_t slot) { return b.slot < slot; };
    for (std::uint32_t c = 0; c < kColorCount; ++c) {
      const auto first = std::lower_bound(restitution_.begin(), restitution_.end(),
                                          kWideLanes * wide_begin_[c], by_slot);
      const auto last =
          std::lower_bound(first, restitution_.end(), kWideLanes * wide_begin_[c + 1], by_slot);
      if (first == last) continue;
      const auto begin = static_cast<std::uint32_t>(first - restitution_.begin());
      const auto end = static_cast<std::uint32_t>(last - restitution_.begin());
      bounce_stages_.push_back({StageKind::restitution, c, begin, end, split(end - begin, 64)});
      stage_blocks_.push_back(block_count(end - begin, bounce_stages_.back().block_size));
    }
  }
  const std::size_t substep_stages = per_substep * static_cast<std::size_t>(settings.substeps);

  struct Context {
    ContactSolver* solver;
    std::span<SolverBody> bodies;
    std::span<const SolverBodyParams> params;
    const SolverSettings* settings;
    JointStages* joints;
    std::size_t per_substep, substep_stages;
  } context{this, bodies, params, &settings, joints, per_substep, substep_stages};
  const auto run_block = [](void* opaque, std::uint32_t stage, std::uint32_t block) {
    const Context& x = *static_cast<Context*>(opaque);
    ContactSolver& self = *x.solver;
    const Stage& st = stage < x.substep_stages ? self.stages_[stage % x.per_substep]
                                               : self.bounce_stages_[stage - x.substep_stages];
    const std::uint32_t begin = st.begin + block * st.block_size;
    const std::uint32_t end = std::min(st.end, begin + st.block_size);
    SolverBody* body_data = x.bodies.data();
    const SolverReal inv_h = x.settings->inv_h, max_push = x.settings->contact_push_max_velocity;
    const bool overflow = st.color == kColorCount;
    WideConstraint* wide = self.wide_.data();
    WideMaxImpulse* max_data = self.max_impulse_.empty() ? nullptr : self.max_impulse_.data();
    switch (st.kind) {
      case StageKind::integrate_velocities:
        integrate_velocities(x.bodies.subspan(begin, end - begin),
                             x.params.subspan(begin, end - begin), *x.settings);
        return;
      case StageKind::integrate_positions:
        integrate_positions(x.bodies.subspan(begin, end - begin), x.settings->h);
        return;
      case StageKind::joint_chains_warm_start:
        x.joints->warm_start_chains(body_data, begin, end);
        return;
      case StageKind::joint_warm_start:
        x.joints->warm_start(body_data, begin, end);
        return;
      case StageKind::joint_chains_solve:
      case StageKind::joint_chains_relax:
        x.joints->solve_chains(body_data, st.kind == StageKind::joint_chains_solve, begin, end);
        return;
      case StageKind::joint_solve:
      case StageKind::joint_relax:
        x.joints->solve(body_data, st.kind == StageKind::joint_solve, begin, end);
        return;
      case StageKind::warm_start:
        if (self.wide_mode_ && !overflow) {
          warm_start_wide(body_data, wide + begin, wide + end);
        } else {
          for (std::uint32_t i = begin; i < end; ++i) warm_start_one(body_data, self.scalar_[i]);
        }
        return;
      case StageKind::solve:
      case StageKind::relax: {
        const bool use_bias = st.kind == StageKind::solve;
        if (self.wide_mode_ && !overflow) {
          solve_wide(body_data, wide + begin, wide + end, max_data ? max_data + begin : nullptr,
                     inv_h, max_push, use_bias);
        } else {
          const bool stacks = overflow && !self.stacked_.empty();
          for (std::uint32_t i = begin; i < end; ++i) {
            if (stacks && self.stacked_[i] != 0) continue;
            solve_one(body_data, self.scalar_[i], inv_h, max_push, use_bias);
          }
          // The overflow is one block: its stacks after its lone constraints (they share
          // no moving body).
          if (stacks) self.stack_solver_->solve(body_data, self.scalar_, inv_h, max_push, use_bias);
        }
        return;
      }
      case StageKind::restitution:
        for (std::uint32_t i = begin; i < end; ++i) {
          self.bounce(body_data, self.restitution_[i], x.settings->restitution_threshold);
        }
        return;
    }
  };
  stage_runner_.run(tasks, stage_blocks_, run_block, &context);

  if (!bouncy_) return;
  // The overflow's (or, for the scalar solver, every) bouncing constraint, one at a time.
  const SolverReal threshold = settings.restitution_threshold;
  for (ContactConstraint& c : scalar_) restitution_one(bodies.data(), c, threshold);
}

void ContactSolver::bounce(SolverBody* bodies, const Bounce& bounce, SolverReal threshold) {
  const std::uint32_t slot = bounce.slot;
  WideConstraint& w = wide_[slot / kWideLanes];
  const int lane = static_cast<int>(slot % kWideLanes);
  ContactConstraint c = unpack(w, lane);
  c.restitution = bounce.restitution;
  for (int j = 0; j < 2; ++j) {
    c.points[j].relative_velocity = bounce.relative_velocity[j];
    c.points[j].max_normal_impulse = max_impulse_[slot / kWideLanes].point[j][lane];
  }
  restitution_one(bodies, c, threshold);
  for (int j = 0; j < 2; ++j) w.points[j].normal_impulse[lane] = c.points[j].normal_impulse;
}

}  // namespace mink::detail
