#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "mink/geometry/large_page_allocator.hpp"
#include "mink/geometry/types.hpp"
#include "stage_runner.hpp"

namespace mink::detail {

// The solver's number type. The solver works on small quantities relative to the step's start
// (velocities, the position and rotation change since the step began, anchors from the centre
// of mass), where single precision loses nothing that matters, while poses stay double in the
// body records (so a world far from the origin loses nothing either). Single precision halves
// the bytes the solver moves and doubles the constraints a SIMD register holds: eight lanes of
// AVX2 instead of four.
using SolverReal = float;

// Velocity state of one body during a step, as the soft-step solver sees it: velocities plus
// the position and rotation change since the step began (so contact separations can be
// updated every substep without recomputing manifolds). 32 bytes: a SIMD register's width.
struct alignas(32) SolverBody {
  SolverReal vx = 0, vy = 0, w = 0;
  // The angle turned since the step began, summed over the substeps: tells how many whole
  // turns (qc, qs) has made, for continuous collision's sweep.
  SolverReal turn = 0;
  SolverReal dpx = 0, dpy = 0;
  SolverReal qc = 1, qs = 0;  // rotation since the step began
};
static_assert(sizeof(SolverBody) == 32);

// What building constraints needs of a moving body, compactly.
struct SolverBodyInfo {
  Real cx = 0, cy = 0;  // centre of mass
  Real inv_mass = 0, inv_inertia = 0;
};

// Per-substep velocity change from gravity and forces, and damping factors.
struct SolverBodyParams {
  SolverReal dvx = 0, dvy = 0, dw = 0;
  SolverReal linear_damping = 1, angular_damping = 1;  // factors 1 / (1 + h * damping)
  // What the divergence check (divergence.cpp) needs of the body record, so that it reads
  // none in the common case: whether the body is dynamic, and whether its centre of mass lies
  // more than half max_world_coordinate from its origin.
  bool dynamic = false, far_mass_centre = false;
};

// Constraints are built once per contact per step, each field written: no default values,
// so a local one costs no stores until its fields are set (ContactConstraint{} is all zero).
struct ContactConstraintPoint {
  SolverReal ax, ay, bx, by;   // anchors from each centre of mass, for the step
  SolverReal base_separation;  // separation minus the anchors' offset along the normal
  SolverReal normal_mass, tangent_mass;
  SolverReal normal_impulse, tangent_impulse;
  SolverReal max_normal_impulse;
  SolverReal relative_velocity;  // normal approach speed when the step began (restitution)
};

struct ContactConstraint {
  std::int32_t body_a, body_b;  // indices into the solver body array
  std::int32_t point_count;
  SolverReal inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
  SolverReal nx, ny;
  SolverReal dx, dy;  // centre of A minus centre of B: anchor on B = anchor on A + (dx, dy)
  SolverReal friction, restitution;
  SolverReal bias_rate, mass_scale, impulse_scale;  // contact softness
  ContactConstraintPoint points[2];
};

// What a constraint is built from, in the solver's precision, written by the narrowphase while
// the contact is at hand (contact.hpp): the set-up then reads one line of a compact array per
// constraint, in the order the narrowphase wrote them, rather than two lines of a contact
// record. Anchors are from each body's centre of mass, worked out in double precision (a world
// far from the origin loses nothing); the point count travels with the constraint's bodies.
struct alignas(64) ContactSeed {
  SolverReal nx, ny;
  SolverReal dx, dy;  // centre of A minus centre of B
  SolverReal friction, restitution;
  struct Point {
    SolverReal ax, ay;  // from A's centre of mass
    SolverReal separation;
    SolverReal normal_impulse, tangent_impulse;
  } points[2];
};
static_assert(sizeof(ContactSeed) == 64);

// Spring softness of a constraint for a substep of length h (Box2D v3's soft step).
struct Softness {
  Real bias_rate = 0, mass_scale = 1, impulse_scale = 0;
};
Softness make_softness(Real hertz, Real damping_ratio, Real h);

// One lane of a SIMD batch as the set-up hands it to ContactSolver::build_batch: the contact's
// seed, the constraint's solver bodies and their inverse masses (zero for a body the solver
// cannot move), and, where the contact bounces, each point's normal approach speed when the
// step began.
struct BatchLane {
  const ContactSeed* seed;
  std::int32_t body_a, body_b;
  SolverReal inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
  SolverReal relative_velocity[2];
};

struct SolverSettings {
  SolverReal h = 0;  // substep length
  SolverReal inv_h = 0;
  SolverReal max_linear_speed = 0;
  SolverReal contact_push_max_velocity = 0;
  SolverReal restitution_threshold = 0;
  int substeps = 1;
  int joint_iterations = 1;
};

// kWideLanes constraints side by side, one per lane, for the wide (SIMD) path.
struct WideConstraint;
class JointStages;

struct WideMaxImpulse;
class ContactStackSolver;

// The bodies of one constraint (indices into the solver body array), and whether the solver
// can change each one's velocity (kinematic bodies and the still body it cannot: they never
// block a colour, as several lanes writing back their unchanged velocity is harmless).
struct ConstraintBodies {
  std::int32_t a = 0, b = 0;
  bool a_fixed = false, b_fixed = false;
  // From the constraint graph (kOverflowColor: one at a time; kNoColor: no constraint, an
  // entry begin() leaves out).
  std::uint8_t color = 0;
  bool hit_events = false;  // the contact's shapes ask for hit events
  std::uint8_t point_count = 0;
};

// The soft-step solver. begin() lays the constraints out by their colours from the constraint
// graph (constraint_graph.hpp): within a colour no two constraints share a moving body, so a
// colour's constraints are independent and are solved eight at a time in SIMD lanes (the
// overflow, one at a time after them). build_batch() then writes a batch's constraints
// straight into its lanes, so the step never builds a scalar copy of every constraint; set()
// writes the overflow's. solve() runs every substep: integrate
// velocities, warm start, solve with bias, integrate positions, relax without bias; then
// restitution.
class ContactSolver {
 public:
  ContactSolver();
  ~ContactSolver();
  ContactSolver(const ContactSolver&) = delete;
  ContactSolver& operator=(const ContactSolver&) = delete;
  ContactSolver(ContactSolver&&) noexcept;
  ContactSolver& operator=(ContactSolver&&) noexcept;

