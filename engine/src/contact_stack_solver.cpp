// Direct solve of contact stacks: see contact_stack_solver.hpp.

#include "contact_stack_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "contact_kernels.hpp"

namespace mink::detail {

namespace {

// Relative weight added to K's diagonal: rows that say the same thing (a box on two coplanar
// ground shapes: four rows, three degrees of freedom) make K singular; this picks the
// smallest impulses among the equal answers and changes no answer by more than a millionth.
constexpr double kRegularization = 1e-6;
// The least share of a row's own (unit-mass) diagonal that must stay once the rows before it
// are taken out: rows at an angle of about 6 degrees or more to every combination of others.
constexpr double kLeastIndependence = 1e-2;

// The Cholesky factor L (m x m, row-major) of K's rows and columns `index` (m of them).
// False when a pivot is not positive to working precision (non-finite input) or keeps less
// than `least_share` of its row's diagonal once the rows before it are taken out.
bool cholesky(const double* k, int n, const int* index, int m, double least_share, double* l) {
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j <= i; ++j) {
      double sum = k[index[i] * n + index[j]];
      for (int t = 0; t < j; ++t) sum -= l[i * m + t] * l[j * m + t];
      if (i == j) {
        if (!(sum > 1e-300) || sum < least_share * k[index[i] * n + index[i]]) return false;
        l[i * m + i] = std::sqrt(sum);
      } else {
        l[i * m + j] = sum / l[j * m + j];
      }
    }
  }
  return true;
}

// Solves K_AA y = rhs for the rows `index` (m of them); false as cholesky().
bool cholesky_solve(const double* k, int n, const int* index, int m, const double* rhs, double* y,
                    double* l) {
  if (!cholesky(k, n, index, m, 0, l)) return false;
  for (int i = 0; i < m; ++i) {
    double sum = rhs[i];
    for (int t = 0; t < i; ++t) sum -= l[i * m + t] * y[t];
    y[i] = sum / l[i * m + i];
  }
  for (int i = m - 1; i >= 0; --i) {
    double sum = y[i];
    for (int t = i + 1; t < m; ++t) sum -= l[t * m + i] * y[t];
    y[i] = sum / l[i * m + i];
  }
  return true;
}

// One side of a normal row: the body, its inverse mass and inertia, and the row's Jacobian
// for it (linear part along the normal, signed, and angular part).
struct RowSide {
  std::int32_t body;
  double inv_mass, inv_inertia;
  double lx, ly, angular;
};

std::array<RowSide, 2> row_sides(const ContactConstraint& c, const ContactConstraintPoint& p) {
  const double nx = c.nx, ny = c.ny;
  return {RowSide{c.body_a, c.inv_mass_a, c.inv_inertia_a, -nx, -ny,
                  -(double{p.ax} * ny - double{p.ay} * nx)},
          RowSide{c.body_b, c.inv_mass_b, c.inv_inertia_b, nx, ny,
                  double{p.bx} * ny - double{p.by} * nx}};
}

}  // namespace

