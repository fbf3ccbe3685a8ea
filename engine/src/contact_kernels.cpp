// The soft-step contact kernels, one constraint at a time: integration of a substep, warm
// start, the solve with and without bias, restitution. The wide (SIMD) kernels in
// contact_kernels_wide.cpp are written lane for lane like these, so both give the same bits.

#include "contact_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mink::detail {

Softness make_softness(Real hertz, Real damping_ratio, Real h) {
  if (hertz == 0) return {0, 1, 0};
  const Real omega = 2 * std::numbers::pi * hertz;
  const Real a1 = 2 * damping_ratio + h * omega;
  const Real a2 = h * omega * a1;
  const Real a3 = 1 / (1 + a2);
  // Undamped at a frequency so low that h * omega underflows to 0 (a spring of 5e-324 hertz),
  // the rate is its limit, omega / (h omega) = 1 / h, not omega / 0.
  return {a1 > 0 ? omega / a1 : 1 / h, a2 * a3, a3};
}

namespace {

// Written exactly as the wide path's lane-wise selects, so both give the same bits (even the
// sign of a zero).
inline SolverReal smax(SolverReal a, SolverReal b) {
  return a > b ? a : b;
}
inline SolverReal smin(SolverReal a, SolverReal b) {
  return a < b ? a : b;
}

// As the wide path's scatter: a body the solver cannot move (no inverse mass or inertia) may
// be in several constraints of a colour solved at once on other threads, so it is never
// written.
inline void store_velocity(SolverBody& body, SolverReal inv_mass, SolverReal inv_inertia,
                           SolverReal vx, SolverReal vy, SolverReal w) {
  if (inv_mass == 0 && inv_inertia == 0) return;
  body.vx = vx;
  body.vy = vy;
  body.w = w;
}

}  // namespace

void integrate_velocities(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
                          const SolverSettings& settings) {
  const SolverReal max_speed_squared = settings.max_linear_speed * settings.max_linear_speed;
  // A body may turn at most an eighth of a turn per substep: beyond that the rotation
  // integration below is meaningless.
  const SolverReal max_angular_speed = 0.25 * std::numbers::pi * settings.inv_h;
  const std::size_t count = bodies.size();
  for (std::size_t i = 0; i < count; ++i) {
    SolverBody& body = bodies[i];
    const SolverBodyParams& p = params[i];
    SolverReal vx = body.vx * p.linear_damping + p.dvx;
    SolverReal vy = body.vy * p.linear_damping + p.dvy;
    SolverReal w = body.w * p.angular_damping + p.dw;
    const SolverReal speed_squared = vx * vx + vy * vy;
    if (speed_squared > max_speed_squared) {
      const SolverReal ratio = settings.max_linear_speed / std::sqrt(speed_squared);
      vx *= ratio;
      vy *= ratio;
    }
    w = std::clamp(w, -max_angular_speed, max_angular_speed);
    body.vx = vx;
    body.vy = vy;
    body.w = w;
  }
}

void integrate_positions(std::span<SolverBody> bodies, SolverReal h) {
  for (SolverBody& body : bodies) {
    body.dpx += h * body.vx;
    body.dpy += h * body.vy;
    // q += h * w * perp(q), renormalised: exact direction, a cheap stand-in for sin/cos.
    const SolverReal hw = h * body.w;
    body.turn += hw;
    const SolverReal qc = body.qc - hw * body.qs;
    const SolverReal qs = body.qs + hw * body.qc;
    const SolverReal inv_length = 1 / std::sqrt(qc * qc + qs * qs);
    body.qc = qc * inv_length;
    body.qs = qs * inv_length;
  }
}

