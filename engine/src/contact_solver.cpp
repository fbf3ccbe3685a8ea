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
// Substeps give most of the benefit of smaller time steps (stiffness, stacking) at the price
// of one iteration each, and the contact separation is updated each substep from the bodies'
// position change without recomputing manifolds. Contacts with a body that does not move get
// twice the stiffness (nothing on the other side to fight). Positive separations
// (speculative points) use bias = s / h, which lets a body close the gap exactly in one
// substep and no further: fast bodies stop at thin ones instead of tunnelling.
//
// Settings (WorldDef): 5 substeps and 60 Hz where Box2D v3 uses 4 and 30 Hz. A soft contact
// under load sags by load / (effective mass * omega^2); at 30 Hz the bottom of the 100-row
// pyramid compresses so much that the top sinks about a metre, at 60 Hz about 0.2 m. 60 Hz
// with 4 substeps makes the pyramid sway (the spring is too stiff for the substep); 5 is
// the fewest that stays steady.
//
// Speed: Gauss-Seidel is a chain of dependent updates, so one constraint at a time the CPU
// mostly waits on latency. As in Box2D v3, the constraint graph is coloured so that no two
// constraints of a colour share a moving body; a colour is then solved four constraints at a
// time in SIMD lanes (GCC vector extensions, compiled for AVX2 and for baseline x86-64 and
// picked at load time). No fused multiply-add is used, so both builds and the one-at-a-time
// twin give bitwise equal results. Bodies and constraints are flat arrays of doubles, no
// virtual calls, no allocation once the scratch arrays have grown.

#include "contact_solver.hpp"

// The wide helpers pass vectors by value between internal functions only; the ABI note GCC
// gives for AVX-sized vectors without AVX enabled does not concern them.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace mink::detail {

Softness make_softness(Real hertz, Real damping_ratio, Real h) {
  if (hertz == 0) return {0, 1, 0};
  const Real omega = 2 * std::numbers::pi * hertz;
  const Real a1 = 2 * damping_ratio + h * omega;
  const Real a2 = h * omega * a1;
  const Real a3 = 1 / (1 + a2);
  return {omega / a1, a2 * a3, a3};
}

// Explicitly 32-byte aligned: without AVX enabled GCC would align it to 16 only, and the AVX2
// build of the kernels uses aligned loads.
typedef double Wide __attribute__((vector_size(32), aligned(32)));