bool solve_complementarity(std::span<const double> k, std::span<const double> q, int n,
                           std::span<double> x, std::uint32_t& active) {
  std::array<int, kMaxStackRows> index{};
  std::array<double, kMaxStackRows> rhs{}, y{};
  std::array<double, kMaxStackRows * kMaxStackRows> l{};
  double q_scale = 0, k_scale = 0;
  for (int i = 0; i < n; ++i) {
    q_scale = std::max(q_scale, std::abs(q[i]));
    k_scale = std::max(k_scale, k[i * n + i]);
  }
  const auto clamped = [&] {
    for (int i = 0; i < n; ++i) x[i] = std::max(x[i], 0.0);
  };
  // Least-index principal pivoting ends for a positive definite K; the limit only guards
  // against rounding making a pivot flip back and forth.
  const int limit = 4 * n + 16;
  for (int pivot = 0;; ++pivot) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
      if ((active >> i & 1) == 0) continue;
      index[m] = i;
      rhs[m] = -q[i];
      ++m;
    }
    std::fill(x.begin(), x.begin() + n, 0.0);
    if (!cholesky_solve(k.data(), n, index.data(), m, rhs.data(), y.data(), l.data())) {
      return false;
    }
    double x_scale = 0;
    for (int t = 0; t < m; ++t) {
      x[index[t]] = y[t];
      x_scale = std::max(x_scale, std::abs(y[t]));
    }
    // The least row that breaks a condition: a basic row that pulls, or a free row whose
    // bodies approach. Rounding is forgiven in proportion to the sizes at hand.
    const double x_tolerance = 1e-12 * x_scale;
    const double w_tolerance = 1e-12 * (q_scale + k_scale * x_scale);
    int flip = -1;
    for (int i = 0; i < n && flip < 0; ++i) {
      if ((active >> i & 1) != 0) {
        if (x[i] < -x_tolerance) flip = i;
        continue;
      }
      double w = q[i];
      for (int j = 0; j < n; ++j) w += k[i * n + j] * x[j];
      if (w < -w_tolerance) flip = i;
    }
    if (flip < 0) {
      clamped();
      return true;
    }
    if (pivot == limit) {
      clamped();
      return false;
    }
    active ^= std::uint32_t{1} << flip;
  }
}

void ContactStackSolver::build(std::span<const ContactConstraint> constraints,
                               std::span<const std::uint32_t> members,
                               std::span<const std::uint32_t> stack_begin) {
  stacks_.clear();
  rows_.clear();
  matrices_.clear();
  members_.assign(members.begin(), members.end());
  direct_constraints_ = 0;
  for (std::size_t s = 0; s + 1 < stack_begin.size(); ++s) {
    Stack st{stack_begin[s],
             stack_begin[s + 1],
             static_cast<std::uint32_t>(rows_.size()),
             0,
             matrices_.size(),
             0,
             false};
    for (std::uint32_t m = st.member_begin; m < st.member_end; ++m) {
      const ContactConstraint& c = constraints[members_[m]];
      for (int j = 0; j < c.point_count; ++j) {
        // Warm started rows are the first guess of which rows push.
        if (c.points[j].normal_impulse > 0) st.active |= std::uint32_t{1} << st.row_count;
        rows_.push_back({members_[m], static_cast<std::uint32_t>(j)});
        ++st.row_count;
      }
    }
    const std::uint32_t n = st.row_count;
    matrices_.resize(matrices_.size() + std::size_t{n} * n, 0.0);
    double* k = matrices_.data() + st.matrix_begin;
    shapes_.assign(std::size_t{n} * n, 0.0);
    for (std::uint32_t r = 0; r < n; ++r) {
      const Row& row_r = rows_[st.row_begin + r];
      const ContactConstraint& cr = constraints[row_r.constraint];
      const std::array<RowSide, 2> sides_r = row_sides(cr, cr.points[row_r.point]);
      for (std::uint32_t s2 = 0; s2 <= r; ++s2) {
        const Row& row_s = rows_[st.row_begin + s2];
        const ContactConstraint& cs = constraints[row_s.constraint];
        const std::array<RowSide, 2> sides_s = row_sides(cs, cs.points[row_s.point]);
        // J_r M^-1 J_s^T: the rows couple through each moving body they share.
        // The same with every body of unit mass (its inertia scaled alike): what the rows'
        // directions alone say of their independence.
        double sum = 0, shape = 0;
        for (const RowSide& u : sides_r) {
          if (u.inv_mass == 0 && u.inv_inertia == 0) continue;
          for (const RowSide& v : sides_s) {
            if (v.body != u.body) continue;
            const double linear = u.lx * v.lx + u.ly * v.ly, angular = u.angular * v.angular;
            sum += u.inv_mass * linear + u.inv_inertia * angular;
            shape += u.inv_mass > 0 ? linear + u.inv_inertia / u.inv_mass * angular : angular;
          }
        }
        k[r * n + s2] = k[s2 * n + r] = sum;
        shapes_[r * n + s2] = shapes_[s2 * n + r] = shape;
      }
      k[r * n + r] *= 1 + kRegularization;
    }
    // Rows that (nearly) repeat others (a box on two ground shapes: four rows on three degrees
    // of freedom) leave the pushes along their common direction free, and targets that
    // disagree there (two penetrations) drive them without bound: such a stack is solved one
    // contact at a time, as without it.
    std::array<int, kMaxStackRows> all{};
    for (std::uint32_t r = 0; r < n; ++r) all[r] = static_cast<int>(r);
    factor_.resize(std::size_t{n} * n);
    st.direct = cholesky(shapes_.data(), static_cast<int>(n), all.data(), static_cast<int>(n),
                         kLeastIndependence, factor_.data());
    if (st.direct) direct_constraints_ += st.member_end - st.member_begin;
    stacks_.push_back(st);
  }
}

