#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contact_solver.hpp"

namespace mink::detail {

// A direct solve for contact stacks under large mass ratios. Gauss-Seidel passes one contact
// at a time, and a light body between heavy ones passes on only its own share of their
// momentum per pass: a 1 kg box under two 1000 kg ones gives way and the stack falls (as
// Box2D v3's does at its default settings). Worse, each soft contact is a spring whose
// stiffness is its effective mass times omega^2, and a light body's contact carrying a heavy
// load sags by load / (its mass * omega^2): 14 cm at 60 Hz.
//
// Where touching bodies of very different masses meet and the contacts of the bodies linked
// to them form a path (each moving body in at most two; find_contact_stacks in
// solver_stages.cpp says why), they are a stack (up to kMaxStackRows normal rows), whose
// normal rows are solved at once in every solve and relax pass: the linear complementarity problem
// of all the rows (pushes never pull, a row that pushes stops its approach) by principal pivoting
// on the rows' exact coupling K = J M^-1 J^T. The softness is the soft step's with K in place of
// one row's effective mass: the new impulses x solve K x = ms (K lambda - v - bias), ms the row's
// mass scale, which for a lone row is exactly the one-at-a-time update. A row then sags by the
// acceleration its pushes give its two bodies apart, over omega^2, not by all the weight it
// carries over one body's mass: in a column at rest the ground's contact sags by g / omega^2
// and the others not at all. A stack whose rows repeat one another (a box on two ground
// shapes) is solved one contact at a time. The stacks' friction stays one contact at a time,
// after the normal rows, as in solve_one.
inline constexpr int kMaxStackRows = 32;
// Two touching bodies make a stack when one's inverse mass is at least this many times the
// other's; below it Gauss-Seidel carries the load well enough (a 1:100 stack stands on it).
inline constexpr double kStackMassRatio = 10;
// A body with more contacts than this is in no stack (it would be in a set too large), so a
// world whose lopsided masses are all such bodies (a heavy drum or spinner among its load)
// spends nothing looking.
inline constexpr std::size_t kMostStackBodyContacts = 4 * kMaxStackRows;

// The linear complementarity problem w = K x + q, x >= 0, w >= 0, x . w = 0, K an n x n
// symmetric positive definite matrix (row-major, n <= kMaxStackRows), by principal pivoting
// with the least-index rule (Murty's), which ends for such a K from any start. `active` (bit i:
// row i pushes, x_i basic) is the guess on entry, the answer's on return. Returns false when
// it gave up at its pivot limit; x is then the last guess's, clamped at zero.
bool solve_complementarity(std::span<const double> k, std::span<const double> q, int n,
                           std::span<double> x, std::uint32_t& active);

class ContactStackSolver {
 public:
  // `members`: the stacks' constraints (positions in `constraints`), stack after stack;
  // `stack_begin`: where each stack starts in them, one past the last at the end. Reads the
  // constraints' anchors, normals and masses, fixed for the step.
  void build(std::span<const ContactConstraint> constraints, std::span<const std::uint32_t> members,
             std::span<const std::uint32_t> stack_begin);
  // Every stack's normal rows at once, then, in the relax pass, their friction one constraint
  // at a time. Stacks share no moving body.
  void solve(SolverBody* bodies, std::span<ContactConstraint> constraints, SolverReal inv_h,
             SolverReal max_push, bool use_bias);
  // The constraints of the stacks solved together (the others' rows repeat one another).
  std::size_t direct_constraints() const noexcept { return direct_constraints_; }

 private:
  struct Stack {
    std::uint32_t member_begin, member_end;
    std::uint32_t row_begin, row_count;
    std::size_t matrix_begin;  // into matrices_: row_count^2, row-major
    std::uint32_t active;      // the last solve's pushing rows, the next one's guess
    bool direct;               // its rows independent: solved together, else one at a time
  };
  struct Row {
    std::uint32_t constraint;
    std::uint32_t point;
  };
  std::vector<Stack> stacks_;
  std::vector<std::uint32_t> members_;
  std::vector<Row> rows_;
  std::vector<double> matrices_;
  std::vector<double> q_, x_, impulses_;  // scratch, per row of a stack
  std::vector<double> shapes_, factor_;   // scratch: a stack's unit-mass coupling, its factor
  std::size_t direct_constraints_ = 0;
};

}  // namespace mink::detail
