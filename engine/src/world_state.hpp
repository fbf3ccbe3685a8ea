#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "body.hpp"
#include "constraint_graph.hpp"
#include "contact.hpp"
#include "contact_map.hpp"
#include "contact_solver.hpp"
#include "continuous.hpp"
#include "id_pool.hpp"
#include "joint.hpp"
#include "joint_solver.hpp"
#include "mink/broadphase/sweep_and_prune.hpp"
#include "mink/engine/contact_events.hpp"
#include "mink/engine/world.hpp"
#include "sensor.hpp"
#include "shape.hpp"
#include "task_runner.hpp"
#include "worker_marks.hpp"

namespace mink {

namespace detail {
// Throws InvalidArgumentError naming the first bad field (world.cpp).
void check_world_def(const WorldDef& def);
// A step's length and substeps as step() takes them: 1e-9..1e9 s, 1..max_substeps; `what`
// starts the message.
void check_step_length(Real time_step, int substeps, const std::string& what);
// Finite and within max_setting_magnitude on each axis; `what` names it in the message.
void check_gravity(const Vec2& gravity, const std::string& what);

}  // namespace detail

// Everything a World owns. Each concept's data and operations live in their own file (body,
// shape, contact, sensor, island, the solver stages); this is where they meet. The records and
// per-step arrays that a step reads scattered are LargeVectors: once a world makes them 2 MiB
// or more, they take 2 MiB pages (large_page_allocator.hpp).
struct WorldState {
  WorldDef def;
  detail::TaskRunner tasks;  // the parallel phases of a step run here
  std::uint32_t serial = 0;  // this world's number, carried by every id it issues
  detail::IdPool<detail::Body> bodies;
  detail::IdPool<detail::Shape> shapes;
  detail::IdPool<detail::Joint> joints;

  SweepAndPrune broadphase{detail::kBroadphaseFattening};
  PairEvents pair_events;
  // Proxies of destroyed shapes are released at the start of the next step, before the pair
  // update, so a proxy id is never reused within one pair-update cycle.
  std::vector<ProxyId> pending_proxy_destroys;

  LargeVector<detail::Contact> contacts;
  LargeVector<detail::ContactImpulses> contact_impulses;  // per contact (contact.hpp)
  detail::ContactMap contact_index;
  // Where each contact is listed in its bodies' contact lists ([0]: body_a's, [1]: body_b's),
  // so removing it edits the lists in place rather than searching them (a static body holding
  // a ring of chain segments lists a thousand). Derived: rebuilt when a snapshot is loaded.
  LargeVector<std::array<std::uint32_t, 2>> contact_slots;
  std::vector<detail::SensorState> sensors;  // sorted by sensor shape slot
  std::size_t touching_count = 0;            // contacts whose touching flag is set
  detail::ConstraintGraph graph;
  std::vector<std::uint32_t> newly_acting;  // contacts waiting for a colour

  // Bodies that may be awake (every awake body is here; stale entries are dropped once a
  // step): a step visits these and their contacts only, so a sleeping island costs nothing.
  LargeVector<std::uint32_t> awake_list;
  // Whether compact_awake_list would change nothing: no entry added, put to sleep, made
  // static, disabled or destroyed since it last ran. Not state: compacting a compact list
  // leaves it as it is, so a restored world, which starts with it false, steps the same.
  bool awake_list_compact = false;
  LargeVector<std::uint32_t> step_contacts;  // contacts of moving bodies this step, in order
  // One bit per contact: marked from the moving bodies' contact lists and read off in order
  // into step_contacts (no sort, and the contacts of sleeping bodies are never touched).
  detail::WorkerMarks step_contact_marks;
  std::vector<std::uint8_t> collide_changes;  // per step contact: what collide() must update
  // Per step contact, as collide() left it: what the island pass and the solver's gathering
  // of constraints read, so those serial passes stay off the contact records. Valid while
  // step_contacts is the list collide() worked through (the island pass may add woken
  // contacts to it).
  struct StepContactKey {
    std::uint32_t body_a, body_b;
    std::uint8_t color;
    std::uint8_t point_count;  // acting when it has manifold points
    bool a_fixed, b_fixed, touching, hit_events;
    bool acting() const { return point_count > 0; }
  };
  StepContactKey step_contact_key(const detail::Contact& c) const {
    return {c.body_a,  c.body_b,  c.color,    static_cast<std::uint8_t>(c.manifold.point_count),
            c.a_fixed, c.b_fixed, c.touching, c.hit_events};
  }
  LargeVector<StepContactKey> step_contact_keys;
  // Per step contact with manifold points, what its constraint is built from (contact.hpp);
  // current whenever the keys are.
  LargeVector<detail::ContactSeed> step_contact_seeds;
  bool step_contact_keys_valid = false;
  // The keys of step_contacts as they are now: collide()'s, or read again from the contacts
  // when the list changed since (the seeds with them).
  const LargeVector<StepContactKey>& current_step_contact_keys();
  detail::ContactSeed step_contact_seed(std::uint32_t contact) const {
    const detail::Contact& c = contacts[contact];
    return detail::contact_seed(c, contact_impulses[contact], bodies[c.body_a].center,
                                bodies[c.body_b].center);
  }