struct WideConstraint {
  std::int32_t body_a[4], body_b[4];
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

namespace {

// ---- one constraint at a time ----

// Written exactly as the wide path's lane-wise selects, so both give the same bits (even the
// sign of a zero).
inline Real smax(Real a, Real b) {
  return a > b ? a : b;
}
inline Real smin(Real a, Real b) {
  return a < b ? a : b;
}

void integrate_velocities(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
                          const SolverSettings& settings) {
  const Real max_speed_squared = settings.max_linear_speed * settings.max_linear_speed;
  // A body may turn at most an eighth of a turn per substep: beyond that the rotation
  // integration below is meaningless.
  const Real max_angular_speed = 0.25 * std::numbers::pi * settings.inv_h;
  const std::size_t count = bodies.size();
  for (std::size_t i = 0; i < count; ++i) {
    SolverBody& body = bodies[i];
    const SolverBodyParams& p = params[i];
    Real vx = body.vx * p.linear_damping + p.dvx;
    Real vy = body.vy * p.linear_damping + p.dvy;
    Real w = body.w * p.angular_damping + p.dw;
    const Real speed_squared = vx * vx + vy * vy;
    if (speed_squared > max_speed_squared) {
      const Real ratio = settings.max_linear_speed / std::sqrt(speed_squared);
      vx *= ratio;
      vy *= ratio;
    }
    w = std::clamp(w, -max_angular_speed, max_angular_speed);
    body.vx = vx;
    body.vy = vy;
    body.w = w;
  }
}

void integrate_positions(std::span<SolverBody> bodies, Real h) {
  for (SolverBody& body : bodies) {
    body.dpx += h * body.vx;
    body.dpy += h * body.vy;
    // q += h * w * perp(q), renormalised: exact direction, a cheap stand-in for sin/cos.
    const Real hw = h * body.w;
    const Real qc = body.qc - hw * body.qs;
    const Real qs = body.qs + hw * body.qc;
    const Real inv_length = 1 / std::sqrt(qc * qc + qs * qs);
    body.qc = qc * inv_length;
    body.qs = qs * inv_length;
  }
}

void warm_start_one(SolverBody* bodies, ContactConstraint& c) {
  SolverBody& a = bodies[c.body_a];
  SolverBody& b = bodies[c.body_b];
  const Real tx = c.ny, ty = -c.nx;
  Real vax = a.vx, vay = a.vy, wa = a.w, vbx = b.vx, vby = b.vy, wb = b.w;
  for (int j = 0; j < 2; ++j) {
    const ContactConstraintPoint& p = c.points[j];
    const Real px = p.normal_impulse * c.nx + p.tangent_impulse * tx;
    const Real py = p.normal_impulse * c.ny + p.tangent_impulse * ty;
    wa -= c.inv_inertia_a * (p.ax * py - p.ay * px);
    vax -= c.inv_mass_a * px;
    vay -= c.inv_mass_a * py;
    wb += c.inv_inertia_b * (p.bx * py - p.by * px);
    vbx += c.inv_mass_b * px;
    vby += c.inv_mass_b * py;
  }
  a.vx = vax, a.vy = vay, a.w = wa;
  b.vx = vbx, b.vy = vby, b.w = wb;
}

// Both points are always processed: a one-point manifold's second point has zero masses and
// impulses, so it changes nothing, and the lanes of the wide path stay uniform.
void solve_one(SolverBody* bodies, ContactConstraint& c, Real inv_h, Real max_push, bool use_bias) {
  SolverBody& a = bodies[c.body_a];
  SolverBody& b = bodies[c.body_b];
  const Real ma = c.inv_mass_a, ia = c.inv_inertia_a, mb = c.inv_mass_b, ib = c.inv_inertia_b;
  Real vax = a.vx, vay = a.vy, wa = a.w, vbx = b.vx, vby = b.vy, wb = b.w;
  const Real dpx = b.dpx - a.dpx, dpy = b.dpy - a.dpy;
  const Real nx = c.nx, ny = c.ny;
  const auto apply = [&](const ContactConstraintPoint& p, Real px, Real py) {
    vax -= ma * px;
    vay -= ma * py;
    wa -= ia * (p.ax * py - p.ay * px);
    vbx += mb * px;
    vby += mb * py;
    wb += ib * (p.bx * py - p.by * px);
  };
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    // Separation now: anchors moved with their bodies since the step began.
    const Real prax = a.qc * p.ax - a.qs * p.ay, pray = a.qs * p.ax + a.qc * p.ay;
    const Real prbx = b.qc * p.bx - b.qs * p.by, prby = b.qs * p.bx + b.qc * p.by;
    const Real s = (dpx + prbx - prax) * nx + (dpy + prby - pray) * ny + p.base_separation;
    Real bias = 0, mass_scale = 1, impulse_scale = 0;
    if (s > 0) {
      bias = s * inv_h;  // speculative: close the gap in this substep, no more
    } else if (use_bias) {
      bias = smax(c.bias_rate * s, -max_push);
      mass_scale = c.mass_scale;
      impulse_scale = c.impulse_scale;
    }
    const Real dvx = (vbx - wb * p.by) - (vax - wa * p.ay);
    const Real dvy = (vby + wb * p.bx) - (vay + wa * p.ax);
    const Real vn = dvx * nx + dvy * ny;
    Real impulse = -p.normal_mass * mass_scale * (vn + bias) - impulse_scale * p.normal_impulse;
    const Real accumulated = smax(p.normal_impulse + impulse, Real{0});
    impulse = accumulated - p.normal_impulse;
    p.normal_impulse = accumulated;
    p.max_normal_impulse = smax(p.max_normal_impulse, impulse);
    apply(p, impulse * nx, impulse * ny);
  }
  const Real tx = ny, ty = -nx;
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    const Real dvx = (vbx - wb * p.by) - (vax - wa * p.ay);
    const Real dvy = (vby + wb * p.bx) - (vay + wa * p.ax);
    const Real vt = dvx * tx + dvy * ty;
    const Real limit = c.friction * p.normal_impulse;
    const Real accumulated = smin(smax(p.tangent_impulse - p.tangent_mass * vt, -limit), limit);
    const Real impulse = accumulated - p.tangent_impulse;
    p.tangent_impulse = accumulated;
    apply(p, impulse * tx, impulse * ty);
  }
  a.vx = vax, a.vy = vay, a.w = wa;
  b.vx = vbx, b.vy = vby, b.w = wb;
}

