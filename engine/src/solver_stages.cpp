// The solver stages of one step: build the solver bodies and contact constraints, run the
// substepped soft-step solve, write poses back and finish the step's bookkeeping.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "contact_kernels.hpp"
#include "contact_stack_solver.hpp"
#include "prefetch.hpp"
#include "world_state.hpp"

namespace mink {

namespace {

// `v` scaled to length `limit` when longer (hypot, as the squares of 1e300 would overflow). An
// infinite component (a force of 1e300 N on a body of min_mass_property) points the way. Most
// bodies are within the limit, which the squared length tells cheaply.
Vec2 clamp_length(Vec2 v, Real limit) {
  if (v.squaredNorm() <= limit * limit) return v;
  if (std::isinf(v.x()) || std::isinf(v.y())) {
    v = Vec2(std::isinf(v.x()) ? std::copysign(Real(1), v.x()) : 0,
             std::isinf(v.y()) ? std::copysign(Real(1), v.y()) : 0);
  }
  const Real length = std::hypot(v.x(), v.y());
  return length > limit ? Vec2(v * (limit / length)) : v;
}

}  // namespace

using detail::Body;
using detail::Contact;
using detail::prefetch_bytes;
using detail::prefetch_line;
using detail::Shape;

namespace {

constexpr std::uint32_t kPrefetchAhead = 8;

// The three cache lines of a body record the solver's set-up reads (body.hpp).
void prefetch_solver_setup(const Body& b) {
  static_assert(offsetof(Body, gravity_scale) + sizeof(Real) <= 192);
  prefetch_bytes(&b, offsetof(Body, gravity_scale) + sizeof(Real));
}

// The four cache lines of a body record finishing its step reads and writes (body.hpp).
void prefetch_finish(const Body& b) {
  static_assert(offsetof(Body, shapes) + sizeof(b.shapes) <= 256);
  prefetch_bytes(&b, offsetof(Body, shapes) + sizeof(b.shapes));
}

// A body's list of shapes (none for a body without shapes, whose list has no storage).
void prefetch_shape_list(const Body& b) {
  if (!b.shapes.empty()) prefetch_line(b.shapes.data());
}

// Finishing a body waits on four lines in a chain (record, shape list, shape, vertices):
// the first is asked for this many bodies ahead.
constexpr std::uint32_t kFinishAhead = 16;

}  // namespace

// What finishing the step of the body at solver index k + kFinishAhead reads of its record,
// then half as far ahead its shape list, a quarter as far its shapes (geometry, box, proxy),
// an eighth as far its polygons' vertices (the new boxes are made of them; they live apart
// from the shape): each stage's lines are asked for once the last stage's are in. `only`, if
// given, picks the bodies (those with a nonzero entry).
void WorldState::prefetch_finish_ahead(std::size_t k, std::size_t end,
                                       const std::uint8_t* only) const {
  const auto ahead = [&](std::size_t distance) -> const Body* {
    const std::size_t at = k + distance;
    if (at >= end || (only != nullptr && only[at] == 0)) return nullptr;
    return &bodies[solver_to_body[at]];
  };
  if (const Body* b = ahead(kFinishAhead)) prefetch_finish(*b);
  if (const Body* b = ahead(kFinishAhead / 2)) prefetch_shape_list(*b);
  if (const Body* b = ahead(kFinishAhead / 4)) {
    for (const std::uint32_t s : b->shapes) {
      prefetch_bytes(&shapes[s], offsetof(Shape, proxy) + sizeof(ProxyId));
    }
  }
  if (const Body* b = ahead(kFinishAhead / 8)) {
    for (const std::uint32_t s : b->shapes) prefetch_polygon(shapes[s], 256);
  }
}

void WorldState::prepare_contacts() {
  const Real h = dt / substeps;
  // A body turns at most an eighth of a turn per substep (the solver's clamp).
  const Real max_angular_speed = 0.25 * std::numbers::pi / h;

  // Solver bodies: every awake body that moves, then one still body standing in for static
  // and sleeping ones.
  // Entries stay -1 between steps: only this step's solver bodies are set, and reset in
  // finish_step, so sleeping bodies are never touched.
  body_solver_index.resize(bodies.size(), -1);
  // collide() compacted the list this step; only the island pass, putting islands to sleep
  // and waking others, changes it since.
  if (def.enable_sleep && (!fell_asleep.empty() || !woken.empty())) compact_awake_list();
  const auto awake = static_cast<std::uint32_t>(awake_list.size());
  solver_bodies.resize(awake);
  solver_params.resize(awake);
  solver_to_body.assign(awake_list.begin(), awake_list.end());
  solver_info.resize(awake);
  // Each body's records are its own, so bodies are loaded in parallel.
  inverse_mass_ranges.assign(tasks.workers(), {});
  solver_inv_mass.resize(awake);
  tasks.parallel_for(awake, 256, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
    InverseMassRange range = inverse_mass_ranges[worker];
    for (std::uint32_t k = begin; k < end; ++k) {
      // Bodies are records of several cache lines apart: ask for those a few ahead early.
      if (k + kPrefetchAhead < end) prefetch_solver_setup(bodies[awake_list[k + kPrefetchAhead]]);
      const std::uint32_t i = awake_list[k];
      Body& b = bodies[i];
      body_solver_index[i] = static_cast<std::int32_t>(k);
      solver_info[k] = {b.center.x(), b.center.y(), b.inv_mass, b.inv_inertia};
      // NaN: lopsided with nothing.
      const bool could_stack =
          b.type == BodyType::dynamic && b.contacts.size() <= detail::kMostStackBodyContacts;
      solver_inv_mass[k] =
          could_stack ? static_cast<float>(b.inv_mass) : std::numeric_limits<float>::quiet_NaN();
      // The solver is single precision and squares speeds: a velocity set beyond the speed
      // limits, or a push of a huge force, is scaled down here in double precision (1e300 m/s
      // became infinite there and the body NaN). Velocities go to the limits, where the solver
      // clamps them anyway; a kinematic body, which moves by its own velocity in double
      // precision, keeps the clamped one, as its contacts see; the push keeps its direction to
      // a millionth.
      const Vec2 velocity = clamp_length(b.velocity, def.max_linear_speed);
      const Real angular_velocity =
          std::clamp(b.angular_velocity, -max_angular_speed, max_angular_speed);
      if (b.type == BodyType::kinematic) {
        b.velocity = velocity;
        b.angular_velocity = angular_velocity;
      }
      detail::SolverBody sb;
      sb.vx = velocity.x();
      sb.vy = velocity.y();
      sb.w = angular_velocity;
      solver_bodies[k] = sb;
      detail::SolverBodyParams p;
      if (b.type == BodyType::dynamic) {
        const Vec2 dv = clamp_length(h * (b.inv_mass * b.force + b.gravity_scale * def.gravity),
                                     1e6 * def.max_linear_speed);
        p.dvx = dv.x();
        p.dvy = dv.y();
        // Beyond twice the limit, the solver ends at the limit whatever the body turned at.
        p.dw =
            std::clamp(h * b.inv_inertia * b.torque, -2 * max_angular_speed, 2 * max_angular_speed);
        p.linear_damping = 1 / (1 + h * b.linear_damping);
        p.angular_damping = 1 / (1 + h * b.angular_damping);
        p.dynamic = true;
        if (could_stack) {
          range.least = std::min(range.least, b.inv_mass);
          range.greatest = std::max(range.greatest, b.inv_mass);
        }
      }
      p.far_mass_centre = b.local_center.norm() > max_world_coordinate / 2;
      solver_params[k] = p;
    }
    inverse_mass_ranges[worker] = range;
  });
  const auto still = static_cast<std::int32_t>(solver_bodies.size());
  still_body = still;
  solver_bodies.emplace_back();
  solver_params.emplace_back();
  counters.awake_bodies = solver_to_body.size();

