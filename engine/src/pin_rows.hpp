#pragma once

// The point row of revolute, weld and motor joints (B's anchor held on A's) in the solver's
// single precision: one function of the number type, which the one-at-a-time rows run on
// floats and the wide rows on kWideLanes joints at once (a colour's pins, as Box2D v3's joint
// grid is made of), so both give the same bits. The joint records' rows (joint_rows.cpp) run
// the same function, so a joint solved from its record, from a revolute row or as a pin moves
// its bodies alike.

#include <cstdint>

#include "contact_kernels.hpp"

namespace mink::detail {

// A revolute joint that is only its point row, solved one at a time: 68 bytes.
struct PinRow {
  std::int32_t body_a, body_b;  // solver bodies
  SolverReal inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
  SolverReal anchor_ax, anchor_ay, anchor_bx, anchor_by;  // from each centre, at step start
  SolverReal delta_x, delta_y;                            // B's centre minus A's, at step start
  SolverReal bias_rate, mass_scale, impulse_scale;        // the joint softness
  SolverReal impulse_x, impulse_y;  // accumulated, kept between steps for warm starting
};

// kWideLanes pins of one colour side by side, PinRow's fields a register each (not a template
// of the number type: a template argument would drop the registers' 32-byte alignment); lanes
// past `lanes` are unused (they hold lane 0's pin again, solved and never written back).
struct WidePinRows {
  std::int32_t body_a[kWideLanes], body_b[kWideLanes];
  Wide inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
  Wide anchor_ax, anchor_ay, anchor_bx, anchor_by;
  Wide delta_x, delta_y;
  Wide bias_rate, mass_scale, impulse_scale;
  Wide impulse_x, impulse_y;
  std::int32_t lanes;
};

// Applies impulse (px, py) at B's anchor, angular impulse `angular` on the relative angle, and
// the opposite to A. `Row`: a PinRow or WidePinRows; `Body`: a SolverBody, or kWideLanes of
// them a field per register.
template <typename Row, typename Body>
__attribute__((always_inline)) inline void pin_warm_start(Body& a, Body& b, const Row& t,
                                                          const decltype(Row::impulse_x)& angular) {
  using T = decltype(Row::impulse_x);
  const T px = t.impulse_x, py = t.impulse_y;
  const T rax = a.qc * t.anchor_ax - a.qs * t.anchor_ay;
  const T ray = a.qs * t.anchor_ax + a.qc * t.anchor_ay;
  const T rbx = b.qc * t.anchor_bx - b.qs * t.anchor_by;
  const T rby = b.qs * t.anchor_bx + b.qc * t.anchor_by;
  a.vx -= t.inv_mass_a * px;
  a.vy -= t.inv_mass_a * py;
  a.w -= t.inv_inertia_a * ((rax * py - ray * px) + angular);
  b.vx += t.inv_mass_b * px;
  b.vy += t.inv_mass_b * py;
  b.w += t.inv_inertia_b * ((rbx * py - rby * px) + angular);
}

// One pass of the point row at the anchors as the substep has turned them: the 2x2 effective
// mass solved directly, the position error pushed out through the softness when `use_bias`.
// The row's impulse accumulates.
template <typename Row, typename Body>
__attribute__((always_inline)) inline void pin_solve(Body& a, Body& b, Row& t, bool use_bias) {
  using T = decltype(Row::impulse_x);
  const T zero{}, one = zero + SolverReal{1};
  const T rax = a.qc * t.anchor_ax - a.qs * t.anchor_ay;
  const T ray = a.qs * t.anchor_ax + a.qc * t.anchor_ay;
  const T rbx = b.qc * t.anchor_bx - b.qs * t.anchor_by;
  const T rby = b.qs * t.anchor_bx + b.qc * t.anchor_by;
  T bias_x = zero, bias_y = zero, mass_scale = one, impulse_scale = zero;
  if (use_bias) {
    bias_x = t.bias_rate * (((b.dpx - a.dpx) + t.delta_x) + (rbx - rax));
    bias_y = t.bias_rate * (((b.dpy - a.dpy) + t.delta_y) + (rby - ray));
    mass_scale = t.mass_scale;
    impulse_scale = t.impulse_scale;
  }
  const T rx = ((b.vx - b.w * rby) - (a.vx - a.w * ray)) + bias_x;
  const T ry = ((b.vy + b.w * rbx) - (a.vy + a.w * rax)) + bias_y;
  const T ma = t.inv_mass_a, ia = t.inv_inertia_a, mb = t.inv_mass_b, ib = t.inv_inertia_b;
  const T k11 = (ma + mb) + ray * ray * ia + rby * rby * ib;
  const T k12 = zero - ray * rax * ia - rby * rbx * ib;
  const T k22 = (ma + mb) + rax * rax * ia + rbx * rbx * ib;
  const T det = k11 * k22 - k12 * k12;
  const T inv_det = det != zero ? one / det : zero;
  const T px = zero - mass_scale * (inv_det * (k22 * rx - k12 * ry)) - impulse_scale * t.impulse_x;
  const T py = zero - mass_scale * (inv_det * (k11 * ry - k12 * rx)) - impulse_scale * t.impulse_y;
  t.impulse_x += px;
  t.impulse_y += py;
  a.vx -= ma * px;
  a.vy -= ma * py;
  a.w -= ia * (rax * py - ray * px);
  b.vx += mb * px;
  b.vy += mb * py;
  b.w += ib * (rbx * py - rby * px);
}

inline void warm_start_pin(SolverBody* bodies, const PinRow& row, SolverReal angular = 0) {
  pin_warm_start(bodies[row.body_a], bodies[row.body_b], row, angular);
}
inline void solve_pin(SolverBody* bodies, PinRow& row, bool use_bias) {
  pin_solve(bodies[row.body_a], bodies[row.body_b], row, use_bias);
}

// kWideLanes pins at a time (pin_rows_wide.cpp), over one colour's [begin, end).
void warm_start_pins_wide(SolverBody* bodies, const WidePinRows* begin, const WidePinRows* end);
void solve_pins_wide(SolverBody* bodies, WidePinRows* begin, WidePinRows* end, bool use_bias);
// Writes `row` into lane `lane` of `wide`, and reads a lane's impulse back.
void pack_pin(WidePinRows& wide, int lane, const PinRow& row);

}  // namespace mink::detail
