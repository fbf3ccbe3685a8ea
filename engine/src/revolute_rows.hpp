#pragma once

// A revolute joint's rows as the solver runs them every substep: the spring, the motor and the
// two limits on the relative angle, then the point row (pin_rows.hpp), in the solver's single
// precision. One function of the number type, which the one-at-a-time rows run on floats and
// the wide rows on kWideLanes joints of one colour at once (a rain of ragdolls is made of
// them), so both give the same bits; the joint's record (revolute_joint.cpp) runs the same
// rows too. A row switched off in one lane computes like the others and is then not applied:
// the lanes never branch apart.

#include <cstdint>

#include "joint_common.hpp"
#include "pin_rows.hpp"

namespace mink::detail {

// The angle rows' fields beside the point row's, named alike in RevoluteRow (SolverReal) and
// WideRevoluteRows (a register of kWideLanes each).
#define MINK_REVOLUTE_ANGLE_FIELDS(T)                                                      \
  T axial_mass;                                                /* 1 / (iA + iB) */         \
  T spring_bias_rate, spring_mass_scale, spring_impulse_scale; /* the spring's softness */ \
  T spring_offset; /* the step-start angle less the spring's target */                     \
  T motor_speed, motor_max_impulse;                                                        \
  T lower_offset; /* the step-start angle less the lower limit */                          \
  T upper_offset; /* the upper limit less the step-start angle */                          \
  T inv_h;                                                                                 \
  T spring_on, motor_on, limit_on; /* 1 where the row acts, 0 where it is switched off */  \
  T spring_impulse, motor_impulse, lower_impulse, upper_impulse; /* accumulated, warm started */

// One joint. `point`: its point row is solved here, rather than by its chain's direct solve
// (joint_chain_solver.hpp), which then also warm starts it (its impulse here stays zero).
struct RevoluteRow : PinRow {
  MINK_REVOLUTE_ANGLE_FIELDS(SolverReal)
  bool point;
};

// kWideLanes joints of one colour side by side, all with the point row or all without; lanes
// past `lanes` hold lane 0's joint again (solved, never written back).
struct WideRevoluteRows : WidePinRows {
  MINK_REVOLUTE_ANGLE_FIELDS(Wide)
  bool point;
};

#undef MINK_REVOLUTE_ANGLE_FIELDS

// The rows below pass registers by value between their parts, always inlined into the wide
// kernels' clones (wide_body.hpp).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

// Warm starts the point row's impulse and the angle rows' together.
template <typename Row, typename Body>
__attribute__((always_inline)) inline void revolute_warm_start(Body& a, Body& b, const Row& t) {
  pin_warm_start(a, b, t,
                 ((t.spring_impulse + t.motor_impulse) + t.lower_impulse) - t.upper_impulse);
}

// One pass of the rows, in the order the point row matters least to most: spring, motor,
// limits, point. The angle is read once (the rows change velocities, not the angle).
template <typename Row, typename Body>
__attribute__((always_inline)) inline void revolute_solve(Body& a, Body& b, Row& t, bool use_bias) {
  using T = decltype(Row::impulse_x);
  const T zero{}, one = zero + SolverReal{1};
  const T ia = t.inv_inertia_a, ib = t.inv_inertia_b, k = t.axial_mass;
  const T turn = solver_relative_turn(a, b);
  {
    const T cdot = b.w - a.w;
    const T bias = t.spring_bias_rate * (t.spring_offset + turn);
    T p =
        zero - t.spring_mass_scale * k * (cdot + bias) - t.spring_impulse_scale * t.spring_impulse;
    p = t.spring_on != zero ? p : zero;
    t.spring_impulse += p;
    a.w -= ia * p;
    b.w += ib * p;
  }
  {
    const T cdot = (b.w - a.w) - t.motor_speed;
    const T old = t.motor_impulse, bound = t.motor_max_impulse;
    T impulse = old - k * cdot;
    impulse = impulse < zero - bound ? zero - bound : (bound < impulse ? bound : impulse);
    impulse = t.motor_on != zero ? impulse : old;
    t.motor_impulse = impulse;
    const T p = impulse - old;
    a.w -= ia * p;
    b.w += ib * p;
  }
  // A limit not reached is speculative: it lets the angle arrive at the bound in one substep
  // and no further; once reached it is rigid, pushing out through the joint softness.
  const auto limit_row = [&](const T& error, const T& cdot, const T& impulse) {
    const auto apart = error > zero;
    T bias = zero, mass_scale = one, impulse_scale = zero;
    if (use_bias) {
      bias = t.bias_rate * error;
      mass_scale = t.mass_scale;
      impulse_scale = t.impulse_scale;
    }
    bias = apart ? error * t.inv_h : bias;
    mass_scale = apart ? one : mass_scale;
    impulse_scale = apart ? zero : impulse_scale;
    const T p = zero - mass_scale * k * (cdot + bias) - impulse_scale * impulse;
    T total = impulse + p;
    total = total < zero ? zero : total;
    return t.limit_on != zero ? total : impulse;
  };
  {
    const T total = limit_row(t.lower_offset + turn, b.w - a.w, t.lower_impulse);
    const T p = total - t.lower_impulse;
    t.lower_impulse = total;
    a.w -= ia * p;
    b.w += ib * p;
  }
  {
    const T total = limit_row(t.upper_offset - turn, a.w - b.w, t.upper_impulse);
    const T p = total - t.upper_impulse;
    t.upper_impulse = total;
    a.w += ia * p;
    b.w -= ib * p;
  }
  if (t.point) pin_solve(a, b, t, use_bias);
}

#pragma GCC diagnostic pop

inline void warm_start_revolute(SolverBody* bodies, const RevoluteRow& row) {
  revolute_warm_start(bodies[row.body_a], bodies[row.body_b], row);
}
inline void solve_revolute(SolverBody* bodies, RevoluteRow& row, bool use_bias) {
  revolute_solve(bodies[row.body_a], bodies[row.body_b], row, use_bias);
}

// kWideLanes joints at a time (revolute_rows_wide.cpp).
void warm_start_revolutes_wide(SolverBody* bodies, const WideRevoluteRows& rows);
void solve_revolutes_wide(SolverBody* bodies, WideRevoluteRows& rows, bool use_bias);
// Writes `row` into lane `lane` of `wide` (`wide.point` is the caller's); and copies a lane's
// accumulated impulses, what the solve changed, back into its row.
void pack_revolute(WideRevoluteRows& wide, int lane, const RevoluteRow& row);
void read_impulses(const WideRevoluteRows& wide, int lane, RevoluteRow& row);

}  // namespace mink::detail