  const Real contact_hertz = std::min(def.contact_hertz, 0.25 * substeps / dt);
  const detail::Softness soft = detail::make_softness(contact_hertz, def.contact_damping_ratio, h);
  const detail::Softness static_soft =
      detail::make_softness(2 * contact_hertz, def.contact_damping_ratio, h);

  // Which step contacts become constraints, and between which solver bodies, from the compact
  // keys rather than the contact records: one entry per step contact, kNoColor where it is no
  // constraint, so a constraint's index is its step contact's (the seeds', the keys'). The
  // solver colours them next, then each constraint is built straight into its slot.
  const LargeVector<StepContactKey>& keys = current_step_contact_keys();
  constraint_bodies.resize(step_contacts.size());
  // Contact stacks need bodies 10 times apart in mass that could be in one; most worlds have
  // none.
  Real least = std::numeric_limits<Real>::infinity(), greatest = 0;
  for (const InverseMassRange& range : inverse_mass_ranges) {
    least = std::min(least, range.least);
    greatest = std::max(greatest, range.greatest);
  }
  const bool stacks_possible = greatest >= detail::kStackMassRatio * least;
  if (stacks_possible) lopsided_marks.reset(keys.size(), tasks.workers());
  const auto lopsided = [&](std::int32_t ia, std::int32_t ib) {
    const float ma = solver_inv_mass[static_cast<std::size_t>(ia)];
    const float mb = solver_inv_mass[static_cast<std::size_t>(ib)];
    const auto ratio = static_cast<float>(detail::kStackMassRatio);
    return ma >= ratio * mb || mb >= ratio * ma;  // false with a NaN
  };
  tasks.parallel_for(static_cast<std::uint32_t>(keys.size()), 1024,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         const StepContactKey& key = keys[k];
                         const std::int32_t ia = body_solver_index[key.body_a];
                         const std::int32_t ib = body_solver_index[key.body_b];
                         if (!key.acting() || (ia < 0 && ib < 0)) {
                           constraint_bodies[k] = {still, still, true, true, detail::kNoColor};
                           continue;
                         }
                         // The solver moves dynamic bodies only (not static or kinematic, as
                         // the contact's flags say); the still body is fixed as well (the
                         // colouring relies on it).
                         constraint_bodies[k] = {
                             ia < 0 ? still : ia,   ib < 0 ? still : ib, ia < 0 || key.a_fixed,
                             ib < 0 || key.b_fixed, key.color,           key.hit_events,
                             key.point_count};
                         if (stacks_possible && ia >= 0 && ib >= 0 && !key.a_fixed &&
                             !key.b_fixed && lopsided(ia, ib)) {
                           lopsided_marks.mark(k, worker);
                         }
                       }
                     });
  find_contact_stacks(stacks_possible);
  contact_solver.begin(constraint_bodies, still, def.simd_solver, tasks);
  if (!stack_members.empty()) contact_solver.set_stacks(stack_members, stack_begin);

  // Per-constraint body data comes from the compact solver arrays and the contact's seed, not
  // the body and contact records.
  const LargeVector<detail::ContactSeed>& seeds = step_contact_seeds;
  const auto masses = [&](std::int32_t index, detail::SolverReal& inv_mass,
                          detail::SolverReal& inv_inertia) {
    if (index == still) {
      inv_mass = inv_inertia = 0;
      return;
    }
    const detail::SolverBodyInfo& info = solver_info[static_cast<std::size_t>(index)];
    inv_mass = static_cast<detail::SolverReal>(info.inv_mass);
    inv_inertia = static_cast<detail::SolverReal>(info.inv_inertia);
  };
  // The normal approach speed of a seed's point when the step began, which only restitution
  // reads: the bodies' velocities are loaded for bouncing contacts alone.
  using detail::SolverReal;
  const auto approach = [&](const detail::ContactSeed& seed, const detail::ContactSeed::Point& p,
                            std::int32_t body_a, std::int32_t body_b) {
    const detail::SolverBody& sa = solver_bodies[static_cast<std::size_t>(body_a)];
    const detail::SolverBody& sb = solver_bodies[static_cast<std::size_t>(body_b)];
    const SolverReal bx = p.ax + seed.dx, by = p.ay + seed.dy;
    const SolverReal dvx = (sb.vx - sb.w * by) - (sa.vx - sa.w * p.ay);
    const SolverReal dvy = (sb.vy + sb.w * bx) - (sa.vy + sa.w * p.ax);
    return dvx * seed.nx + dvy * seed.ny;
  };
  // Constraint r whole, one at a time: the overflow's, or every one for the scalar solver.
  const auto build = [&](std::uint32_t r, std::uint32_t worker) {
    detail::ContactConstraint k;
    const detail::ContactSeed& seed = seeds[r];
    const detail::ConstraintBodies& cb = constraint_bodies[r];
    k.body_a = cb.a;
    k.body_b = cb.b;
    masses(cb.a, k.inv_mass_a, k.inv_inertia_a);
    masses(cb.b, k.inv_mass_b, k.inv_inertia_b);
    k.nx = seed.nx;
    k.ny = seed.ny;
    k.dx = seed.dx;
    k.dy = seed.dy;
    k.friction = seed.friction;
    k.restitution = seed.restitution;
    const detail::Softness& s = (k.inv_mass_a == 0 || k.inv_mass_b == 0) ? static_soft : soft;
    k.bias_rate = s.bias_rate;
    k.mass_scale = s.mass_scale;
    k.impulse_scale = s.impulse_scale;
    k.point_count = cb.point_count;
    if (k.point_count < 2) k.points[1] = detail::ContactConstraintPoint{};
    for (int j = 0; j < k.point_count; ++j) {
      const detail::ContactSeed::Point& sp = seed.points[j];
      detail::ContactConstraintPoint& p = k.points[j];
      p.ax = sp.ax;
      p.ay = sp.ay;
      // Through the centre offset, as the wide solver recomputes it (same bits).
      p.bx = sp.ax + k.dx;
      p.by = sp.ay + k.dy;
      p.base_separation = sp.separation;  // finish_points' to finish
      p.normal_impulse = sp.normal_impulse;
      p.tangent_impulse = sp.tangent_impulse;
      p.max_normal_impulse = 0;
      p.relative_velocity = k.restitution > 0 ? approach(seed, sp, cb.a, cb.b) : 0;
    }
    detail::finish_points(k);
    contact_solver.set(r, k, worker);
  };
  // Constraint r as a lane of its SIMD batch.
  const auto batch_lane = [&](std::uint32_t r) {
    const detail::ConstraintBodies& cb = constraint_bodies[r];
    detail::BatchLane lane;
    lane.seed = &seeds[r];
    lane.body_a = cb.a;
    lane.body_b = cb.b;
    masses(cb.a, lane.inv_mass_a, lane.inv_inertia_a);
    masses(cb.b, lane.inv_mass_b, lane.inv_inertia_b);
    if (lane.seed->restitution > 0) {
      for (int j = 0; j < 2; ++j) {
        lane.relative_velocity[j] =
            j < cb.point_count ? approach(*lane.seed, lane.seed->points[j], cb.a, cb.b) : 0;
      }
    }
    return lane;
  };
  // Each constraint is built into its own slot, so they are built in parallel, in slot order
  // (one SIMD batch filled after another). A colour's seeds come in their order but with gaps,
  // and their bodies' records are scattered: those a few slots ahead are asked for early.
  const std::span<const std::uint32_t> order = contact_solver.slot_order();
  const auto prefetch_ahead = [&](std::size_t position, std::size_t end) {
    if (position + kPrefetchAhead >= end) return;
    const std::uint32_t ahead = order[position + kPrefetchAhead];
    prefetch_line(&seeds[ahead]);
    const detail::ConstraintBodies& cb = constraint_bodies[ahead];
    // The still body has no record there.
    if (cb.a != still) prefetch_line(&solver_info[static_cast<std::size_t>(cb.a)]);
    if (cb.b != still) prefetch_line(&solver_info[static_cast<std::size_t>(cb.b)]);
  };
  const auto position_of = [&](std::span<const std::uint32_t> constraints) {
    return static_cast<std::size_t>(constraints.data() - order.data());
  };
  if (def.simd_solver) {
    // A batch at a time, all its lanes at once from their seeds.
    tasks.parallel_for(contact_solver.batch_count(), 32,
                       [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                         const std::span<const std::uint32_t> last = contact_solver.batch(end - 1);
                         const std::size_t stop = position_of(last) + last.size();
                         detail::BatchLane in[detail::kWideLanes];
                         for (std::uint32_t w = begin; w < end; ++w) {
                           const std::span<const std::uint32_t> lanes = contact_solver.batch(w);
                           const std::size_t first = position_of(lanes);
                           std::uint32_t two_points = 0;
                           for (std::uint32_t lane = 0; lane < lanes.size(); ++lane) {
                             prefetch_ahead(first + lane, stop);
                             in[lane] = batch_lane(lanes[lane]);
                             if (constraint_bodies[lanes[lane]].point_count == 2) {
                               two_points |= 1u << lane;
                             }
                           }
                           contact_solver.build_batch(w, {in, lanes.size()}, two_points, soft,
                                                      static_soft, worker);
                         }
                       });
  }
  // The rest one at a time: the overflow, or every constraint for the scalar solver.
  const std::span<const std::uint32_t> singles =
      def.simd_solver ? contact_solver.overflow() : order;
  const std::size_t singles_first = position_of(singles);
  tasks.parallel_for(static_cast<std::uint32_t>(singles.size()), 256,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         prefetch_ahead(singles_first + k, singles_first + end);
                         build(singles[k], worker);
                       }
                     });
  contact_solver.finish();

  counters.constraint_colors = contact_solver.color_count();
  counters.overflow_constraints = contact_solver.overflow_count();
  counters.stacked_constraints = contact_solver.stacked_count();
}