void restitution_one(SolverBody* bodies, ContactConstraint& c, Real threshold) {
  if (c.restitution == 0) return;
  SolverBody& a = bodies[c.body_a];
  SolverBody& b = bodies[c.body_b];
  for (int j = 0; j < 2; ++j) {
    ContactConstraintPoint& p = c.points[j];
    // Only points that approached fast enough and actually pushed bounce.
    if (p.relative_velocity > -threshold || p.max_normal_impulse == 0) continue;
    const Real dvx = (b.vx - b.w * p.by) - (a.vx - a.w * p.ay);
    const Real dvy = (b.vy + b.w * p.bx) - (a.vy + a.w * p.ax);
    const Real vn = dvx * c.nx + dvy * c.ny;
    Real impulse = -p.normal_mass * (vn + c.restitution * p.relative_velocity);
    const Real accumulated = smax(p.normal_impulse + impulse, Real{0});
    impulse = accumulated - p.normal_impulse;
    p.normal_impulse = accumulated;
    p.max_normal_impulse = smax(p.max_normal_impulse, impulse);
    const Real px = impulse * c.nx, py = impulse * c.ny;
    a.vx -= c.inv_mass_a * px;
    a.vy -= c.inv_mass_a * py;
    a.w -= c.inv_inertia_a * (p.ax * py - p.ay * px);
    b.vx += c.inv_mass_b * px;
    b.vy += c.inv_mass_b * py;
    b.w += c.inv_inertia_b * (p.bx * py - p.by * px);
  }
}

// ---- four constraints at a time ----

struct WideBody {
  Wide vx, vy, w, dpx, dpy, qc, qs;
};

inline Wide splat(Real x) {
  return Wide{x, x, x, x};
}
inline Wide wmax(Wide a, Wide b) {
  return a > b ? a : b;
}
inline Wide wmin(Wide a, Wide b) {
  return a < b ? a : b;
}

inline WideBody gather(const SolverBody* bodies, const std::int32_t* index) {
  const SolverBody& b0 = bodies[index[0]];
  const SolverBody& b1 = bodies[index[1]];
  const SolverBody& b2 = bodies[index[2]];
  const SolverBody& b3 = bodies[index[3]];
  return {Wide{b0.vx, b1.vx, b2.vx, b3.vx},     Wide{b0.vy, b1.vy, b2.vy, b3.vy},
          Wide{b0.w, b1.w, b2.w, b3.w},         Wide{b0.dpx, b1.dpx, b2.dpx, b3.dpx},
          Wide{b0.dpy, b1.dpy, b2.dpy, b3.dpy}, Wide{b0.qc, b1.qc, b2.qc, b3.qc},
          Wide{b0.qs, b1.qs, b2.qs, b3.qs}};
}

