#pragma once

#include <cstdint>
#include <span>

#include "contact_solver.hpp"

namespace mink::detail {

// One AVX2 register of solver numbers. Explicitly 32-byte aligned: without AVX enabled GCC
// would align it to 16 only, and the AVX2 build of the kernels uses aligned loads.
typedef SolverReal Wide __attribute__((vector_size(32), aligned(32)));
inline constexpr int kWideLanes = 32 / sizeof(SolverReal);

struct WideConstraint {
  std::int32_t body_a[kWideLanes], body_b[kWideLanes];
  Wide inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
  Wide nx, ny, friction, bias_rate, mass_scale, impulse_scale;
  Wide dx, dy;  // centre of A minus centre of B: anchor on B = anchor on A + (dx, dy)
  struct Point {
    Wide ax, ay, base_separation, normal_mass, tangent_mass, normal_impulse, tangent_impulse;
  } points[2];
};

// Per wide constraint, each point's largest single impulse of the step (restitution only).
struct WideMaxImpulse {
  Wide point[2];
};

// Each point's normal and tangent masses, and its base separation from the separation its
// field holds until then: the separation less the anchors' offset along the normal.
void finish_points(ContactConstraint& c);
// The same for the lanes of a SIMD batch (same bits); a lane whose bit in `two_points` is
// clear keeps its second point zero, as a one-point constraint's is.
void finish_points_wide(WideConstraint& w, std::uint32_t two_points);

// One constraint at a time (the overflow, and the whole solve in scalar mode).
void integrate_velocities(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
                          const SolverSettings& settings);
void integrate_positions(std::span<SolverBody> bodies, SolverReal h);
void warm_start_one(SolverBody* bodies, ContactConstraint& c);
// Both points are always processed: a one-point manifold's second point has zero masses and
// impulses, so it changes nothing, and the lanes of the wide path stay uniform.
void solve_one(SolverBody* bodies, ContactConstraint& c, SolverReal inv_h, SolverReal max_push,
               bool use_bias);

// The parts of solve_one, for a solver that takes a constraint's normal rows elsewhere (the
// direct solve of contact stacks) and its friction as solve_one does.
// The velocities of a constraint's two bodies while it is solved.
struct PairVelocity {
  SolverReal vax, vay, wa, vbx, vby, wb;
  // An impulse (px, py) at point p, on B and against A.
  void apply(const ContactConstraint& c, const ContactConstraintPoint& p, SolverReal px,
             SolverReal py);
  // Point p's speed along the normal, B relative to A.
  SolverReal normal_speed(const ContactConstraint& c, const ContactConstraintPoint& p) const;
};
PairVelocity load_pair(const SolverBody* bodies, const ContactConstraint& c);
// Leaves a body the solver cannot move as it is.
void store_pair(SolverBody* bodies, const ContactConstraint& c, const PairVelocity& v);
// Point p's separation now, its anchors moved with their bodies since the step began.
SolverReal separation_now(const SolverBody& a, const SolverBody& b, const ContactConstraint& c,
                          const ContactConstraintPoint& p);
// What a normal row aims for at a separation: the bias speed, and the softness's share of the
// row's mass and of its accumulated impulse that it applies.
struct PointBias {
  SolverReal bias, mass_scale, impulse_scale;
};
PointBias point_bias(const ContactConstraint& c, SolverReal separation, SolverReal inv_h,
                     SolverReal max_push, bool use_bias);
// Both points' friction against the velocities `v`, which it updates.
void solve_friction(ContactConstraint& c, PairVelocity& v);
void restitution_one(SolverBody* bodies, ContactConstraint& c, SolverReal threshold);

// kWideLanes at a time, over a colour's wide constraints [begin, end).
void warm_start_wide(SolverBody* bodies, WideConstraint* begin, WideConstraint* end);
// `max_impulse` (one per wide constraint) tracks each point's largest impulse for restitution;
// null when nothing bounces.
void solve_wide(SolverBody* bodies, WideConstraint* begin, WideConstraint* end,
                WideMaxImpulse* max_impulse, SolverReal inv_h, SolverReal max_push, bool use_bias);
// The lanes of a SIMD batch built from their seeds, `count` of them, the lanes past them
// padding (body `padding_body` on both sides, no mass, no impulse): bitwise what packing each
// whole constraint and then finish_points_wide give. `soft` between two moving bodies,
// `fixed_soft` where a side has no mass.
void build_wide(WideConstraint& w, const BatchLane* lanes, int count, std::uint32_t two_points,
                std::int32_t padding_body, const Softness& soft, const Softness& fixed_soft);
// Writes `constraint` into lane `lane` of `wide`.
void pack(WideConstraint& wide, int lane, const ContactConstraint& constraint);
// Lane `lane` of `wide` as a constraint, its current impulses included; the fields the lanes do
// not hold (restitution, relative and largest impulses) are zero.
ContactConstraint unpack(const WideConstraint& wide, int lane);

}  // namespace mink::detail