void warm_start_one(SolverBody* bodies, ContactConstraint& c) {
  SolverBody& a = bodies[c.body_a];
  SolverBody& b = bodies[c.body_b];
  const SolverReal tx = c.ny, ty = -c.nx;
  SolverReal vax = a.vx, vay = a.vy, wa = a.w, vbx = b.vx, vby = b.vy, wb = b.w;
  for (int j = 0; j < 2; ++j) {
    const ContactConstraintPoint& p = c.points[j];
    const SolverReal px = p.normal_impulse * c.nx + p.tangent_impulse * tx;
    const SolverReal py = p.normal_impulse * c.ny + p.tangent_impulse * ty;
    wa -= c.inv_inertia_a * (p.ax * py - p.ay * px);
    vax -= c.inv_mass_a * px;
    vay -= c.inv_mass_a * py;
    wb += c.inv_inertia_b * (p.bx * py - p.by * px);
    vbx += c.inv_mass_b * px;
    vby += c.inv_mass_b * py;
  }
  store_velocity(a, c.inv_mass_a, c.inv_inertia_a, vax, vay, wa);
  store_velocity(b, c.inv_mass_b, c.inv_inertia_b, vbx, vby, wb);
}

void PairVelocity::apply(const ContactConstraint& c, const ContactConstraintPoint& p, SolverReal px,
                         SolverReal py) {
  vax -= c.inv_mass_a * px;
  vay -= c.inv_mass_a * py;
  wa -= c.inv_inertia_a * (p.ax * py - p.ay * px);
  vbx += c.inv_mass_b * px;
  vby += c.inv_mass_b * py;
  wb += c.inv_inertia_b * (p.bx * py - p.by * px);
}

SolverReal PairVelocity::normal_speed(const ContactConstraint& c,
                                      const ContactConstraintPoint& p) const {
  const SolverReal dvx = (vbx - wb * p.by) - (vax - wa * p.ay);
  const SolverReal dvy = (vby + wb * p.bx) - (vay + wa * p.ax);
  return dvx * c.nx + dvy * c.ny;
}

PairVelocity load_pair(const SolverBody* bodies, const ContactConstraint& c) {
  const SolverBody& a = bodies[c.body_a];
  const SolverBody& b = bodies[c.body_b];
  return {a.vx, a.vy, a.w, b.vx, b.vy, b.w};
}

void store_pair(SolverBody* bodies, const ContactConstraint& c, const PairVelocity& v) {
  store_velocity(bodies[c.body_a], c.inv_mass_a, c.inv_inertia_a, v.vax, v.vay, v.wa);
  store_velocity(bodies[c.body_b], c.inv_mass_b, c.inv_inertia_b, v.vbx, v.vby, v.wb);
}

SolverReal separation_now(const SolverBody& a, const SolverBody& b, const ContactConstraint& c,
                          const ContactConstraintPoint& p) {
  // The anchors moved with their bodies since the step began.
  const SolverReal dpx = b.dpx - a.dpx, dpy = b.dpy - a.dpy;
  const SolverReal prax = a.qc * p.ax - a.qs * p.ay, pray = a.qs * p.ax + a.qc * p.ay;
  const SolverReal prbx = b.qc * p.bx - b.qs * p.by, prby = b.qs * p.bx + b.qc * p.by;
  return (dpx + prbx - prax) * c.nx + (dpy + prby - pray) * c.ny + p.base_separation;
}

PointBias point_bias(const ContactConstraint& c, SolverReal separation, SolverReal inv_h,
                     SolverReal max_push, bool use_bias) {
  if (separation > 0) return {separation * inv_h, 1, 0};  // speculative: close the gap, no more
  if (!use_bias) return {0, 1, 0};
  return {smax(c.bias_rate * separation, -max_push), c.mass_scale, c.impulse_scale};
}

void solve_one(SolverBody* bodies, ContactConstraint& c, SolverReal inv_h, SolverReal max_push,
               bool use_bias) {
  const SolverBody& a = bodies[c.body_a];
  const SolverBody& b = bodies[c.body_b];
  PairVelocity v = load_pair(bodies, c);
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    const PointBias pb = point_bias(c, separation_now(a, b, c, p), inv_h, max_push, use_bias);
    SolverReal impulse = -p.normal_mass * pb.mass_scale * (v.normal_speed(c, p) + pb.bias) -
                         pb.impulse_scale * p.normal_impulse;
    const SolverReal accumulated = smax(p.normal_impulse + impulse, SolverReal{0});
    impulse = accumulated - p.normal_impulse;
    p.normal_impulse = accumulated;
    p.max_normal_impulse = smax(p.max_normal_impulse, impulse);
    v.apply(c, p, impulse * c.nx, impulse * c.ny);
  }
  if (!use_bias) solve_friction(c, v);
  store_pair(bodies, c, v);
}