// A stack is the set of constraints linked through moving bodies to a constraint between
// two lopsided ones (kStackMassRatio), when it is a path, each of its moving bodies in at most
// two of its constraints (a column of boxes on the ground), of at most kMaxStackRows points.
// Found by a walk from that constraint over its bodies' contact lists, given up as soon as it
// is no such path, so a world pays for its lopsided constraints' neighbourhoods only. Solved
// together, a light body in three contacts or more can be wedged between heavy ones whose
// faces close at an angle, and the exact answer shoots it out along the wedge (a watermelon
// seed): in piles of boxes, balls and capsules 1000 times apart in mass, stacks of any shape
// made more bodies fly than one contact at a time did, paths fewer. Stacks come in the order
// of their first lopsided constraint, each one's constraints in order.
void WorldState::find_contact_stacks(bool possible) {
  stack_members.clear();
  stack_begin.clear();
  if (!possible) return;
  constexpr std::uint8_t kStackNone = 0, kStackTaken = 1, kStackRefused = 2;
  stack_seen.assign(solver_to_body.size(), kStackNone);
  const auto moving = [&](std::uint32_t body, bool fixed) {
    return !fixed && body_solver_index[body] >= 0;
  };
  // Contact ci's constraint this step (the step's contacts are in contact order), if any.
  constexpr std::uint32_t kNoConstraint = ~std::uint32_t{0};
  const auto constraint_of = [&](std::uint32_t ci) {
    const auto at = std::lower_bound(step_contacts.begin(), step_contacts.end(), ci);
    if (at == step_contacts.end() || *at != ci) return kNoConstraint;
    const auto r = static_cast<std::uint32_t>(at - step_contacts.begin());
    return constraint_bodies[r].color == detail::kNoColor ? kNoConstraint : r;
  };
  lopsided_marks.for_each_marked([&](std::uint32_t seed) {
    const detail::ConstraintBodies& first = constraint_bodies[seed];
    if (stack_seen[static_cast<std::size_t>(first.a)] != kStackNone ||
        stack_seen[static_cast<std::size_t>(first.b)] != kStackNone) {
      return;  // in a stack already, or in a set that is none
    }
    stack_walk.assign({static_cast<std::uint32_t>(first.a), static_cast<std::uint32_t>(first.b)});
    stack_found.clear();
    std::uint32_t rows = 0;
    bool refused = false;
    for (std::size_t next = 0; next < stack_walk.size() && !refused; ++next) {
      if (std::isnan(solver_inv_mass[stack_walk[next]])) {
        refused = true;  // too many contacts
        break;
      }
      const Body& b = bodies[solver_to_body[stack_walk[next]]];
      int degree = 0;
      for (const std::uint32_t ci : b.contacts) {
        const Contact& c = contacts[ci];
        const std::uint32_t r = c.manifold.point_count == 0 ? kNoConstraint : constraint_of(ci);
        if (r == kNoConstraint) continue;
        if (++degree > 2) {
          refused = true;
          break;
        }
        if (std::find(stack_found.begin(), stack_found.end(), r) != stack_found.end()) continue;
        stack_found.push_back(r);
        rows += constraint_bodies[r].point_count;
        if (rows > detail::kMaxStackRows) {
          refused = true;
          break;
        }
        const std::array<std::pair<std::uint32_t, bool>, 2> ends{
            {{c.body_a, c.a_fixed}, {c.body_b, c.b_fixed}}};
        for (const auto& [body, fixed] : ends) {
          if (!moving(body, fixed)) continue;
          const auto si = static_cast<std::uint32_t>(body_solver_index[body]);
          if (stack_seen[si] == kStackRefused) {
            refused = true;
          } else if (std::find(stack_walk.begin(), stack_walk.end(), si) == stack_walk.end()) {
            stack_walk.push_back(si);
          }
        }
      }
    }
    for (const std::uint32_t si : stack_walk) {
      stack_seen[si] = refused ? kStackRefused : kStackTaken;
    }
    if (refused) return;
    std::sort(stack_found.begin(), stack_found.end());
    if (stack_begin.empty()) stack_begin.push_back(0);
    for (const std::uint32_t r : stack_found) {
      stack_members.push_back(r);
      constraint_bodies[r].color = detail::kOverflowColor;
    }
    stack_begin.push_back(static_cast<std::uint32_t>(stack_members.size()));
  });
}

