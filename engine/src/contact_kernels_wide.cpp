// The soft-step contact kernels kWideLanes constraints at a time, one per SIMD lane (GCC vector
// extensions), compiled for x86-64-v4 (AVX-512), AVX2 and baseline x86-64 and picked at load
// time. No fused multiply-add is used (the engine builds with -ffp-contract=off), so every
// build and the one-at-a-time kernels give bitwise equal results.

#include "wide_body.hpp"

namespace mink::detail {

namespace {

// `Track` keeps each point's largest single impulse of the step for restitution; scenes
// without restitution skip that store.
template <bool Track>
__attribute__((always_inline)) inline void solve_wide_impl(
    SolverBody* bodies, WideConstraint* begin, WideConstraint* end, WideMaxImpulse* max_impulse,
    SolverReal inv_h_scalar, SolverReal max_push_scalar, bool use_bias) {
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
    // Both points' separations first: positions do not change while solving, and the
    // position fields then need no register through the impulses.
    Wide bxs[2], bys[2], separations[2];
    for (int j = 0; j < 2; ++j) {
      const WideConstraint::Point& p = c->points[j];
      const Wide bx = p.ax + c->dx, by = p.ay + c->dy;
      bxs[j] = bx;
      bys[j] = by;
      const Wide prax = a.qc * p.ax - a.qs * p.ay, pray = a.qs * p.ax + a.qc * p.ay;
      const Wide prbx = b.qc * bx - b.qs * by, prby = b.qs * bx + b.qc * by;
      separations[j] = (dpx + prbx - prax) * nx + (dpy + prby - pray) * ny + p.base_separation;
    }
    for (int j = 0; j < 2; ++j) {
      WideConstraint::Point& p = c->points[j];
      const Wide bx = bxs[j], by = bys[j], s = separations[j];
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
    // Friction in the relax pass only, as in the scalar kernel (see there).
    const Wide tx = ny, ty = -nx;
    for (int j = 0; j < 2 && !use_bias; ++j) {
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
    scatter(bodies, c->body_a, a, c->inv_mass_a, c->inv_inertia_a);
    scatter(bodies, c->body_b, b, c->inv_mass_b, c->inv_inertia_b);
  }
}

// Always inlined into the kernel below, as the solve's body is (vectors stay in registers).
MINK_WIDE_INLINE void finish_points_impl(WideConstraint& w, std::uint32_t two_points) {
  const Wide zero = splat(0), one = splat(1);
  const Wide nx = w.nx, ny = w.ny, tx = ny, ty = -nx;
  const Wide ma = w.inv_mass_a, ia = w.inv_inertia_a, mb = w.inv_mass_b, ib = w.inv_inertia_b;
  Wide second;
  for (int lane = 0; lane < kWideLanes; ++lane) second[lane] = (two_points >> lane) & 1;
  const auto has_second = second > zero;
  for (int j = 0; j < 2; ++j) {
    WideConstraint::Point& p = w.points[j];
    const Wide ax = p.ax, ay = p.ay, bx = ax + w.dx, by = ay + w.dy;
    Wide base_separation = p.base_separation - ((bx - ax) * nx + (by - ay) * ny);
    const Wide rna = ax * ny - ay * nx, rnb = bx * ny - by * nx;
    const Wide kn = ma + mb + ia * rna * rna + ib * rnb * rnb;
    Wide normal_mass = kn > zero ? one / kn : zero;
    const Wide rta = ax * ty - ay * tx, rtb = bx * ty - by * tx;
    const Wide kt = ma + mb + ia * rta * rta + ib * rtb * rtb;
    Wide tangent_mass = kt > zero ? one / kt : zero;
    if (j == 1) {
      base_separation = has_second ? base_separation : zero;
      normal_mass = has_second ? normal_mass : zero;
      tangent_mass = has_second ? tangent_mass : zero;
    }
    p.base_separation = base_separation;
    p.normal_mass = normal_mass;
    p.tangent_mass = tangent_mass;
  }
}

// Per lane: `padded` where `padding` is set, else `against_fixed` where `fixed` is, else
// `moving`, each in the solver's precision.
MINK_WIDE_INLINE Wide lanes_of(WideIndex padding, WideIndex fixed, Real padded, Real moving,
                               Real against_fixed) {
  return padding ? splat(static_cast<SolverReal>(padded))
                 : (fixed ? splat(static_cast<SolverReal>(against_fixed))
                          : splat(static_cast<SolverReal>(moving)));
}

// Always inlined into the kernel below: clang checks a vector's passing before inlining, and a
// call that returns one from the baseline clone would pass it in another way.
MINK_WIDE_INLINE void build_wide_impl(WideConstraint& w, const BatchLane* lanes, int count,
                                      std::uint32_t two_points, std::int32_t padding_body,
                                      const Softness& soft, const Softness& fixed_soft) {
  static constexpr ContactSeed kPadding = {1, 0, 0, 0, 0, 0, {{0, 0, 0, 0, 0}, {0, 0, 0, 0, 0}}};
  static_assert(sizeof(ContactSeed) == 2 * sizeof(Wide));
  const auto seed_of = [&](int lane) -> const ContactSeed& {
    return lane < count ? *lanes[lane].seed : kPadding;
  };
  if constexpr (kWideLanes == 8) {
    // A seed is two rows of eight fields: the batch's seeds are two 8 x 8 matrices whose
    // transposes hold one field per register.
    Wide low[8], high[8];
    for (int lane = 0; lane < 8; ++lane) {
      const ContactSeed& seed = seed_of(lane);
      __builtin_memcpy(&low[lane], &seed, sizeof(Wide));
      __builtin_memcpy(&high[lane], &seed.points[0].separation, sizeof(Wide));
    }
    static_assert(offsetof(ContactSeed, points[0].separation) == sizeof(Wide));
    transpose8(low);
    transpose8(high);
    w.nx = low[0];
    w.ny = low[1];
    w.dx = low[2];
    w.dy = low[3];
    w.friction = low[4];
    w.points[0].ax = low[6];
    w.points[0].ay = low[7];
    w.points[0].base_separation = high[0];
    w.points[0].normal_impulse = high[1];
    w.points[0].tangent_impulse = high[2];
    w.points[1].ax = high[3];
    w.points[1].ay = high[4];
    w.points[1].base_separation = high[5];
    w.points[1].normal_impulse = high[6];
    w.points[1].tangent_impulse = high[7];
  } else {
    for (int lane = 0; lane < kWideLanes; ++lane) {
      const ContactSeed& seed = seed_of(lane);
      w.nx[lane] = seed.nx;
      w.ny[lane] = seed.ny;
      w.dx[lane] = seed.dx;
      w.dy[lane] = seed.dy;
      w.friction[lane] = seed.friction;
      for (int j = 0; j < 2; ++j) {
        w.points[j].ax[lane] = seed.points[j].ax;
        w.points[j].ay[lane] = seed.points[j].ay;
        w.points[j].base_separation[lane] = seed.points[j].separation;
        w.points[j].normal_impulse[lane] = seed.points[j].normal_impulse;
        w.points[j].tangent_impulse[lane] = seed.points[j].tangent_impulse;
      }
    }
  }
  Wide ma = splat(0), ia = ma, mb = ma, ib = ma, used = ma;
  for (int lane = 0; lane < kWideLanes; ++lane) {
    if (lane >= count) {
      w.body_a[lane] = w.body_b[lane] = padding_body;
      continue;
    }
    const BatchLane& in = lanes[lane];
    w.body_a[lane] = in.body_a;
    w.body_b[lane] = in.body_b;
    ma[lane] = in.inv_mass_a;
    ia[lane] = in.inv_inertia_a;
    mb[lane] = in.inv_mass_b;
    ib[lane] = in.inv_inertia_b;
    used[lane] = 1;
  }
  w.inv_mass_a = ma;
  w.inv_inertia_a = ia;
  w.inv_mass_b = mb;
  w.inv_inertia_b = ib;
  // Padding is bias free and unscaled; a constraint with a side of no mass is fixed.
  const Wide zero = splat(0);
  const auto padding = used == zero;
  const auto fixed = (ma == zero) | (mb == zero);
  w.bias_rate = lanes_of(padding, fixed, 0, soft.bias_rate, fixed_soft.bias_rate);
  w.mass_scale = lanes_of(padding, fixed, 1, soft.mass_scale, fixed_soft.mass_scale);
  w.impulse_scale = lanes_of(padding, fixed, 0, soft.impulse_scale, fixed_soft.impulse_scale);
  finish_points_impl(w, two_points);
}

}  // namespace

MINK_WIDE_KERNEL void finish_points_wide(WideConstraint& w, std::uint32_t two_points) {
  finish_points_impl(w, two_points);
}

MINK_WIDE_KERNEL void build_wide(WideConstraint& w, const BatchLane* lanes, int count,
                                 std::uint32_t two_points, std::int32_t padding_body,
                                 const Softness& soft, const Softness& fixed_soft) {
  build_wide_impl(w, lanes, count, two_points, padding_body, soft, fixed_soft);
}

MINK_WIDE_KERNEL void warm_start_wide(SolverBody* bodies, WideConstraint* begin,
                                      WideConstraint* end) {
  for (WideConstraint* c = begin; c != end; ++c) {
    WideBody a = gather_velocities(bodies, c->body_a);
    WideBody b = gather_velocities(bodies, c->body_b);
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
    scatter(bodies, c->body_a, a, c->inv_mass_a, c->inv_inertia_a);
    scatter(bodies, c->body_b, b, c->inv_mass_b, c->inv_inertia_b);
  }
}

MINK_WIDE_KERNEL void solve_wide(SolverBody* bodies, WideConstraint* begin, WideConstraint* end,
                                 WideMaxImpulse* max_impulse, SolverReal inv_h, SolverReal max_push,
                                 bool use_bias) {
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

ContactConstraint unpack(const WideConstraint& w, int lane) {
  ContactConstraint c{};
  c.body_a = w.body_a[lane];
  c.body_b = w.body_b[lane];
  c.inv_mass_a = w.inv_mass_a[lane];
  c.inv_inertia_a = w.inv_inertia_a[lane];
  c.inv_mass_b = w.inv_mass_b[lane];
  c.inv_inertia_b = w.inv_inertia_b[lane];
  c.nx = w.nx[lane];
  c.ny = w.ny[lane];
  c.friction = w.friction[lane];
  c.bias_rate = w.bias_rate[lane];
  c.mass_scale = w.mass_scale[lane];
  c.impulse_scale = w.impulse_scale[lane];
  c.dx = w.dx[lane];
  c.dy = w.dy[lane];
  for (int j = 0; j < 2; ++j) {
    const WideConstraint::Point& q = w.points[j];
    ContactConstraintPoint& p = c.points[j];
    p.ax = q.ax[lane];
    p.ay = q.ay[lane];
    // Through the centre offset, as the kernels recompute it (same bits).
    p.bx = p.ax + c.dx;
    p.by = p.ay + c.dy;
    p.base_separation = q.base_separation[lane];
    p.normal_mass = q.normal_mass[lane];
    p.tangent_mass = q.tangent_mass[lane];
    p.normal_impulse = q.normal_impulse[lane];
    p.tangent_impulse = q.tangent_impulse[lane];
  }
  return c;
}

}  // namespace mink::detail