// Friction in the relax pass only. Solved in the biased pass as well, it also answered the
// push-out's sideways share and fought each substep's normal correction, and the light boxes
// near a stiff stack's top walked: a 40-row pyramid's top box crept 0.6 m sideways in 500
// steps at 60 Hz contacts. Against velocities rid of the bias it holds them (2 cm).
void solve_friction(ContactConstraint& c, PairVelocity& v) {
  const SolverReal tx = c.ny, ty = -c.nx;
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    const SolverReal dvx = (v.vbx - v.wb * p.by) - (v.vax - v.wa * p.ay);
    const SolverReal dvy = (v.vby + v.wb * p.bx) - (v.vay + v.wa * p.ax);
    const SolverReal vt = dvx * tx + dvy * ty;
    const SolverReal limit = c.friction * p.normal_impulse;
    const SolverReal accumulated =
        smin(smax(p.tangent_impulse - p.tangent_mass * vt, -limit), limit);
    const SolverReal impulse = accumulated - p.tangent_impulse;
    p.tangent_impulse = accumulated;
    v.apply(c, p, impulse * tx, impulse * ty);
  }
}

void finish_points(ContactConstraint& c) {
  const SolverReal nx = c.nx, ny = c.ny, tx = ny, ty = -nx;
  const SolverReal ma = c.inv_mass_a, ia = c.inv_inertia_a, mb = c.inv_mass_b, ib = c.inv_inertia_b;
  for (int j = 0; j < c.point_count; ++j) {
    ContactConstraintPoint& p = c.points[j];
    const SolverReal ax = p.ax, ay = p.ay, bx = p.bx, by = p.by;
    p.base_separation -= (bx - ax) * nx + (by - ay) * ny;
    const SolverReal rna = ax * ny - ay * nx, rnb = bx * ny - by * nx;
    const SolverReal kn = ma + mb + ia * rna * rna + ib * rnb * rnb;
    p.normal_mass = kn > 0 ? 1 / kn : 0;
    const SolverReal rta = ax * ty - ay * tx, rtb = bx * ty - by * tx;
    const SolverReal kt = ma + mb + ia * rta * rta + ib * rtb * rtb;
    p.tangent_mass = kt > 0 ? 1 / kt : 0;
  }
}

void restitution_one(SolverBody* bodies, ContactConstraint& c, SolverReal threshold) {
  if (c.restitution == 0) return;
  SolverBody& a = bodies[c.body_a];
  SolverBody& b = bodies[c.body_b];
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    // Only points that approached fast enough and actually pushed bounce.
    if (p.relative_velocity > -threshold || p.max_normal_impulse == 0) continue;
    const SolverReal dvx = (b.vx - b.w * p.by) - (a.vx - a.w * p.ay);
    const SolverReal dvy = (b.vy + b.w * p.bx) - (a.vy + a.w * p.ax);
    const SolverReal vn = dvx * c.nx + dvy * c.ny;
    SolverReal impulse = -p.normal_mass * (vn + c.restitution * p.relative_velocity);
    const SolverReal accumulated = smax(p.normal_impulse + impulse, SolverReal{0});
    impulse = accumulated - p.normal_impulse;
    p.normal_impulse = accumulated;
    p.max_normal_impulse = smax(p.max_normal_impulse, impulse);
    const SolverReal px = impulse * c.nx, py = impulse * c.ny;
    // A body the solver cannot move is left as it is (as the SIMD kernels leave it): a colour's
    // bounces run in parallel, and such a body may be in several of them.
    if (c.inv_mass_a != 0 || c.inv_inertia_a != 0) {
      a.vx -= c.inv_mass_a * px;
      a.vy -= c.inv_mass_a * py;
      a.w -= c.inv_inertia_a * (p.ax * py - p.ay * px);
    }
    if (c.inv_mass_b != 0 || c.inv_inertia_b != 0) {
      b.vx += c.inv_mass_b * px;
      b.vy += c.inv_mass_b * py;
      b.w += c.inv_inertia_b * (p.bx * py - p.by * px);
    }
  }
}

}  // namespace mink::detail
