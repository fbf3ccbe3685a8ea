#pragma once

// The constraint rows joints are built from, each solved in the soft step's form: a rigid row
// pushes its position error out through the joint softness in the biased pass only; a spring
// row is soft with its own frequency; a motor row drives a speed with a bounded impulse; a
// limit row is speculative while the limit is not reached (it lets the coordinate arrive at
// the bound in one substep and no further) and rigid once it is. Angular rows act on the
// relative angle; axial rows on a translation along a world axis.

#include "joint_common.hpp"
#include "pin_rows.hpp"

namespace mink::detail {

// A spring, motor or limit switched off since the last step must not be warm started: the
// kinds that have them call this in prepare. (A distance joint's spring shares its impulse
// with the rigid row, which goes on acting.)
template <typename Kind>
void drop_switched_off(Kind& joint) {
  if constexpr (requires { joint.spring_impulse; }) {
    if (!joint.def.spring.enabled) joint.spring_impulse = 0;
  }
  if (!joint.def.motor.enabled) joint.motor_impulse = 0;
  if (!joint.def.limit.enabled) joint.lower_impulse = joint.upper_impulse = 0;
}

// Sets the frame's anchors (from each centre of mass, world-rotated) from body-local anchors.
void set_anchors(JointFrame& frame, const Vec2& local_anchor_a, const Vec2& local_anchor_b);

// The anchors now: their offsets from the centres of mass, and B's anchor minus A's.
struct CurrentAnchors {
  Vec2 ra{0, 0}, rb{0, 0}, separation{0, 0};
};
// `Frame`, here and below: a JointFrame, or what holds the fields of one that the function
// reads.
template <typename Frame>
CurrentAnchors current_anchors(const Frame& frame, const SolverBody& a, const SolverBody& b);

// Warm starts a point-and-angle joint (revolute, weld, motor joint): `linear` at the anchors
// as they are now, `angular` on the relative angle.
template <typename Frame>
void warm_start_point(SolverBody* bodies, const Frame& frame, const Vec2& linear, Real angular);

// The point row in the solver's precision (pin_rows.hpp), with impulse `impulse`.
template <typename Frame>
PinRow pin_row(const Frame& frame, const Vec2& impulse);

// B's anchor held on A's: a 2x2 block row, in the solver's precision (pin_rows.hpp).
// `impulse` accumulates.
template <typename Frame>
void solve_point(SolverBody& a, SolverBody& b, const Frame& frame, bool use_bias, Vec2& impulse);

// B's anchor held on A's by a spring (weld springs): soft with `spring` in both passes, as a
// spring is a force and not an error to push out.
void solve_point_spring(SolverBody& a, SolverBody& b, const JointFrame& frame,
                        const Softness& spring, Vec2& impulse);
// B's anchor driven to `velocity` relative to A's with an accumulated impulse no longer than
// frame.h * max_force (a two-dimensional motor).
void solve_point_motor(SolverBody& a, SolverBody& b, const JointFrame& frame, const Vec2& velocity,
                       Real max_force, Vec2& impulse);

// Rows on the relative angle (B minus A); `axial_mass` is 1 / (iA + iB).
void solve_angle(SolverBody& a, SolverBody& b, const JointFrame& frame, Real axial_mass, Real error,
                 bool use_bias, Real& impulse);
template <typename Frame>
void solve_angular_spring(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                          const Softness& spring, Real error, Real& impulse);
template <typename Frame>
void solve_angular_motor(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                         const JointMotor& motor, Real& impulse);
template <typename Frame>
void solve_angular_limits(SolverBody& a, SolverBody& b, const Frame& frame, Real axial_mass,
                          Real angle, const JointLimit& limit, bool use_bias, Real& lower_impulse,
                          Real& upper_impulse);

// A translation row along a world axis: impulse p moves B along +axis and A against it, with
// lever arms a1 (A's, from its centre to B's anchor) and a2 (B's).
struct AxialRow {
  Vec2 axis{1, 0};
  Real a1 = 0, a2 = 0;
  Real mass = 0;  // 1 / effective mass along the row, 0 when nothing can move
};
AxialRow make_axial_row(const JointFrame& frame, const CurrentAnchors& anchors, const Vec2& axis);
Real axial_velocity(const AxialRow& row, const SolverBody& a, const SolverBody& b);
void apply_axial(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                 Real impulse);
void solve_axial(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                 Real error, bool use_bias, Real& impulse);
void solve_axial_spring(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                        const Softness& spring, Real error, Real& impulse);
void solve_axial_motor(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                       const JointMotor& motor, Real& impulse);
void solve_axial_limits(const AxialRow& row, const JointFrame& frame, SolverBody& a, SolverBody& b,
                        Real translation, const JointLimit& limit, bool use_bias,
                        Real& lower_impulse, Real& upper_impulse);

// A slider's rows in the current substep (prismatic and wheel joints): `axis` is the world
// axis at step start, turned here with A since; the rows act along it and across it.
struct SliderRows {
  CurrentAnchors anchors;
  Vec2 axis{1, 0};
  Real translation = 0;  // B's anchor's offset from A's along the axis
  AxialRow along, across;
};
SliderRows make_slider_rows(const JointFrame& frame, const SolverBody& a, const SolverBody& b,
                            const Vec2& axis);

}  // namespace mink::detail
