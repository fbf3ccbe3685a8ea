// The pins kWideLanes at a time (pin_rows.hpp): the same function as one at a time, on
// registers of kWideLanes joints that share no moving body (one colour), and no fused
// multiply-add, so the bits are the one-at-a-time rows'.

#include "pin_rows.hpp"
#include "wide_body.hpp"

namespace mink::detail {

MINK_WIDE_KERNEL void warm_start_pins_wide(SolverBody* bodies, const WidePinRows* begin,
                                           const WidePinRows* end) {
  for (const WidePinRows* r = begin; r != end; ++r) {
    WideBody a = gather(bodies, r->body_a);
    WideBody b = gather(bodies, r->body_b);
    const Wide no_angular{};
    pin_warm_start(a, b, *r, no_angular);
    scatter_lanes(bodies, r->body_a, a, r->lanes);
    scatter_lanes(bodies, r->body_b, b, r->lanes);
  }
}

MINK_WIDE_KERNEL void solve_pins_wide(SolverBody* bodies, WidePinRows* begin, WidePinRows* end,
                                      bool use_bias) {
  for (WidePinRows* r = begin; r != end; ++r) {
    WideBody a = gather(bodies, r->body_a);
    WideBody b = gather(bodies, r->body_b);
    pin_solve(a, b, *r, use_bias);
    scatter_lanes(bodies, r->body_a, a, r->lanes);
    scatter_lanes(bodies, r->body_b, b, r->lanes);
  }
}

void pack_pin(WidePinRows& w, int lane, const PinRow& row) {
  w.body_a[lane] = row.body_a;
  w.body_b[lane] = row.body_b;
  w.inv_mass_a[lane] = row.inv_mass_a;
  w.inv_inertia_a[lane] = row.inv_inertia_a;
  w.inv_mass_b[lane] = row.inv_mass_b;
  w.inv_inertia_b[lane] = row.inv_inertia_b;
  w.anchor_ax[lane] = row.anchor_ax;
  w.anchor_ay[lane] = row.anchor_ay;
  w.anchor_bx[lane] = row.anchor_bx;
  w.anchor_by[lane] = row.anchor_by;
  w.delta_x[lane] = row.delta_x;
  w.delta_y[lane] = row.delta_y;
  w.bias_rate[lane] = row.bias_rate;
  w.mass_scale[lane] = row.mass_scale;
  w.impulse_scale[lane] = row.impulse_scale;
  w.impulse_x[lane] = row.impulse_x;
  w.impulse_y[lane] = row.impulse_y;
}

}  // namespace mink::detail
