// Direct solve of revolute joint chains: see joint_chain_solver.hpp.

#include "joint_chain_solver.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "joint_rows.hpp"

namespace mink::detail {

using Mat2 = Eigen::Matrix2d;

namespace {

constexpr std::uint32_t kNone = ~std::uint32_t{0};

bool movable(const JointBody& b) {
  return b.inv_mass > 0 || b.inv_inertia > 0;
}

// The Jacobian of a point row for one body: sign * [I, perp(r)], perp(r) = (-r.y, r.x).
// J_x M^-1 J_y^T for two such rows on the same body.
Mat2 coupling(const JointBody& b, const Vec2& r1, const Vec2& r2) {
  const Vec2 p1 = left_perp(r1), p2 = left_perp(r2);
  Mat2 k = b.inv_mass * Mat2::Identity();
  k += b.inv_inertia * p1 * p2.transpose();
  return k;
}

}  // namespace

void JointChainSolver::build(IdPool<Joint>& joints, const std::vector<std::uint32_t>& order,
                             std::span<const JointEnds> ends, bool enabled) {
  path_begin_.clear();
  chain_joints_.clear();
  chain_positions_.clear();
  next_side_.clear();
  next_other_side_.clear();
  if (!enabled) return;
  // Candidates: revolute joints with a moving body; each moving body's candidate count. Read
  // from `ends`, in order, rather than from the joints' records, which a large net scatters.
  std::vector<std::uint32_t> candidates, candidate_positions;
  std::vector<std::uint32_t> degree;
  const auto key = [](const JointBody& b) { return static_cast<std::size_t>(b.solver); };
  for (std::uint32_t position = 0; position < order.size(); ++position) {
    const JointEnds& e = ends[position];
    if (!e.revolute) continue;
    if (!movable(e.bodies[0]) && !movable(e.bodies[1])) continue;
    candidates.push_back(order[position]);
    candidate_positions.push_back(position);
    for (int s = 0; s < 2; ++s) {
      if (!movable(e.bodies[s])) continue;
      if (degree.size() <= key(e.bodies[s])) degree.resize(key(e.bodies[s]) + 1, 0);
      ++degree[key(e.bodies[s])];
    }
  }
  // Bodies in more than two candidates make the rows' graph branch: those joints stay out.
  std::vector<std::uint32_t> kept, kept_positions;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const JointEnds& f = ends[candidate_positions[c]];
    bool ok = true;
    for (int s = 0; s < 2; ++s) ok = ok && (!movable(f.bodies[s]) || degree[key(f.bodies[s])] <= 2);
    if (ok) {
      kept.push_back(candidates[c]);
      kept_positions.push_back(candidate_positions[c]);
    }
  }
  // Neighbours through each side's body.
  std::vector<std::uint32_t> first_at(degree.size(), kNone);
  std::vector<std::array<std::uint32_t, 2>> neighbour(kept.size(), {kNone, kNone});
  for (std::uint32_t k = 0; k < kept.size(); ++k) {
    const JointEnds& f = ends[kept_positions[k]];
    for (int s = 0; s < 2; ++s) {
      if (!movable(f.bodies[s]) || degree[key(f.bodies[s])] != 2) continue;
      std::uint32_t& other = first_at[key(f.bodies[s])];
      if (other == kNone) {
        other = k;
        continue;
      }
      const JointEnds& g = ends[kept_positions[other]];
      const int t = g.bodies[0].solver == f.bodies[s].solver && movable(g.bodies[0]) ? 0 : 1;
      // Two joints from this body to one other body, or to two fixed ones, pin it twice: their
      // four rows on its three freedoms are redundant and the direct solve's pivot would
      // vanish, so the path breaks here and each joint is solved on its own.
      const JointBody& f_far = f.bodies[static_cast<std::size_t>(1 - s)];
      const JointBody& g_far = g.bodies[static_cast<std::size_t>(1 - t)];
      if ((!movable(f_far) && !movable(g_far)) || f_far.solver == g_far.solver) continue;
      neighbour[k][s] = other;
      neighbour[other][t] = k;
    }
  }
  // Walk each component to an end, then along it; loops stay one at a time.
  std::vector<bool> visited(kept.size(), false);
  for (std::uint32_t start = 0; start < kept.size(); ++start) {
    if (visited[start]) continue;
    std::uint32_t end = start, from = kNone;
    bool loop = false;
    for (;;) {
      const auto& n = neighbour[end];
      const std::uint32_t next =
          n[0] != from && n[0] != kNone ? n[0] : (n[1] != from ? n[1] : kNone);
      if (next == kNone) break;
      if (next == start) {
        loop = true;
        break;
      }
      from = end;
      end = next;
    }
    if (loop) {
      // Mark the loop visited; its joints keep their one-at-a-time rows.
      std::uint32_t at = start, prev = kNone;
      do {
        visited[at] = true;
        const auto& n = neighbour[at];
        const std::uint32_t next = n[0] != prev ? n[0] : n[1];
        prev = at;
        at = next;
      } while (at != start);
      continue;
    }
    path_begin_.push_back(static_cast<std::uint32_t>(chain_joints_.size()));
    std::uint32_t at = end, prev = kNone;
    while (at != kNone) {
      visited[at] = true;
      chain_joints_.push_back(kept[at]);
      chain_positions_.push_back(kept_positions[at]);
      std::get<RevoluteJoint>(joints[kept[at]].kind).direct = true;
      const auto& n = neighbour[at];
      const int side = n[0] != prev && n[0] != kNone ? 0 : (n[1] != prev && n[1] != kNone ? 1 : -1);
      if (side < 0) {
        next_side_.push_back(0);
        next_other_side_.push_back(0);
        break;
      }
      const std::uint32_t next = n[static_cast<std::size_t>(side)];
      next_side_.push_back(static_cast<std::uint8_t>(side));
      next_other_side_.push_back(neighbour[next][0] == at ? 0 : 1);
      prev = at;
      at = next;
    }
  }
  path_begin_.push_back(static_cast<std::uint32_t>(chain_joints_.size()));
  rows_.resize(chain_joints_.size());
}