  std::vector<ContactBeginEvent> begin_events;
  std::vector<ContactEndEvent> end_events;
  std::vector<ContactHitEvent> hit_events;
  std::vector<SensorBeginEvent> sensor_begin_events;
  std::vector<SensorEndEvent> sensor_end_events;
  std::vector<BodyMoveEvent> move_events;
  std::vector<JointBreakEvent> joint_break_events;
  std::vector<BodyStoppedEvent> stopped_events;
  std::vector<std::uint32_t> fell_asleep;  // bodies the last step put to sleep
  StepCounters counters;
  StepProfile profile;

  Recorder* recorder = nullptr;  // World::set_recorder's, not state
  int call_depth = 0;            // World calls under way: only the outermost is recorded

  Real time = 0;
  Real accumulator = 0;
  std::uint64_t step_count = 0;
  std::uint32_t next_chain = 0;
  // The step being run: WorldDef's by default, or what step(dt, substeps) asked for.
  Real dt = 0;
  int substeps = 1;

  // Step scratch, kept to avoid allocating every step.
  LargeVector<detail::SolverBody> solver_bodies;
  LargeVector<detail::SolverBodyParams> solver_params;
  LargeVector<std::uint32_t> solver_to_body;
  LargeVector<std::int32_t> body_solver_index;
  // Per solver body, this step: whether a shape's box left its broadphase box (found while the
  // body's records are at hand, so the broadphase's serial update visits only those).
  std::vector<std::uint8_t> boxes_left;
  // Per solver body while the step's joints finish: the angle it turned in the step, counting
  // whole turns (delta_angle), taken once per body rather than once per joint.
  std::vector<Real> solver_turned;
  std::vector<std::uint8_t> hit_marks;  // per constraint: whether it is a hit (solve)
  // Per solver body, this step: 1 where the solve diverged on it, 2 where it is stopped with
  // one that did (stop_diverged); empty when every solve held.
  std::vector<std::uint8_t> stopped;
  LargeVector<detail::SolverBodyInfo> solver_info;
  LargeVector<detail::ConstraintBodies> constraint_bodies;  // per step contact
  // Per worker while solver bodies load: the least and greatest inverse mass of the dynamic
  // bodies it loaded (contact stacks are looked for only where they differ enough).
  struct InverseMassRange {
    Real least = std::numeric_limits<Real>::infinity(), greatest = 0;
  };
  std::vector<InverseMassRange> inverse_mass_ranges;
  // Finding the contact stacks (find_contact_stacks): per solver body its inverse mass, in a
  // compact array (NaN for a body in no stack); the constraints between lopsided moving
  // bodies, marked as they are made; per solver body whether a walk met it (none yet, in a
  // stack, or in a set that is none); the stacks' constraints and where each stack starts;
  // the walk's scratch.
  std::vector<float> solver_inv_mass;
  detail::WorkerMarks lopsided_marks;
  std::vector<std::uint8_t> stack_seen;
  std::vector<std::uint32_t> stack_members, stack_begin, stack_walk, stack_found;
  detail::ContactSolver contact_solver;
  std::int32_t still_body = 0;                   // the solver body standing in for the unmoving
  std::vector<std::uint32_t> step_joints;        // joints of moving bodies this step, solve order
  std::vector<std::uint32_t> joint_color_begin;  // where each colour starts in step_joints
  detail::WorkerMarks joint_marks;               // one bit per joint slot, while gathering
  std::vector<std::uint8_t> joint_slot_color;    // per joint slot: its colour, while gathering
  std::vector<std::uint32_t> joint_order;        // step_joints in slot order
  std::vector<std::uint32_t> joint_position;     // per joint_order entry: its place in step_joints
  std::vector<std::uint32_t> joint_fill;
  std::vector<std::uint8_t> joint_broke;       // per joint_order entry, while finishing
  std::vector<std::uint32_t> joint_own_slots;  // per step joint: its first own solver record
  detail::JointStages joint_stages;
  std::vector<detail::JointBodies> joint_bodies;  // per joint slot; see set_joint_bodies
  std::vector<std::uint64_t> island_stamp;        // per body: the step whose island pass reached it
  std::vector<std::uint32_t> island_stack, island_members, woken;
  std::vector<std::uint32_t> island_parent;  // union-find over bodies, while finding islands
  std::vector<Real> island_sleep;            // per island root: its members' shortest rest
  std::vector<ProxyId> query_scratch;
  detail::ContinuousState continuous;