void ContactStackSolver::solve(SolverBody* bodies, std::span<ContactConstraint> constraints,
                               SolverReal inv_h, SolverReal max_push, bool use_bias) {
  for (Stack& st : stacks_) {
    const auto one_at_a_time = [&] {
      for (std::uint32_t m = st.member_begin; m < st.member_end; ++m) {
        solve_one(bodies, constraints[members_[m]], inv_h, max_push, use_bias);
      }
    };
    if (!st.direct) {
      one_at_a_time();
      continue;
    }
    const std::uint32_t n = st.row_count;
    const std::span<const double> k(matrices_.data() + st.matrix_begin, std::size_t{n} * n);
    q_.resize(n);
    x_.resize(n);
    impulses_.resize(n);
    for (std::uint32_t r = 0; r < n; ++r) {
      const Row& row = rows_[st.row_begin + r];
      impulses_[r] = constraints[row.constraint].points[row.point].normal_impulse;
    }
    // The soft step for all rows at once: K x = ms (K lambda - v - bias), as w = K x + q.
    for (std::uint32_t r = 0; r < n; ++r) {
      const Row& row = rows_[st.row_begin + r];
      const ContactConstraint& c = constraints[row.constraint];
      const ContactConstraintPoint& p = c.points[row.point];
      const PointBias pb = point_bias(c, separation_now(bodies[c.body_a], bodies[c.body_b], c, p),
                                      inv_h, max_push, use_bias);
      const double target = double{load_pair(bodies, c).normal_speed(c, p)} + pb.bias;
      double pushed = 0;
      for (std::uint32_t j = 0; j < n; ++j) pushed += k[r * n + j] * impulses_[j];
      q_[r] = double{pb.mass_scale} * (target - pushed);
    }
    std::uint32_t active = st.active;
    if (!solve_complementarity(k, q_, static_cast<int>(n), x_, active)) {
      one_at_a_time();  // as without a stack
      continue;
    }
    st.active = active;
    for (std::uint32_t r = 0; r < n; ++r) {
      const Row& row = rows_[st.row_begin + r];
      ContactConstraint& c = constraints[row.constraint];
      ContactConstraintPoint& p = c.points[row.point];
      const auto accumulated = static_cast<SolverReal>(x_[r]);
      const SolverReal impulse = accumulated - p.normal_impulse;
      p.normal_impulse = accumulated;
      p.max_normal_impulse = std::max(p.max_normal_impulse, impulse);
      PairVelocity v = load_pair(bodies, c);
      v.apply(c, p, impulse * c.nx, impulse * c.ny);
      store_pair(bodies, c, v);
    }
    if (use_bias) continue;
    for (std::uint32_t m = st.member_begin; m < st.member_end; ++m) {
      ContactConstraint& c = constraints[members_[m]];
      PairVelocity v = load_pair(bodies, c);
      solve_friction(c, v);
      store_pair(bodies, c, v);
    }
  }
}

}  // namespace mink::detail