  // `still` is the index of the body standing in for static and sleeping bodies; constraints
  // mark it fixed, so it may be shared by any number of constraints of one colour. `wide`
  // false keeps every constraint scalar and solves them one at a time in the same colour
  // order: the slow twin the tests compare the SIMD path against (the results are bitwise
  // equal).
  // Runs on `tasks`, whose workers may then call set() at once.
  void begin(std::span<const ConstraintBodies> constraints, std::int32_t still, bool wide,
             TaskRunner& tasks);
  // Constraint `index` (as passed to begin) of the overflow, or any in scalar mode, once
  // each, from any worker (each index writes only its own slot), then finish().
  void set(std::uint32_t index, const ContactConstraint& constraint, std::uint32_t worker);
  // The constraints (indices as passed to begin) in the order of their slots: colour by
  // colour, each colour's lanes in turn. Setting them in this order fills one SIMD batch
  // after another, so the batches being written stay in cache.
  std::span<const std::uint32_t> slot_order() const noexcept { return order_; }
  // Wide mode: the SIMD batches, for a caller that fills a batch at a time, and the overflow.
  // A batch's constraints (indices as passed to begin; a colour's last batch may hold fewer
  // than kWideLanes) are built by build_batch() from their lanes, in the batch's order, all
  // lanes at once (bitwise what building each whole and set() give); the lanes past them
  // become padding (the still body, no mass). The overflow's constraints are set() whole.
  std::uint32_t batch_count() const noexcept {
    return static_cast<std::uint32_t>(batch_first_.size());
  }
  std::span<const std::uint32_t> batch(std::uint32_t batch) const noexcept;
  std::span<const std::uint32_t> overflow() const noexcept;
  // `two_points`: bit `lane` set for each lane whose constraint has two points. `soft` is the
  // softness between two moving bodies, `fixed_soft` against one the solver cannot move.
  void build_batch(std::uint32_t batch, std::span<const BatchLane> lanes, std::uint32_t two_points,
                   const Softness& soft, const Softness& fixed_soft, std::uint32_t worker);
  // The constraints (indices as passed to begin, each of the overflow) solved as contact stacks
  // (contact_stack_solver.hpp), stack after stack; `stack_begin`: where each stack starts,
  // one past the last at the end. After begin(), before finish(); none unless called.
  void set_stacks(std::span<const std::uint32_t> members,
                  std::span<const std::uint32_t> stack_begin);
  void finish();
  // `joints`, when given, runs its part of each stage before the contacts.
  // The stages run on the task runner's workers, each colour split into blocks; the result
  // does not depend on the worker count.
  void solve(std::span<SolverBody> bodies, std::span<const SolverBodyParams> params,
             const SolverSettings& settings, JointStages* joints, TaskRunner& tasks);
  // The accumulated impulses of constraint `index` after solve().
  void impulses(std::uint32_t index, SolverReal normal[2], SolverReal tangent[2]) const;