// Only velocities change while solving. Lanes sharing the still body write back the same
// zeros it holds (its masses are zero), so the order of those writes does not matter.
inline void scatter(SolverBody* bodies, const std::int32_t* index, const WideBody& w) {
  for (int lane = 0; lane < 4; ++lane) {
    SolverBody& b = bodies[index[lane]];
    b.vx = w.vx[lane];
    b.vy = w.vy[lane];
    b.w = w.w[lane];
  }
}

__attribute__((target_clones("avx2", "default"))) void warm_start_wide(SolverBody* bodies,
                                                                       WideConstraint* begin,
                                                                       WideConstraint* end) {
  for (WideConstraint* c = begin; c != end; ++c) {
    WideBody a = gather(bodies, c->body_a);
    WideBody b = gather(bodies, c->body_b);
    const Wide tx = c->ny, ty = -c->nx;
    for (int j = 0; j < 2; ++j) {
      const WideConstraint::Point& p = c->points[j];
      const Wide bx = p.ax + c->dx, by = p.ay + c->dy;
      const Wide px = p.normal_impulse * c->nx + p.tangent_impulse * tx;
      const Wide py = p.normal_impulse * c->ny + p.tangent_impulse * ty;
      a.w -= c->inv_inertia_a * (p.ax * py - p.ay * px);
      a.vx -= c->inv_mass_a * px;
      a.vy -= c->inv_mass_a * py;
      b.w += c->inv_inertia_b * (bx * py - by * px);
      b.vx += c->inv_mass_b * px;
      b.vy += c->inv_mass_b * py;
    }
    scatter(bodies, c->body_a, a);
    scatter(bodies, c->body_b, b);
  }
}

// `Track` keeps each point's largest single impulse of the step for restitution; scenes
// without restitution skip that store.
template <bool Track>
__attribute__((always_inline)) inline void solve_wide_impl(
    SolverBody* bodies, WideConstraint* begin, WideConstraint* end, WideMaxImpulse* max_impulse,
    Real inv_h_scalar, Real max_push_scalar, bool use_bias) {
  const Wide zero = splat(0), one = splat(1), inv_h = splat(inv_h_scalar),
             max_push = splat(-max_push_scalar);
  for (WideConstraint* c = begin; c != end; ++c) {
    WideBody a = gather(bodies, c->body_a);
    WideBody b = gather(bodies, c->body_b);
    const Wide ma = c->inv_mass_a, ia = c->inv_inertia_a, mb = c->inv_mass_b, ib = c->inv_inertia_b;
    const Wide dpx = b.dpx - a.dpx, dpy = b.dpy - a.dpy;
    const Wide nx = c->nx, ny = c->ny;
    const auto apply = [&](const WideConstraint::Point& p, Wide bx, Wide by, Wide px, Wide py) {
      a.vx -= ma * px;
      a.vy -= ma * py;
      a.w -= ia * (p.ax * py - p.ay * px);
      b.vx += mb * px;
      b.vy += mb * py;
      b.w += ib * (bx * py - by * px);
    };
    Wide bxs[2], bys[2];
    for (int j = 0; j < 2; ++j) {
      WideConstraint::Point& p = c->points[j];
      const Wide bx = p.ax + c->dx, by = p.ay + c->dy;
      bxs[j] = bx;
      bys[j] = by;
      const Wide prax = a.qc * p.ax - a.qs * p.ay, pray = a.qs * p.ax + a.qc * p.ay;
      const Wide prbx = b.qc * bx - b.qs * by, prby = b.qs * bx + b.qc * by;
      const Wide s = (dpx + prbx - prax) * nx + (dpy + prby - pray) * ny + p.base_separation;
      const auto speculative = s > zero;
      Wide bias = speculative ? s * inv_h : zero;
      Wide mass_scale = one, impulse_scale = zero;
      if (use_bias) {
        bias = speculative ? bias : wmax(c->bias_rate * s, max_push);
        mass_scale = speculative ? one : c->mass_scale;
        impulse_scale = speculative ? zero : c->impulse_scale;
      }
      const Wide dvx = (b.vx - b.w * by) - (a.vx - a.w * p.ay);
      const Wide dvy = (b.vy + b.w * bx) - (a.vy + a.w * p.ax);
      const Wide vn = dvx * nx + dvy * ny;
      Wide impulse = -p.normal_mass * mass_scale * (vn + bias) - impulse_scale * p.normal_impulse;
      const Wide accumulated = wmax(p.normal_impulse + impulse, zero);
      impulse = accumulated - p.normal_impulse;
      p.normal_impulse = accumulated;
      if constexpr (Track) {
        Wide& m = max_impulse[c - begin].point[j];
        m = wmax(m, impulse);
      }
      apply(p, bx, by, impulse * nx, impulse * ny);
    }
    const Wide tx = ny, ty = -nx;
    for (int j = 0; j < 2; ++j) {
      WideConstraint::Point& p = c->points[j];
      const Wide bx = bxs[j], by = bys[j];
      const Wide dvx = (b.vx - b.w * by) - (a.vx - a.w * p.ay);
      const Wide dvy = (b.vy + b.w * bx) - (a.vy + a.w * p.ax);
      const Wide vt = dvx * tx + dvy * ty;
      const Wide limit = c->friction * p.normal_impulse;
      const Wide accumulated = wmin(wmax(p.tangent_impulse - p.tangent_mass * vt, -limit), limit);
      const Wide impulse = accumulated - p.tangent_impulse;
      p.tangent_impulse = accumulated;
      apply(p, bx, by, impulse * tx, impulse * ty);
    }
    scatter(bodies, c->body_a, a);
    scatter(bodies, c->body_b, b);
  }
}

