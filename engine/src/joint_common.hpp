#pragma once

// What every joint kind's solver shares: the joint's bodies as the step sees them, the step's
// settings, and the small vector helpers the constraint rows are written with. Each kind lives
// in its own file (revolute_joint.cpp, ...) and implements the same set of functions on its
// own state struct; joint.cpp dispatches to them.

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>

#include "contact_solver.hpp"
#include "mink/engine/debug_draw.hpp"
#include "mink/engine/joint_def.hpp"
#include "mink/narrowphase/pose.hpp"

namespace mink::detail {

// One body of a joint as the rows read it every substep.
struct JointBody {
  std::int32_t solver = 0;  // index into the solver body array (the still body when not moving)
  Real inv_mass = 0, inv_inertia = 0;
};

// Where one body of a joint was at the start of the step, which only preparing reads (kept
// apart from JointBody so the rows' reads of a large net stay on few cache lines).
struct JointBodyStart {
  Vec2 center{0, 0};  // centre of mass, world
  Rotation rotation{};
  Vec2 local_center{0, 0};  // centre of mass in the body frame
};

// A joint's bodies and the anchors, fixed for the step by prepare (Box2D v3's joint frames):
// the current anchor offsets and separation are recovered each substep from the bodies'
// position and rotation change since the step began, without touching the body records.
struct JointFrame {
  std::array<JointBody, 4> bodies{};  // A, B; a gear also C and D (the A bodies of its joints)
  Vec2 anchor_a{0, 0};  // anchor on A from A's centre of mass, world-rotated at step start
  Vec2 anchor_b{0, 0};
  Vec2 delta_center{0, 0};  // B's centre minus A's, at step start
  Real h = 0, inv_h = 0;
  Softness soft;  // how rigid constraints push out their error (Box2D v3's joint softness)
  // Step start value of the joint's coordinate, for kinds whose position error needs more than
  // the anchors (a revolute's unwrapped angle, a gear's two joint coordinates).
  Real coordinate_a = 0, coordinate_b = 0;
  std::array<JointBodyStart, 4> starts{};  // the bodies' poses at step start, as `bodies`
};

// The joint's state at the end of a step: bodies as they are now (poses and velocities), for
// coordinates, speeds, drawing and end-of-step bookkeeping.
struct JointBodyState {
  Pose pose;
  Vec2 center{0, 0};
  Vec2 velocity{0, 0};
  Real angular_velocity = 0;
  // What the body turned in the step just solved, counting whole turns (0 when the solver did
  // not move it, and outside finishing a step).
  Real turned = 0;
  // The velocity of the body's material point now at world point `p`.
  Vec2 velocity_at(const Vec2& p) const {
    return velocity +
           Vec2(-angular_velocity * (p.y() - center.y()), angular_velocity * (p.x() - center.x()));
  }
};

// Force and torque a joint put on body B during the last step.
struct JointReaction {
  Vec2 force{0, 0};
  Real torque = 0;
};

inline Real cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
// w x r for a scalar angular velocity w.
inline Vec2 cross(Real w, const Vec2& r) {
  return {-w * r.y(), w * r.x()};
}
inline Vec2 left_perp(const Vec2& v) {
  return {-v.y(), v.x()};
}

inline Vec2 velocity_of(const SolverBody& b) {
  return {b.vx, b.vy};
}
inline Vec2 delta_position(const SolverBody& b) {
  return {b.dpx, b.dpy};
}
inline Rotation delta_rotation(const SolverBody& b) {
  return {b.qc, b.qs};
}
// These pass registers by value, always inlined into the wide kernels' clones (wide_body.hpp):
// the note GCC gives on their calling convention without AVX does not concern them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

// The few operations the rows in the solver's precision need that a number and a register of
// kWideLanes numbers (a GCC vector) spell differently, so one function of the number type runs
// on both and gives the same bits. Vector comparisons give lane masks, which `?:` selects by.
template <typename T>
__attribute__((always_inline)) inline T lane_abs(T x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::abs(x);
  } else {
    typedef std::int32_t Bits __attribute__((vector_size(sizeof(T))));
    Bits bits;
    __builtin_memcpy(&bits, &x, sizeof x);
    bits &= 0x7fffffff;
    __builtin_memcpy(&x, &bits, sizeof x);
    return x;
  }
}
// Whether the sign bit is set (-0 included), as a bool or a lane mask.
template <typename T>
__attribute__((always_inline)) inline auto lane_negative(T x) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::signbit(x);
  } else {
    typedef std::int32_t Bits __attribute__((vector_size(sizeof(T))));
    Bits bits;
    __builtin_memcpy(&bits, &x, sizeof x);
    return bits < 0;
  }
}
// x rounded to the nearest whole number, ties to even, for |x| < 2^22: the sum with 1.5 * 2^23
// keeps no fraction.
template <typename T>
__attribute__((always_inline)) inline T lane_round(T x) {
  constexpr SolverReal shift = 12582912.0f;
  return (x + shift) - shift;
}