void WorldState::write_back(std::uint32_t solver_index) {
  Body& b = bodies[solver_to_body[solver_index]];
  const detail::SolverBody& sb = solver_bodies[solver_index];
  b.previous_origin = b.origin;
  b.previous_rotation = b.rotation;
  b.moved_step = step_count;
  Real qc = sb.qc, qs = sb.qs;
  if (b.type == BodyType::kinematic) {
    // A kinematic body's motion is prescribed, not solved (the solver's single-precision copy
    // only served its contacts).
    const detail::KinematicMotion motion = detail::kinematic_motion(b, dt, substeps);
    qc = motion.qc;
    qs = motion.qs;
    b.center += motion.moved;
  } else {
    b.velocity = Vec2(sb.vx, sb.vy);
    b.angular_velocity = sb.w;
    b.center += detail::on_grid(Vec2(sb.dpx, sb.dpy));
  }
  b.rotation = detail::turned(b.rotation, qc, qs);
  detail::place_origin(b);
  b.force = Vec2(0, 0);
  b.torque = 0;
}

void WorldState::solve() {
  const Real h = dt / substeps;
  detail::SolverSettings settings;
  settings.h = h;
  settings.inv_h = 1 / h;
  settings.max_linear_speed = def.max_linear_speed;
  settings.contact_push_max_velocity = def.contact_push_max_velocity;
  settings.restitution_threshold = def.restitution_threshold;
  settings.substeps = substeps;
  settings.joint_iterations = def.joint_iterations;
  contact_solver.solve(solver_bodies, solver_params, settings,
                       joint_stages.empty() ? nullptr : &joint_stages, tasks);
  stop_diverged();

  // Impulses back to the contacts and poses back to the bodies, each its own record, in
  // parallel, which also marks the hits (the shapes met fast and the contact pushed: a
  // speculative point that never closed does not count); their events after, in constraint
  // order, from the marks rather than from every contact again. The impulses are read in slot
  // order, the order of the solver's lanes in memory; where they go is asked for a few ahead.
  hit_marks.assign(constraint_bodies.size(), 0);
  const auto contact_of = [&](std::uint32_t r) { return step_contacts[r]; };
  const std::span<const std::uint32_t> order = contact_solver.slot_order();
  tasks.parallel_for(
      static_cast<std::uint32_t>(order.size()), 256,
      [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t k = begin; k < end; ++k) {
          if (k + kPrefetchAhead < end) {
            prefetch_line(&contact_impulses[contact_of(order[k + kPrefetchAhead])]);
          }
          const std::uint32_t r = order[k];
          const std::uint32_t ci = contact_of(r);
          detail::ContactImpulses& impulses = contact_impulses[ci];
          contact_solver.impulses(r, impulses.normal, impulses.tangent);
          if (stopped_in_step(constraint_bodies[r].a) || stopped_in_step(constraint_bodies[r].b)) {
            impulses = {};
          }
          // The hit flag from the constraint's record: the contact's line with the approach
          // speed is read for hit-event contacts only.
          hit_marks[r] = constraint_bodies[r].hit_events &&
                         contacts[ci].approach_speed > def.hit_event_threshold &&
                         std::max(impulses.normal[0], impulses.normal[1]) > 0;
        }
      });
  for (std::uint32_t r = 0; r < constraint_bodies.size(); ++r) {
    if (hit_marks[r] == 0) continue;
    const Contact& c = contacts[contact_of(r)];
    hit_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b), c.approach_point,
                          c.manifold.normal, c.approach_speed});
  }

  // Each body's step finished in one visit while its records are at hand, bodies in parallel.
  if (def.enable_continuous) continuous.prepare_marks(solver_to_body.size(), tasks.workers());
  boxes_left.assign(solver_to_body.size(), 0);
  solver_turned.resize(step_joints.empty() ? 0 : solver_to_body.size());
  tasks.parallel_for(static_cast<std::uint32_t>(solver_to_body.size()), 128,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                       for (std::uint32_t si = begin; si < end; ++si) {
                         prefetch_finish_ahead(si, end, nullptr);
                         finish_body(si, worker);
                       }
                     });
}