__attribute__((target_clones("avx2", "default"))) void solve_wide(
    SolverBody* bodies, WideConstraint* begin, WideConstraint* end, WideMaxImpulse* max_impulse,
    Real inv_h, Real max_push, bool use_bias) {
  if (max_impulse) {
    solve_wide_impl<true>(bodies, begin, end, max_impulse, inv_h, max_push, use_bias);
  } else {
    solve_wide_impl<false>(bodies, begin, end, nullptr, inv_h, max_push, use_bias);
  }
}

void pack(WideConstraint& w, int lane, const ContactConstraint& c) {
  w.body_a[lane] = c.body_a;
  w.body_b[lane] = c.body_b;
  w.inv_mass_a[lane] = c.inv_mass_a;
  w.inv_inertia_a[lane] = c.inv_inertia_a;
  w.inv_mass_b[lane] = c.inv_mass_b;
  w.inv_inertia_b[lane] = c.inv_inertia_b;
  w.nx[lane] = c.nx;
  w.ny[lane] = c.ny;
  w.friction[lane] = c.friction;
  w.bias_rate[lane] = c.bias_rate;
  w.mass_scale[lane] = c.mass_scale;
  w.impulse_scale[lane] = c.impulse_scale;
  w.dx[lane] = c.dx;
  w.dy[lane] = c.dy;
  for (int j = 0; j < 2; ++j) {
    const ContactConstraintPoint& p = c.points[j];
    WideConstraint::Point& q = w.points[j];
    q.ax[lane] = p.ax;
    q.ay[lane] = p.ay;
    q.base_separation[lane] = p.base_separation;
    q.normal_mass[lane] = p.normal_mass;
    q.tangent_mass[lane] = p.tangent_mass;
    q.normal_impulse[lane] = p.normal_impulse;
    q.tangent_impulse[lane] = p.tangent_impulse;
  }
}

// Colours before giving up on a constraint (it then joins the one-at-a-time overflow).
constexpr std::size_t kColorCount = 24;

}  // namespace