// atan2(y, x) in the solver's precision, in [-pi, pi]: a polynomial in the ratio of the smaller
// coordinate to the larger (fitted here for relative error, at most 9e-8 before rounding), then
// the octant: within two ulps of the exact angle. The rows of a ragdoll's limits and springs take
// one every pass, where the C library's atan2f cost a tenth of rain's step; and a polynomial gives
// the same bits with every C library, which atan2f need not. `T`: SolverReal, or a register of
// them (the wide rows), selected lane by lane rather than branched.
template <typename T>
__attribute__((always_inline)) inline T lane_atan2(T y, T x) {
  const T zero{};
  const T ax = lane_abs(x), ay = lane_abs(y);
  const auto steep = ay > ax;
  const T larger = steep ? ay : ax, smaller = steep ? ax : ay;
  const T t = smaller / larger, s = t * t;
  T p = zero - 0.004780914322f;
  p = p * s + 0.02455874342f;
  p = p * s - 0.05990696222f;
  p = p * s + 0.09942913973f;
  p = p * s - 0.1402947468f;
  p = p * s + 0.1997138446f;
  p = p * s - 0.3333209411f;
  p = p * s + 0.9999999115f;
  T angle = t * p;
  angle = steep ? (zero + static_cast<SolverReal>(std::numbers::pi / 2)) - angle : angle;
  angle = x < zero ? (zero + static_cast<SolverReal>(std::numbers::pi)) - angle : angle;
  angle = lane_negative(y) ? zero - angle : angle;
  // The origin gives 0, and NaN stays NaN.
  return larger > zero ? angle : (larger == zero ? zero : x + y);
}
inline SolverReal solver_atan2(SolverReal y, SolverReal x) {
  return lane_atan2(y, x);
}

#pragma GCC diagnostic pop

// The body's rotation since the step began, as an angle counting whole turns: (qc, qs) gives
// it exactly up to whole turns, the summed substep angle tells how many. A substep may turn
// an eighth of a turn and more, so a fast body passes half a turn within one step, where the
// bare arc tangent would jump by a full turn (and a joint's error with it).
inline Real delta_angle(const SolverBody& b) {
  constexpr Real two_pi = 2 * std::numbers::pi;
  const Real exact = solver_atan2(b.qs, b.qc);
  // Turned less than a quarter turn (most bodies, every substep): the principal angle is the
  // turn, and counting whole turns (a division and a rounding) would add zero.
  if (std::abs(b.turn) <= Real{1.5}) return exact;
  return exact + two_pi * std::round((b.turn - exact) / two_pi);
}

// B's turn since the step began less A's, counting whole turns: delta_angle(b) -
// delta_angle(a), from one arc tangent of the relative rotation rather than two. The rows of
// a ragdoll's limits and springs ask for it every pass.
inline Real relative_turn(const SolverBody& a, const SolverBody& b) {
  constexpr Real two_pi = 2 * std::numbers::pi;
  const SolverReal c = a.qc * b.qc + a.qs * b.qs;  // cos and sin of B's angle less A's
  const SolverReal s = a.qc * b.qs - a.qs * b.qc;
  const Real exact = solver_atan2(s, c);
  const Real turned = Real{b.turn} - Real{a.turn};
  // Less than a quarter turn apart, as the principal angle tells (see delta_angle).
  if (std::abs(turned) <= Real{1.5}) return exact;
  return exact + two_pi * std::round((turned - exact) / two_pi);
}

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

// relative_turn() in the solver's precision throughout, for a SolverBody or kWideLanes of them
// a field per register (the wide revolute rows): the whole turns from a rounding that gives
// zero where they turned less than a quarter turn apart, so no lane needs a branch.
template <typename Body>
__attribute__((always_inline)) inline auto solver_relative_turn(const Body& a, const Body& b) {
  using T = decltype(Body::qc);
  constexpr SolverReal two_pi = 2 * std::numbers::pi, inv_two_pi = 1 / (2 * std::numbers::pi);
  const T zero{};
  const T c = a.qc * b.qc + a.qs * b.qs;
  const T s = a.qc * b.qs - a.qs * b.qc;
  const T exact = lane_atan2(s, c);
  const T turned = b.turn - a.turn;
  const T whole = lane_round((turned - exact) * inv_two_pi);
  return lane_abs(turned) <= zero + SolverReal{1.5} ? exact : exact + two_pi * whole;
}

