// The revolute rows kWideLanes at a time (revolute_rows.hpp): the same function as one at a
// time, on registers of kWideLanes joints that share no moving body (one colour), and no fused
// multiply-add, so the bits are the one-at-a-time rows'.

#include "revolute_rows.hpp"
#include "wide_body.hpp"

namespace mink::detail {

MINK_WIDE_KERNEL void warm_start_revolutes_wide(SolverBody* bodies, const WideRevoluteRows& r) {
  WideBody a = gather(bodies, r.body_a);
  WideBody b = gather(bodies, r.body_b);
  revolute_warm_start(a, b, r);
  scatter_lanes(bodies, r.body_a, a, r.lanes);
  scatter_lanes(bodies, r.body_b, b, r.lanes);
}

MINK_WIDE_KERNEL void solve_revolutes_wide(SolverBody* bodies, WideRevoluteRows& r, bool use_bias) {
  WideBody a = gather(bodies, r.body_a);
  WideBody b = gather(bodies, r.body_b);
  revolute_solve(a, b, r, use_bias);
  scatter_lanes(bodies, r.body_a, a, r.lanes);
  scatter_lanes(bodies, r.body_b, b, r.lanes);
}

// The angle rows' fields, and those of them the solve accumulates.
// clang-format off
#define MINK_REVOLUTE_IMPULSES(X) \
  X(spring_impulse) X(motor_impulse) X(lower_impulse) X(upper_impulse)
#define MINK_REVOLUTE_SETTINGS(X)                                                      \
  X(axial_mass) X(spring_bias_rate) X(spring_mass_scale) X(spring_impulse_scale)       \
  X(spring_offset) X(motor_speed) X(motor_max_impulse) X(lower_offset) X(upper_offset) \
  X(inv_h) X(spring_on) X(motor_on) X(limit_on)
// clang-format on

void pack_revolute(WideRevoluteRows& w, int lane, const RevoluteRow& row) {
  pack_pin(w, lane, row);
#define MINK_PACK(field) w.field[lane] = row.field;
  MINK_REVOLUTE_SETTINGS(MINK_PACK)
  MINK_REVOLUTE_IMPULSES(MINK_PACK)
#undef MINK_PACK
}

void read_impulses(const WideRevoluteRows& w, int lane, RevoluteRow& row) {
#define MINK_READ(field) row.field = w.field[lane];
  MINK_READ(impulse_x)
  MINK_READ(impulse_y)
  MINK_REVOLUTE_IMPULSES(MINK_READ)
#undef MINK_READ
}

}  // namespace mink::detail