  std::size_t color_count() const noexcept;
  std::size_t overflow_count() const noexcept { return overflow_count_; }
  // The constraints of contact stacks solved together.
  std::size_t stacked_count() const noexcept;

 private:
  bool wide_mode_ = true;
  bool bouncy_ = false;  // some constraint has restitution
  std::int32_t still_ = 0;
  std::size_t overflow_count_ = 0;
  // Per constraint: where it lives. Wide mode: 4 * wide index + lane, or kScalar | index
  // into scalar_ for the overflow. Scalar mode: kScalar | index into scalar_ (colour order,
  // then the overflow), so set() and impulses() need not ask which mode they are in.
  std::vector<std::uint32_t> slot_;
  std::vector<std::uint32_t> order_;  // constraint indices by slot
  std::vector<ContactConstraint> scalar_;
  // The contact stacks: their constraints (set_stacks' indices, then finish()'s positions in
  // scalar_) and where each stack starts; per position in scalar_, whether it is in one.
  std::vector<std::uint32_t> stack_members_, stack_begin_;
  std::vector<std::uint8_t> stacked_;
  std::unique_ptr<ContactStackSolver> stack_solver_;
  std::vector<std::uint32_t> color_begin_;  // colour positions, one past the last at the end
  LargeVector<WideConstraint> wide_;
  std::vector<std::uint32_t> wide_begin_;   // into wide_, per colour
  std::vector<std::uint32_t> batch_first_;  // per wide constraint, its first lane's position
  std::vector<std::uint8_t> color_of_;
  // Per worker's run of constraints in begin(): its count, then its next position, per colour,
  // each run's on cache lines of its own.
  static constexpr std::size_t kRunColorStride = 64;
  std::vector<std::uint32_t> run_colors_;
  std::vector<WideMaxImpulse> max_impulse_;
  // Wide mode with restitution: the bouncing constraints' slots, in colour order, with what
  // restitution reads that the lanes do not hold (the rest is read back from the lanes).
  struct Bounce {
    std::uint32_t slot;
    SolverReal restitution;
    SolverReal relative_velocity[2];
  };
  std::vector<Bounce> restitution_, merged_;  // merged_: scratch for merging the workers
  // What set() finds per worker, merged by finish() in slot order.
  struct alignas(64) WorkerFindings {
    bool bouncy = false;
    std::vector<Bounce> restitution;
  };
  std::vector<WorkerFindings> findings_;
  // Restitution of one bouncing constraint of the SIMD batches (its lane read out and the
  // bounce applied one at a time; the colour's others run alongside).
  void bounce(SolverBody* bodies, const Bounce& bounce, SolverReal threshold);
  struct Stage;
  std::vector<Stage> stages_;                // one substep's stages
  std::vector<Stage> bounce_stages_;         // restitution's, once after the substeps
  std::vector<std::uint32_t> stage_blocks_;  // blocks per stage: every substep's, then those
  StageRunner stage_runner_;
};

}  // namespace mink::detail
