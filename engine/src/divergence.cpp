// A solve that diverged: the bodies it diverged on, and every body joined to them by joints
// and contacts, put back where the step began, at rest, their joints' and contacts' impulses
// forgotten, and each reported (BodyStoppedEvent). The single-precision solver cannot hold
// every system the API accepts (a joint anchor kilometres from a light body, inertias a
// billion times apart pulling on each other): such a solve runs away within a few substeps,
// and a NaN or a body flung past the world's limit would otherwise reach the world's state,
// its snapshots and every later step.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "checks.hpp"
#include "joint_common.hpp"
#include "union_find.hpp"
#include "world_state.hpp"

namespace mink {

namespace {

// A speed this many times the limits is no motion the solver meant: velocities start each
// substep within them, and the fastest a joint row spins a body in the benchmark suite and
// the examples is 13 times the turn limit (a lander's light leg against its hull).
constexpr Real kRunawayFactor = 1000;

// What a stopped joint forgets: the impulses it warm starts from.
void forget(detail::RevoluteJoint& j) {
  j.linear_impulse = {0, 0};
  j.spring_impulse = j.motor_impulse = j.lower_impulse = j.upper_impulse = 0;
}
void forget(detail::PrismaticJoint& j) {
  j.block_impulse = {0, 0};
  j.spring_impulse = j.motor_impulse = j.lower_impulse = j.upper_impulse = 0;
}
void forget(detail::DistanceJoint& j) {
  j.impulse = j.lower_impulse = j.upper_impulse = j.motor_impulse = 0;
}
void forget(detail::WeldJoint& j) {
  j.linear_impulse = {0, 0};
  j.angular_impulse = 0;
}
void forget(detail::WheelJoint& j) {
  j.perp_impulse = j.spring_impulse = j.lower_impulse = j.upper_impulse = j.motor_impulse = 0;
}
void forget(detail::MotorJoint& j) {
  j.linear_impulse = {0, 0};
  j.angular_impulse = 0;
}
void forget(detail::GearJoint& j) {
  j.impulse = 0;
}
void forget(detail::PulleyJoint& j) {
  j.impulse = 0;
}

}  // namespace

// Whether the solve diverged on solver body `k`: a number no float holds, a runaway speed, or
// an origin the step would take beyond max_world_coordinate.
bool WorldState::solve_diverged(std::uint32_t k, Real max_speed, Real max_angular_speed) const {
  const detail::SolverBodyParams& params = solver_params[k];
  const Vec2 start(solver_info[k].cx, solver_info[k].cy);
  // A centre of mass within a quarter of the limit, and within half of it from the origin,
  // keeps the origin within the limit whatever the turn; only otherwise is it placed exactly.
  const auto origin_within = [&](const Vec2& center, Real qc, Real qs) {
    if (detail::within(center, max_world_coordinate / 4) && !params.far_mass_centre) return true;
    const detail::Body& b = bodies[solver_to_body[k]];
    const Rotation rotation = detail::turned(b.rotation, qc, qs);
    return detail::within_world(center - detail::on_grid(rotation.apply(b.local_center)));
  };
  if (!params.dynamic) {
    // A kinematic body moves by its own velocity, which the solve does not change: only where
    // it goes can be beyond the world. Its step moves it at most dt times the speed limit.
    if (detail::within(start, max_world_coordinate / 8) && !params.far_mass_centre &&
        dt * def.max_linear_speed <= max_world_coordinate / 8) {
      return false;
    }
    const detail::KinematicMotion motion =
        detail::kinematic_motion(bodies[solver_to_body[k]], dt, substeps);
    return !origin_within(start + motion.moved, motion.qc, motion.qs);
  }
  const detail::SolverBody& s = solver_bodies[k];
  const Real vx = s.vx, vy = s.vy, w = s.w;
  for (const Real v : {vx, vy, w, Real(s.dpx), Real(s.dpy), Real(s.qc), Real(s.qs)}) {
    if (!std::isfinite(v)) return true;
  }
  if (vx * vx + vy * vy > max_speed * max_speed || std::abs(w) > max_angular_speed) return true;
  return !origin_within(start + detail::on_grid(Vec2(s.dpx, s.dpy)), s.qc, s.qs);
}

void WorldState::stop_diverged() {
  const auto count = static_cast<std::uint32_t>(solver_to_body.size());
  const Real h = dt / substeps;
  const Real max_speed = kRunawayFactor * def.max_linear_speed;
  const Real max_angular_speed = kRunawayFactor * 0.25 * std::numbers::pi / h;
  stopped.clear();
  // The common case, every solve held, costs one read of each body in parallel.
  std::atomic<bool> any{false};
  tasks.parallel_for(count, 256, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
    for (std::uint32_t k = begin; k < end; ++k) {
      if (solve_diverged(k, max_speed, max_angular_speed)) {
        any.store(true, std::memory_order_relaxed);
        return;
      }
    }
  });
  if (!any.load()) return;

  // Rare from here on, and serial: which bodies diverged, and what joins them.
  stopped.assign(count, 0);
  std::vector<std::uint32_t> parent(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    parent[k] = k;
    if (solve_diverged(k, max_speed, max_angular_speed)) stopped[k] = 1;
  }
  const auto pulled = [&](std::int32_t solver_index) {
    return solver_index >= 0 && static_cast<std::uint32_t>(solver_index) < count &&
           solver_params[static_cast<std::uint32_t>(solver_index)].dynamic;
  };
  for (const detail::ConstraintBodies& c : constraint_bodies) {
    if (pulled(c.a) && pulled(c.b)) {
      detail::join_sets(parent, static_cast<std::uint32_t>(c.a), static_cast<std::uint32_t>(c.b));
    }
  }
  // The joints' bodies from their compact copies, not from the kilobyte records.
  for (const std::uint32_t j : step_joints) {
    const detail::JointBodies& joint = joint_bodies[j];
    std::int32_t first = -1;
    for (std::uint32_t k = 0; k < joint.count; ++k) {
      const std::int32_t s = body_solver_index[joint.body[k]];
      if (!pulled(s)) continue;
      if (first < 0) {
        first = s;
      } else {
        detail::join_sets(parent, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(s));
      }
    }
  }
  std::vector<std::uint8_t> diverged_root(count, 0);
  for (std::uint32_t k = 0; k < count; ++k) {
    if (stopped[k] == 1) diverged_root[detail::find_set(parent, k)] = 1;
  }
  const std::size_t first_event = stopped_events.size();
  for (std::uint32_t k = 0; k < count; ++k) {
    if (stopped[k] == 0 && diverged_root[detail::find_set(parent, k)] != 0) stopped[k] = 2;
    if (stopped[k] == 0) continue;
    // No motion since the step began: write_back leaves the pose and sets the body at rest (a
    // kinematic body, moved by its own velocity, is set at rest here).
    solver_bodies[k] = detail::SolverBody{};
    const std::uint32_t i = solver_to_body[k];
    if (!solver_params[k].dynamic) {
      bodies[i].velocity = Vec2(0, 0);
      bodies[i].angular_velocity = 0;
    }
    stopped_events.push_back({body_id(i), stopped[k] == 1, bodies[i].user_data});
  }
  std::sort(stopped_events.begin() + static_cast<std::ptrdiff_t>(first_event), stopped_events.end(),
            [](const BodyStoppedEvent& x, const BodyStoppedEvent& y) {
              return x.body.index < y.body.index;
            });
}

void detail::forget_impulses(Joint& joint) {
  std::visit([](auto& kind) { forget(kind); }, joint.kind);
  joint.reaction = {};
}

}  // namespace mink