#pragma GCC diagnostic pop

// Applies impulse `p` at offset `r` (and angular impulse `l`) to B and the opposite to A.
// `Frame`: a JointFrame, or a row's frame (joint_rows.hpp), which holds the same fields.
template <typename Frame>
inline void apply_pair(SolverBody& a, SolverBody& b, const Frame& f, const Vec2& ra, const Vec2& rb,
                       const Vec2& p, Real l) {
  const JointBody& ja = f.bodies[0];
  const JointBody& jb = f.bodies[1];
  a.vx -= ja.inv_mass * p.x();
  a.vy -= ja.inv_mass * p.y();
  a.w -= ja.inv_inertia * (cross(ra, p) + l);
  b.vx += jb.inv_mass * p.x();
  b.vy += jb.inv_mass * p.y();
  b.w += jb.inv_inertia * (cross(rb, p) + l);
}

// An angle in (-pi, pi].
inline Real wrap_angle(Real a) {
  constexpr Real two_pi = 2 * std::numbers::pi;
  // Most angles are already in range (a joint turns little in a step), where the remainder
  // would return them unchanged.
  if (a > -std::numbers::pi && a <= std::numbers::pi) return a;
  a = std::remainder(a, two_pi);
  return a <= -std::numbers::pi ? a + two_pi : a;
}

// B's rotation relative to A as an angle in (-pi, pi].
inline Real relative_angle(const Rotation& a, const Rotation& b) {
  return std::atan2(a.cos * b.sin - a.sin * b.cos, a.cos * b.cos + a.sin * b.sin);
}

// Joint colours for drawing.
inline constexpr Color kJointColor{0.5f, 0.8f, 0.8f, 1.0f};
inline constexpr Color kJointAxisColor{0.9f, 0.6f, 0.2f, 1.0f};
inline constexpr Color kJointLimitColor{0.9f, 0.3f, 0.3f, 1.0f};

// A slider's translation (prismatic and wheel joints): B's anchor's offset from A's along
// A's axis; and its rate, which includes the axis turning with A.
inline Real slider_translation(const JointBodyState& a, const JointBodyState& b,
                               const Vec2& local_anchor_a, const Vec2& local_anchor_b,
                               const Vec2& local_axis_a) {
  const Vec2 d = b.pose.apply(local_anchor_b) - a.pose.apply(local_anchor_a);
  return a.pose.rotation.apply(local_axis_a).dot(d);
}
inline Real slider_speed(const JointBodyState& a, const JointBodyState& b,
                         const Vec2& local_anchor_a, const Vec2& local_anchor_b,
                         const Vec2& local_axis_a) {
  const Vec2 pa = a.pose.apply(local_anchor_a), pb = b.pose.apply(local_anchor_b);
  const Vec2 axis = a.pose.rotation.apply(local_axis_a);
  return (pb - pa).dot(cross(a.angular_velocity, axis)) +
         axis.dot(b.velocity_at(pb) - a.velocity_at(pa));
}

// Each body's anchor, tied to its centre of mass (the drawing every anchored kind starts from).
inline void draw_anchors(DebugDraw& draw, const JointBodyState& a, const JointBodyState& b,
                         const Vec2& pa, const Vec2& pb) {
  draw.draw_segment(a.center, pa, kJointColor);
  draw.draw_segment(b.center, pb, kJointColor);
  draw.draw_point(pa, 5, kJointColor);
  draw.draw_point(pb, 5, kJointColor);
}

// A slider's axis through A's anchor `pa` (prismatic and wheel joints): the travel between
// the limits with a tick at each, or a metre either side when it is unbounded.
inline void draw_axis(DebugDraw& draw, const Vec2& pa, const Vec2& axis, const JointLimit& limit) {
  if (!limit.enabled) {
    draw.draw_segment(pa - axis, pa + axis, kJointAxisColor);
    return;
  }
  const Vec2 tick = 0.1 * left_perp(axis);
  const Vec2 lower = pa + limit.lower * axis, upper = pa + limit.upper * axis;
  draw.draw_segment(lower, upper, kJointAxisColor);
  draw.draw_segment(lower - tick, lower + tick, kJointLimitColor);
  draw.draw_segment(upper - tick, upper + tick, kJointLimitColor);
}

}  // namespace mink::detail