ContactSolver::ContactSolver() = default;
ContactSolver::~ContactSolver() = default;
ContactSolver::ContactSolver(ContactSolver&&) noexcept = default;
ContactSolver& ContactSolver::operator=(ContactSolver&&) noexcept = default;

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
                          std::size_t body_count, bool wide) {
  wide_mode_ = wide;
  bouncy_ = false;
  still_ = still;
  restitution_.clear();
  // Greedy colouring in constraint order (deterministic): the first colour where neither
  // moving body is taken yet. Bodies the solver cannot move never block a colour.
  const std::size_t words = (body_count + 63) / 64;
  color_bits_.assign(kColorCount * words, 0);
  color_of_.resize(constraints.size());
  std::array<std::uint32_t, kColorCount + 1> counts{};
  for (std::uint32_t i = 0; i < constraints.size(); ++i) {
    const std::int32_t a = constraints[i].a, b = constraints[i].b;
    const bool a_fixed = constraints[i].a_fixed, b_fixed = constraints[i].b_fixed;
    const std::uint64_t a_bit = a_fixed ? 0 : std::uint64_t{1} << (a & 63);
    const std::uint64_t b_bit = b_fixed ? 0 : std::uint64_t{1} << (b & 63);
    const std::size_t a_word = static_cast<std::size_t>(a) >> 6;
    const std::size_t b_word = static_cast<std::size_t>(b) >> 6;
    std::size_t color = 0;
    for (std::uint64_t* bits = color_bits_.data(); color < kColorCount; ++color, bits += words) {
      if (!(bits[a_word] & a_bit) && !(bits[b_word] & b_bit)) {
        bits[a_word] |= a_bit;
        bits[b_word] |= b_bit;
        break;
      }
    }
    color_of_[i] = static_cast<std::uint8_t>(color);
    ++counts[color];
  }
  overflow_count_ = counts[kColorCount];
  color_begin_.assign(kColorCount + 2, 0);
  wide_begin_.assign(kColorCount + 1, 0);
  for (std::size_t c = 0; c <= kColorCount; ++c) color_begin_[c + 1] = color_begin_[c] + counts[c];
  for (std::size_t c = 0; c < kColorCount; ++c) {
    wide_begin_[c + 1] = wide_begin_[c] + (counts[c] + 3) / 4;
  }
  // Slots: position within the colour gives the batch and the lane directly.
  slot_.resize(constraints.size());
  std::array<std::uint32_t, kColorCount + 1> fill{};
  for (std::size_t c = 0; c <= kColorCount; ++c) fill[c] = color_begin_[c];
  for (std::uint32_t i = 0; i < constraints.size(); ++i) {
    const std::uint8_t color = color_of_[i];
    const std::uint32_t position = fill[color]++;
    if (!wide) {
      slot_[i] = kScalar | position;
    } else if (color == kColorCount) {
      slot_[i] = kScalar | (position - color_begin_[kColorCount]);
    } else {
      const std::uint32_t offset = position - color_begin_[color];
      slot_[i] = 4 * (wide_begin_[color] + offset / 4) + offset % 4;
    }
  }
  if (wide) {
    scalar_.resize(overflow_count_);
    wide_.resize(wide_begin_[kColorCount]);
  } else {
    scalar_.resize(constraints.size());
    wide_.clear();
  }
}

void ContactSolver::set(std::uint32_t index, const ContactConstraint& constraint) {
  const std::uint32_t slot = slot_[index];
  bouncy_ = bouncy_ || constraint.restitution > 0;
  if (slot & kScalar) {
    scalar_[slot & ~kScalar] = constraint;
  } else {
    pack(wide_[slot / 4], static_cast<int>(slot % 4), constraint);
    if (constraint.restitution > 0) restitution_.emplace_back(slot, constraint);
  }
}