  detail::Body& body(BodyId id) { return bodies.get(id, serial, "body"); }
  const detail::Body& body(BodyId id) const { return const_cast<WorldState*>(this)->body(id); }
  detail::Shape& shape(ShapeId id) { return shapes.get(id, serial, "shape"); }
  const detail::Shape& shape(ShapeId id) const { return const_cast<WorldState*>(this)->shape(id); }
  ShapeId shape_id(std::uint32_t index) const { return {index, shapes[index].generation, serial}; }
  BodyId body_id(std::uint32_t index) const { return {index, bodies[index].generation, serial}; }
  detail::Joint& joint(JointId id) { return joints.get(id, serial, "joint"); }
  const detail::Joint& joint(JointId id) const { return const_cast<WorldState*>(this)->joint(id); }
  JointId joint_id(std::uint32_t index) const { return {index, joints[index].generation, serial}; }

  void clear_events();
  // body.cpp
  void wake(detail::Body& body);
  void add_to_awake_list(detail::Body& body);
  void compact_awake_list();
  void update_mass(detail::Body& body);
  // shape.cpp
  // A fast body's shapes leave a step with their bare box (with_margin false; see finish_body).
  void update_shape_aabb(detail::Shape& shape, const detail::Body& body, bool with_margin = true);
  Aabb shape_box(const detail::Shape& shape, const detail::Body& body, bool with_margin) const;
  // A snapshot holds the boxes, not which are bare: found again from them.
  void find_bare_boxes();
  void create_proxy(std::uint32_t shape_index);
  void destroy_proxy(detail::Shape& shape);
  // Re-makes the shape's broadphase proxy, so every pair it is in is tested again next step
  // (after a filter, type or enable change); its contacts end now.
  void refresh_proxy(std::uint32_t shape_index);
  // seam.cpp
  void update_seams(std::uint32_t shape_index, bool removing);
  bool smooth_seam(detail::Contact& contact, const Pose& pose_a, const Pose& pose_b,
                   Real speculative_distance) const;
  // contact.cpp
  void destroy_contact(std::uint32_t index);
  void remove_contact_from(std::uint32_t body, std::uint32_t slot, bool other_fixed);
  void rebuild_contact_slots();
  void set_touching(detail::Contact& contact, bool touching);
  // Gives a contact its graph colour when it starts to have points (at the end of collide, in
  // a fixed order) and takes it back when it has none.
  void update_color(std::uint32_t contact_index);
  void assign_new_colors();
  void destroy_shape_contacts(std::uint32_t shape_index);
  void destroy_contacts_between(std::uint32_t body_a, std::uint32_t body_b);
  bool should_make_contact(std::uint32_t shape_a, std::uint32_t shape_b) const;
  void update_pairs();
  // Marks the body's contacts for this step; collect_step_contacts lists the marked ones.
  void mark_step_contacts(const detail::Body& body, std::uint32_t worker = 0);
  void collect_step_contacts();
  bool update_manifold(detail::Contact& contact, detail::ContactImpulses& impulses) const;
  void collide();
  // sensor.cpp
  void update_sensors();
  bool crossed_in_step(const detail::Shape& sensor, const Pose& sensor_pose,
                       const detail::FastBody& fast, const detail::Shape& visitor) const;
  void destroy_sensor(std::uint32_t shape_index);
  // island.cpp
  void update_islands();
  void join_woken_contacts();
  // joint.cpp
  void destroy_joint(std::uint32_t index);
  // Copies the joint's bodies to joint_bodies (none while the slot is free).
  void set_joint_bodies(std::uint32_t index);
  // Gives the joint back its colour and takes one again with its bodies' current types.
  void recolor_joint(std::uint32_t index);
  // True when a joint between the two bodies keeps their shapes from colliding.
  bool joint_prevents_contact(std::uint32_t body_a, std::uint32_t body_b) const;
  detail::JointBodyState joint_body_state(std::uint32_t body) const;
  detail::JointBodyState finished_body_state(std::uint32_t body) const;
  Real finished_turn(std::uint32_t body) const;  // its solver_turned; 0 if the solver left it
  // The joint's free coordinate and its rate now (World::joint_coordinate, joint_speed).
  Real joint_coordinate(std::uint32_t index) const;
  Real joint_speed(std::uint32_t index) const;
  void wake_joint_bodies(std::uint32_t index);
  // joint_solver.cpp
  void prepare_joints();
  // Prepares joint `index` (at `position` of the step's order) for the step; a plain pin,
  // when `may_pin`, straight into the joint stages' pin row, which it then returns true for.
  bool prepare_joint(std::uint32_t index, std::uint32_t position, std::uint32_t own_slot, Real h,
                     const detail::Softness& soft, bool may_pin);
  void finish_joints();
  void finish_joint(std::uint32_t k, Real inv_h);  // joint_order[k]; substeps of 1 / inv_h
  // solver_stages.cpp
  void prepare_contacts();
  // The step's contact stacks (contact_stack_solver.hpp), their constraints moved to the
  // overflow; none unless `possible` (bodies 10 times apart in mass that could be in one), in
  // which case prepare_contacts has marked the lopsided constraints.
  void find_contact_stacks(bool possible);
  void solve();
  // Solver body `solver_index`'s velocity and pose back into its body record.
  void write_back(std::uint32_t solver_index);
  // divergence.cpp: after the solve, the bodies it diverged on, and those joined to them,
  // back to where the step began, at rest; and whether a solver body was so stopped.
  void stop_diverged();
  bool solve_diverged(std::uint32_t solver_index, Real max_speed, Real max_angular_speed) const;
  bool stopped_in_step(std::int32_t solver_index) const {
    // The unmoving solver body (still_body) lies past the moving ones, and is never stopped.
    return solver_index >= 0 && static_cast<std::size_t>(solver_index) < stopped.size() &&
           stopped[static_cast<std::size_t>(solver_index)] != 0;
  }
  void finish_body(std::uint32_t solver_index, std::uint32_t worker);
  void finish_step();
  // continuous.cpp (before finish_step: it needs the step's solver records)
  void solve_continuous();
  // From finish_body: whether the step moved the body fast (continuous collision sweeps it).
  bool moved_fast(std::uint32_t solver_index) const;
  void prefetch_finish_ahead(std::size_t k, std::size_t end, const std::uint8_t* only) const;
  void record_fast_body(std::uint32_t solver_index, const Aabb& swept, bool covered,
                        std::uint32_t worker);
  const std::vector<std::uint32_t>& fixed_candidates(std::uint32_t fast_body, const Aabb& box,
                                                     bool covered, bool bullet,
                                                     std::uint32_t worker);
  Vec2 quick_shapes(std::uint32_t solver_index, std::uint32_t worker);
  std::uint64_t passing_shapes(const detail::Body& fast_body,
                               const std::vector<detail::QuickShape>& quick,
                               const ShapeGeometry& still, const Pose& still_pose) const;
  bool passes_unswept(std::uint32_t solver_index, const Aabb& box, bool covered,
                      std::uint32_t worker);
  void prefetch_pair(const detail::Contact& c) const;
  void prefetch_hulls(const detail::Contact& c) const;
  Vec2 start_center(std::uint32_t solver_index) const;
  Sweep solver_sweep(std::uint32_t solver_index) const;
  Sweep body_sweep(std::uint32_t body) const;
  void sweep_pair(detail::FastBody& fast, const detail::LocalSweep& local,
                  std::uint32_t other_shape, const detail::FramedSweep& other,
                  std::uint64_t settled) const;
};

}  // namespace mink