// Its pose and velocity back from the solver, its shapes' boxes at the new pose (the
// broadphase takes them in finish_step), its sleep timer, and whether continuous collision
// must sweep it.
void WorldState::finish_body(std::uint32_t solver_index, std::uint32_t worker) {
  if (!solver_turned.empty()) {
    solver_turned[solver_index] = detail::delta_angle(solver_bodies[solver_index]);
  }
  write_back(solver_index);
  Body& b = bodies[solver_to_body[solver_index]];
  // A fast body's box over the step: its shapes' boxes where the step began and where it ended
  // (as Box2D v3 takes it). Their broadphase boxes cover it when each shape has one and none
  // left it: every box is held where a step begins. Without fast_body_margin, a fast body's
  // boxes end the step bare, as Box2D v3 leaves a fast body whose sweep stops it nowhere (with
  // the margin, a fast body paired with up to a fifth more shapes than Box2D v3's in washer,
  // smash and tumbler); a sweep that stops it gives them their margin again
  // (solve_continuous).
  const bool fast = def.enable_continuous && moved_fast(solver_index);
  Aabb swept = fast ? shapes[b.shapes.front()].aabb : Aabb{};
  bool has_proxies = true;
  for (const std::uint32_t s : b.shapes) {
    Shape& shape = shapes[s];
    if (fast) swept = swept.merged(shape.aabb);
    update_shape_aabb(shape, b, !fast || def.fast_body_margin);
    if (fast) swept = swept.merged(shape.aabb);
    has_proxies = has_proxies && shape.proxy != null_proxy;
    if (shape.proxy != null_proxy && !broadphase.fat_aabb(shape.proxy).contains(shape.aabb)) {
      boxes_left[solver_index] = 1;
    }
  }
  const Real linear_tolerance = def.linear_sleep_tolerance;
  const Real angular_tolerance = def.angular_sleep_tolerance;
  if (!def.enable_sleep || !b.allow_sleep || b.type != BodyType::dynamic ||
      b.velocity.squaredNorm() > linear_tolerance * linear_tolerance ||
      b.angular_velocity * b.angular_velocity > angular_tolerance * angular_tolerance) {
    b.sleep_time = 0;
  } else {
    b.sleep_time += dt;
  }
  if (fast) {
    record_fast_body(solver_index, swept, has_proxies && boxes_left[solver_index] == 0, worker);
  }
}