void ContactSolver::finish() {
  if (!wide_mode_) return;
  // Lanes past the end of each colour's last batch: the still body, no mass, no impulse.
  ContactConstraint padding;
  padding.body_a = padding.body_b = still_;
  padding.nx = 1;
  padding.mass_scale = 1;
  for (std::size_t c = 0; c < kColorCount; ++c) {
    const std::uint32_t count = color_begin_[c + 1] - color_begin_[c];
    if (count % 4 == 0) continue;
    WideConstraint& w = wide_[wide_begin_[c + 1] - 1];
    for (int lane = static_cast<int>(count % 4); lane < 4; ++lane) pack(w, lane, padding);
  }
  // Bounce in colour order, as the one-at-a-time twin does.
  std::sort(restitution_.begin(), restitution_.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
}

void ContactSolver::impulses(std::uint32_t index, Real normal[2], Real tangent[2]) const {
  const std::uint32_t slot = slot_[index];
  if (slot & kScalar) {
    const ContactConstraint& c = scalar_[slot & ~kScalar];
    for (int j = 0; j < 2; ++j) {
      normal[j] = c.points[j].normal_impulse;
      tangent[j] = c.points[j].tangent_impulse;
    }
    return;
  }
  const WideConstraint& w = wide_[slot / 4];
  for (int j = 0; j < 2; ++j) {
    normal[j] = w.points[j].normal_impulse[slot % 4];
    tangent[j] = w.points[j].tangent_impulse[slot % 4];
  }
}

void ContactSolver::solve(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
                          const SolverSettings& settings) {
  SolverBody* body_data = bodies.data();
  WideConstraint* wide_data = wide_.data();
  // Largest impulses are only needed when something bounces.
  max_impulse_.assign(bouncy_ && wide_mode_ ? wide_.size() : 0, WideMaxImpulse{});
  WideMaxImpulse* max_data = max_impulse_.empty() ? nullptr : max_impulse_.data();
  const auto scalar_pass = [&](auto&& fn) {
    for (ContactConstraint& c : scalar_) fn(c);
  };
  const auto wide_pass = [&](auto&& fn) {
    for (std::size_t c = 0; c < kColorCount; ++c) {
      fn(wide_data + wide_begin_[c], wide_data + wide_begin_[c + 1],
         max_data ? max_data + wide_begin_[c] : nullptr);
    }
  };
  const Real inv_h = settings.inv_h, max_push = settings.contact_push_max_velocity;
  for (int substep = 0; substep < settings.substeps; ++substep) {
    integrate_velocities(bodies, params, settings);
    if (wide_mode_) {
      wide_pass([&](WideConstraint* b, WideConstraint* e, WideMaxImpulse*) {
        warm_start_wide(body_data, b, e);
      });
    }
    scalar_pass([&](ContactConstraint& c) { warm_start_one(body_data, c); });
    if (wide_mode_) {
      wide_pass([&](WideConstraint* b, WideConstraint* e, WideMaxImpulse* m) {
        solve_wide(body_data, b, e, m, inv_h, max_push, true);
      });
    }
    scalar_pass([&](ContactConstraint& c) { solve_one(body_data, c, inv_h, max_push, true); });
    integrate_positions(bodies, settings.h);
    if (wide_mode_) {
      wide_pass([&](WideConstraint* b, WideConstraint* e, WideMaxImpulse* m) {
        solve_wide(body_data, b, e, m, inv_h, max_push, false);
      });
    }
    scalar_pass([&](ContactConstraint& c) { solve_one(body_data, c, inv_h, max_push, false); });
  }
  if (!bouncy_) return;
  // Restitution, once per step and rare: one at a time, colours first, then the overflow.
  const Real threshold = settings.restitution_threshold;
  for (auto& [slot, c] : restitution_) {
    WideConstraint& w = wide_[slot / 4];
    const int lane = static_cast<int>(slot % 4);
    for (int j = 0; j < 2; ++j) {
      c.points[j].normal_impulse = w.points[j].normal_impulse[lane];
      c.points[j].max_normal_impulse = max_data[slot / 4].point[j][lane];
    }
    restitution_one(body_data, c, threshold);
    for (int j = 0; j < 2; ++j) w.points[j].normal_impulse[lane] = c.points[j].normal_impulse;
  }
  scalar_pass([&](ContactConstraint& c) { restitution_one(body_data, c, threshold); });
}

}  // namespace mink::detail