namespace {
constexpr Real kRedundantPivot = 1e-12;
}  // namespace

void JointChainSolver::warm_start(IdPool<Joint>& joints, SolverBody* bodies, std::uint32_t first,
                                  std::uint32_t last) {
  for (std::uint32_t i = path_begin_[first]; i < path_begin_[last]; ++i) {
    const Joint& joint = joints[chain_joints_[i]];
    warm_start_point(bodies, joint.frame, std::get<RevoluteJoint>(joint.kind).linear_impulse, 0);
  }
}

void JointChainSolver::solve(IdPool<Joint>& joints, SolverBody* bodies, bool use_bias,
                             std::uint32_t first, std::uint32_t last) {
  for (std::uint32_t p = first; p < last; ++p) {
    const std::uint32_t begin = path_begin_[p], end = path_begin_[p + 1];
    // Rows from the velocities before this pass (the system is solved as a whole).
    for (std::uint32_t i = begin; i < end; ++i) {
      const Joint& joint = joints[chain_joints_[i]];
      const JointFrame& f = joint.frame;
      const SolverBody& a = bodies[f.bodies[0].solver];
      const SolverBody& b = bodies[f.bodies[1].solver];
      Row& row = rows_[i];
      const CurrentAnchors anchors = current_anchors(f, a, b);
      row.ra = anchors.ra;
      row.rb = anchors.rb;
      const Vec2 cdot =
          (velocity_of(b) + cross(b.w, row.rb)) - (velocity_of(a) + cross(a.w, row.ra));
      row.diagonal = coupling(f.bodies[0], row.ra, row.ra) + coupling(f.bodies[1], row.rb, row.rb);
      const Real mass_scale = use_bias ? f.soft.mass_scale : 1;
      const Vec2 bias = use_bias ? Vec2(f.soft.bias_rate * anchors.separation) : Vec2(0, 0);
      row.rhs = -mass_scale * (cdot + bias);
    }
    for (std::uint32_t i = begin; i + 1 < end; ++i) {
      // The body joint i shares with joint i + 1, and the rows' signs on it (-1 on an A side).
      const JointFrame& f = joints[chain_joints_[i]].frame;
      const int s = next_side_[i], t = next_other_side_[i];
      const Vec2& r1 = s == 0 ? rows_[i].ra : rows_[i].rb;
      const Vec2& r2 = t == 0 ? rows_[i + 1].ra : rows_[i + 1].rb;
      const Real sign = (s == 0 ? -1 : 1) * (t == 0 ? -1 : 1);
      rows_[i].upper = sign * coupling(f.bodies[static_cast<std::size_t>(s)], r1, r2);
    }
    // Block Thomas: eliminate forward, substitute back.
    for (std::uint32_t i = begin; i < end; ++i) {
      Row& row = rows_[i];
      Mat2 pivot = row.diagonal;
      if (i > begin) {
        const Row& prev = rows_[i - 1];
        pivot -= prev.upper.transpose() * prev.eliminated;
        row.rhs -= prev.upper.transpose() * prev.rhs;
      }
      // A pivot that still vanishes against its rows' own scale is a redundancy the path's
      // making did not see (a chain closing on fixed bodies in a degenerate pose): its inverse
      // would be rounding blown up, so the row takes no share of this pass instead.
      const Real scale = row.diagonal.trace();
      const Real det = pivot.determinant();
      if (!(std::abs(det) > kRedundantPivot * scale * scale)) {
        row.eliminated.setZero();
        row.rhs.setZero();
        continue;
      }
      const Mat2 inverse = pivot.inverse();
      if (i + 1 < end) row.eliminated = inverse * row.upper;
      row.rhs = inverse * row.rhs;
    }
    for (std::uint32_t i = end - 1; i-- > begin;)
      rows_[i].rhs -= rows_[i].eliminated * rows_[i + 1].rhs;
    // Each joint's share: the solved impulse, less the soft part of what it already holds.
    for (std::uint32_t i = begin; i < end; ++i) {
      Joint& joint = joints[chain_joints_[i]];
      auto& revolute = std::get<RevoluteJoint>(joint.kind);
      const JointFrame& f = joint.frame;
      const Real impulse_scale = use_bias ? f.soft.impulse_scale : 0;
      const Vec2 impulse = rows_[i].rhs - impulse_scale * revolute.linear_impulse;
      revolute.linear_impulse += impulse;
      apply_pair(bodies[f.bodies[0].solver], bodies[f.bodies[1].solver], f, rows_[i].ra,
                 rows_[i].rb, impulse, 0);
    }
  }
}

}  // namespace mink::detail
