// The joint rows: see joint_rows.hpp.

#include "joint_rows.hpp"

#include <algorithm>

namespace mink::detail {

namespace {

// Bias and softness of a rigid row with position error `error`.
template <typename Frame>
Softness rigid_row(const Frame& frame, Real error, bool use_bias, Real& bias) {
  if (!use_bias) {
    bias = 0;
    return {0, 1, 0};
  }
  bias = frame.soft.bias_rate * error;
  return frame.soft;
}

// A one-sided row (a limit): speculative while apart (error > 0), rigid once reached.
template <typename Frame>
Softness limit_row(const Frame& frame, Real error, bool use_bias, Real& bias) {
  if (error > 0) {
    bias = error * frame.inv_h;
    return {0, 1, 0};
  }
  return rigid_row(frame, error, use_bias, bias);
}

template <typename Frame>
void apply_angular(SolverBody& a, SolverBody& b, const Frame& frame, Real impulse) {
  a.w -= frame.bodies[0].inv_inertia * impulse;
  b.w += frame.bodies[1].inv_inertia * impulse;
}

}  // namespace

void set_anchors(JointFrame& frame, const Vec2& local_anchor_a, const Vec2& local_anchor_b) {
  const JointBodyStart& a = frame.starts[0];
  const JointBodyStart& b = frame.starts[1];
  frame.anchor_a = a.rotation.apply(local_anchor_a - a.local_center);
  frame.anchor_b = b.rotation.apply(local_anchor_b - b.local_center);
  frame.delta_center = b.center - a.center;
}

template <typename Frame>
PinRow pin_row(const Frame& frame, const Vec2& impulse) {
  const auto f = [](Real x) { return static_cast<SolverReal>(x); };
  return {frame.bodies[0].solver,
          frame.bodies[1].solver,
          f(frame.bodies[0].inv_mass),
          f(frame.bodies[0].inv_inertia),
          f(frame.bodies[1].inv_mass),
          f(frame.bodies[1].inv_inertia),
          f(frame.anchor_a.x()),
          f(frame.anchor_a.y()),
          f(frame.anchor_b.x()),
          f(frame.anchor_b.y()),
          f(frame.delta_center.x()),
          f(frame.delta_center.y()),
          f(frame.soft.bias_rate),
          f(frame.soft.mass_scale),
          f(frame.soft.impulse_scale),
          f(impulse.x()),
          f(impulse.y())};
}

template <typename Frame>
void warm_start_point(SolverBody* bodies, const Frame& frame, const Vec2& linear, Real angular) {
  warm_start_pin(bodies, pin_row(frame, linear), static_cast<SolverReal>(angular));
}

template <typename Frame>
CurrentAnchors current_anchors(const Frame& frame, const SolverBody& a, const SolverBody& b) {
  CurrentAnchors c;
  c.ra = delta_rotation(a).apply(frame.anchor_a);
  c.rb = delta_rotation(b).apply(frame.anchor_b);
  c.separation = (delta_position(b) - delta_position(a)) + frame.delta_center + (c.rb - c.ra);
  return c;
}

namespace {

// B's anchor's velocity relative to A's.
Vec2 point_velocity(const CurrentAnchors& c, const SolverBody& a, const SolverBody& b) {
  return (velocity_of(b) + cross(b.w, c.rb)) - (velocity_of(a) + cross(a.w, c.ra));
}

// The impulse that changes the anchors' relative velocity by `dv`: K^-1 dv, with K the point
// row's 2x2 effective mass matrix at the current anchors.
template <typename Frame>
Vec2 point_impulse(const Frame& frame, const CurrentAnchors& c, const Vec2& dv) {
  const Real ma = frame.bodies[0].inv_mass, mb = frame.bodies[1].inv_mass;
  const Real ia = frame.bodies[0].inv_inertia, ib = frame.bodies[1].inv_inertia;
  const Real k11 = ma + mb + c.ra.y() * c.ra.y() * ia + c.rb.y() * c.rb.y() * ib;
  const Real k12 = -c.ra.y() * c.ra.x() * ia - c.rb.y() * c.rb.x() * ib;
  const Real k22 = ma + mb + c.ra.x() * c.ra.x() * ia + c.rb.x() * c.rb.x() * ib;
  Real det = k11 * k22 - k12 * k12;
  if (det != 0) det = 1 / det;
  return {det * (k22 * dv.x() - k12 * dv.y()), det * (k11 * dv.y() - k12 * dv.x())};
}

}  // namespace

template <typename Frame>
void solve_point(SolverBody& a, SolverBody& b, const Frame& frame, bool use_bias, Vec2& impulse) {
  PinRow row = pin_row(frame, impulse);
  pin_solve(a, b, row, use_bias);
  impulse = Vec2(row.impulse_x, row.impulse_y);
}

template CurrentAnchors current_anchors(const JointFrame&, const SolverBody&, const SolverBody&);
template void warm_start_point(SolverBody*, const JointFrame&, const Vec2&, Real);
template PinRow pin_row(const JointFrame&, const Vec2&);
template void solve_point(SolverBody&, SolverBody&, const JointFrame&, bool, Vec2&);

void solve_point_spring(SolverBody& a, SolverBody& b, const JointFrame& frame,
                        const Softness& spring, Vec2& impulse) {
  const CurrentAnchors c = current_anchors(frame, a, b);
  const Vec2 rhs = point_velocity(c, a, b) + spring.bias_rate * c.separation;
  const Vec2 p = -spring.mass_scale * point_impulse(frame, c, rhs) - spring.impulse_scale * impulse;
  impulse += p;
  apply_pair(a, b, frame, c.ra, c.rb, p, 0);
}

void solve_point_motor(SolverBody& a, SolverBody& b, const JointFrame& frame, const Vec2& velocity,
                       Real max_force, Vec2& impulse) {
  const CurrentAnchors c = current_anchors(frame, a, b);
  const Vec2 old = impulse;
  impulse -= point_impulse(frame, c, point_velocity(c, a, b) - velocity);
  // Bounded as a vector, so the force keeps its direction when it saturates.
  const Real max_impulse = frame.h * max_force;
  const Real length = impulse.norm();
  if (length > max_impulse) impulse *= max_impulse / length;
  apply_pair(a, b, frame, c.ra, c.rb, impulse - old, 0);
}

void solve_angle(SolverBody& a, SolverBody& b, const JointFrame& frame, Real axial_mass, Real error,
                 bool use_bias, Real& impulse) {
  Real bias = 0;
  const Softness s = rigid_row(frame, error, use_bias, bias);
  const Real cdot = b.w - a.w;
  const Real p = -s.mass_scale * axial_mass * (cdot + bias) - s.impulse_scale * impulse;
  impulse += p;
  apply_angular(a, b, frame, p);
}

template <typename Frame>
void solve_angular_spring(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                          const Softness& spring, Real error, Real& impulse) {
  const Real cdot = b.w - a.w;
  const Real bias = spring.bias_rate * error;
  const Real p = -spring.mass_scale * axial_mass * (cdot + bias) - spring.impulse_scale * impulse;
  impulse += p;
  apply_angular(a, b, frame, p);
}

template <typename Frame>
void solve_angular_motor(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                         const JointMotor& motor, Real& impulse) {
  const Real cdot = b.w - a.w - motor.speed;
  const Real max_impulse = frame.h * motor.max_force;
  const Real old = impulse;
  impulse = std::clamp(old - axial_mass * cdot, -max_impulse, max_impulse);
  apply_angular(a, b, frame, impulse - old);
}

template <typename Frame>
void solve_angular_limits(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                          Real angle, const JointLimit& limit, bool use_bias, Real& lower_impulse,
                          Real& upper_impulse) {
  {
    Real bias = 0;
    const Softness s = limit_row(frame, angle - limit.lower, use_bias, bias);
    const Real cdot = b.w - a.w;
    const Real p = -s.mass_scale * axial_mass * (cdot + bias) - s.impulse_scale * lower_impulse;
    const Real total = std::max<Real>(lower_impulse + p, 0);
    apply_angular(a, b, frame, total - lower_impulse);
    lower_impulse = total;
  }
  {
    Real bias = 0;
    const Softness s = limit_row(frame, limit.upper - angle, use_bias, bias);
    const Real cdot = a.w - b.w;
    const Real p = -s.mass_scale * axial_mass * (cdot + bias) - s.impulse_scale * upper_impulse;
    const Real total = std::max<Real>(upper_impulse + p, 0);
    apply_angular(a, b, frame, -(total - upper_impulse));
    upper_impulse = total;
  }
}

template void solve_angular_spring(SolverBody&, SolverBody&, const JointFrame&, Real,
                                   const Softness&, Real, Real&);
template void solve_angular_motor(SolverBody&, SolverBody&, const JointFrame&, Real,
                                  const JointMotor&, Real&);
template void solve_angular_limits(SolverBody&, SolverBody&, const JointFrame&, Real, Real,
                                   const JointLimit&, bool, Real&, Real&);

AxialRow make_axial_row(const JointFrame& frame, const CurrentAnchors& anchors, const Vec2& axis) {
  AxialRow row;
  row.axis = axis;
  row.a1 = cross(anchors.separation + anchors.ra, axis);
  row.a2 = cross(anchors.rb, axis);
  const Real k = frame.bodies[0].inv_mass + frame.bodies[1].inv_mass +
                 frame.bodies[0].inv_inertia * row.a1 * row.a1 +
                 frame.bodies[1].inv_inertia * row.a2 * row.a2;
  row.mass = k > 0 ? 1 / k : 0;
  return row;
}

Real axial_velocity(const AxialRow& row, const SolverBody& a, const SolverBody& b) {
  return row.axis.dot(velocity_of(b) - velocity_of(a)) + row.a2 * b.w - row.a1 * a.w;
}

void apply_axial(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                 Real impulse) {
  const JointBody& ja = frame.bodies[0];
  const JointBody& jb = frame.bodies[1];
  const Vec2 p = impulse * row.axis;
  a.vx -= ja.inv_mass * p.x();
  a.vy -= ja.inv_mass * p.y();
  a.w -= ja.inv_inertia * impulse * row.a1;
  b.vx += jb.inv_mass * p.x();
  b.vy += jb.inv_mass * p.y();
  b.w += jb.inv_inertia * impulse * row.a2;
}

void solve_axial(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                 Real error, bool use_bias, Real& impulse) {
  Real bias = 0;
  const Softness s = rigid_row(frame, error, use_bias, bias);
  const Real cdot = axial_velocity(row, a, b);
  const Real p = -s.mass_scale * row.mass * (cdot + bias) - s.impulse_scale * impulse;
  impulse += p;
  apply_axial(row, frame, a, b, p);
}

void solve_axial_spring(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                        const Softness& spring, Real error, Real& impulse) {
  const Real cdot = axial_velocity(row, a, b);
  const Real bias = spring.bias_rate * error;
  const Real p = -spring.mass_scale * row.mass * (cdot + bias) - spring.impulse_scale * impulse;
  impulse += p;
  apply_axial(row, frame, a, b, p);
}

void solve_axial_motor(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                       const JointMotor& motor, Real& impulse) {
  const Real cdot = axial_velocity(row, a, b) - motor.speed;
  const Real max_impulse = frame.h * motor.max_force;
  const Real old = impulse;
  impulse = std::clamp(old - row.mass * cdot, -max_impulse, max_impulse);
  apply_axial(row, frame, a, b, impulse - old);
}

void solve_axial_limits(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                        Real translation, const JointLimit& limit, bool use_bias,
                        Real& lower_impulse, Real& upper_impulse) {
  {
    Real bias = 0;
    const Softness s = limit_row(frame, translation - limit.lower, use_bias, bias);
    const Real cdot = axial_velocity(row, a, b);
    const Real p = -s.mass_scale * row.mass * (cdot + bias) - s.impulse_scale * lower_impulse;
    const Real total = std::max<Real>(lower_impulse + p, 0);
    apply_axial(row, frame, a, b, total - lower_impulse);
    lower_impulse = total;
  }
  {
    Real bias = 0;
    const Softness s = limit_row(frame, limit.upper - translation, use_bias, bias);
    const Real cdot = -axial_velocity(row, a, b);
    const Real p = -s.mass_scale * row.mass * (cdot + bias) - s.impulse_scale * upper_impulse;
    const Real total = std::max<Real>(upper_impulse + p, 0);
    apply_axial(row, frame, a, b, -(total - upper_impulse));
    upper_impulse = total;
  }
}

SliderRows make_slider_rows(const JointFrame& frame, const SolverBody& a, const SolverBody& b,
                            const Vec2& axis) {
  SliderRows s;
  s.anchors = current_anchors(frame, a, b);
  s.axis = delta_rotation(a).apply(axis);
  s.translation = s.axis.dot(s.anchors.separation);
  s.along = make_axial_row(frame, s.anchors, s.axis);
  s.across = make_axial_row(frame, s.anchors, left_perp(s.axis));
  return s;
}

}  // namespace mink::detail