void WorldState::finish_step() {
  // The boxes that left their broadphase boxes in finish_body (or as continuous collision
  // stopped their body short), to the broadphase in order; the others it would keep.
  const std::size_t count = solver_to_body.size();
  for (std::size_t k = 0; k < count; ++k) {
    prefetch_finish_ahead(k, count, boxes_left.data());
    if (boxes_left[k] == 0) continue;
    for (std::uint32_t s : bodies[solver_to_body[k]].shapes) {
      if (shapes[s].proxy != null_proxy) broadphase.move_proxy(shapes[s].proxy, shapes[s].aabb);
    }
  }
  // Move events in body slot order: the simulated bodies (in parallel, each to its own
  // place, which also ends the step's solver index of each), and those that fell asleep.
  const std::size_t first_event = move_events.size();
  move_events.resize(first_event + solver_to_body.size());
  tasks.parallel_for(static_cast<std::uint32_t>(solver_to_body.size()), 256,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         const std::uint32_t i = solver_to_body[k];
                         const Body& b = bodies[i];
                         move_events[first_event + k] = {body_id(i), b.pose(), false, b.user_data};
                         body_solver_index[i] = -1;
                       }
                     });
  for (const std::uint32_t i : fell_asleep) {
    const Body& b = bodies[i];
    move_events.push_back({body_id(i), b.pose(), true, b.user_data});
  }
  if (!fell_asleep.empty()) {
    // The simulated bodies' events are in slot order already: the few that fell asleep are
    // sorted and merged in, and an advance's earlier steps keep theirs apart.
    const auto by_slot = [](const BodyMoveEvent& x, const BodyMoveEvent& y) {
      return x.body.index < y.body.index;
    };
    const auto step_begin = move_events.begin() + static_cast<std::ptrdiff_t>(first_event);
    const auto asleep_begin = step_begin + static_cast<std::ptrdiff_t>(solver_to_body.size());
    std::sort(asleep_begin, move_events.end(), by_slot);
    std::inplace_merge(step_begin, asleep_begin, move_events.end(), by_slot);
  }
  counters.broadphase_pairs = broadphase.pairs().size();
  counters.contacts = contacts.size();
  counters.touching_contacts = touching_count;
}

}  // namespace mink
