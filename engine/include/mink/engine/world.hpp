#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "mink/broadphase/aabb.hpp"
#include "mink/byte_stream.hpp"
#include "mink/engine/body_def.hpp"
#include "mink/engine/contact_events.hpp"
#include "mink/engine/debug_draw.hpp"
#include "mink/engine/filter.hpp"
#include "mink/engine/ids.hpp"
#include "mink/engine/joint_def.hpp"
#include "mink/engine/recorder.hpp"
#include "mink/engine/shape_def.hpp"
#include "mink/engine/world_def.hpp"
#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/ray_cast.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

namespace mink {

struct WorldState;
namespace detail {
class RecordScope;
}  // namespace detail

/// @brief A World::ray_cast hit: which shape, and where.
struct ShapeRayHit {
  ShapeId shape;  ///< the shape hit first
  RayHit hit;     ///< where, in world coordinates
};

/// @brief A World::cast_shape hit: which shape stopped the cast, and where.
struct ShapeCastHit {
  ShapeId shape;      ///< the shape met first
  Real fraction = 0;  ///< of the translation, at the first touch (0: touching at the start)
  Vec2 point{0, 0};   ///< on that shape's surface, world
  /// Unit, from that shape towards the cast one; zero when the two overlap deeper than their
  /// rounding at the start (fraction 0), where no direction separates them.
  Vec2 normal{0, 0};
};

/// @brief The chain a chain segment belongs to (World::shape_chain).
struct ChainMembership {
  std::uint32_t chain = 0;  ///< the create_chain call that made it, numbered from 0
  bool loop = false;        ///< that chain closes on itself
};

/// @brief What World::advance did.
struct AdvanceResult {
  int steps = 0;  ///< fixed steps run by this call
  /// Leftover time / time step, in [0, 1): World::interpolated_pose(id, alpha) blends each
  /// body's pose before and after the last step by it, for smooth drawing between steps.
  Real alpha = 0;
};

/// A 2D rigid-body world: bodies with shapes of every kind (circles, capsules, segments, chains,
/// rounded polygons), a sweep-and-prune broadphase, GJK-based manifolds and a soft-step solver.
/// Every call is deterministic. Any id argument that does not name a live object of this world
/// (ids carry their world) throws StaleIdError naming the id.
class World {
 public:
  /// @brief Creates an empty world.
  /// @throws InvalidArgumentError naming the first bad field of `def`.
  explicit World(const WorldDef& def = {});
  ~World();
  /// @brief Worlds move (ids stay valid in the moved-to world) but do not copy.
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// @brief The settings in force (set_gravity and enable_sleep update them).
  const WorldDef& def() const noexcept;
  /// @brief Gravity acceleration, world frame (m/s^2).
  /// @throws InvalidArgumentError when not finite.
  void set_gravity(const Vec2& gravity);
  /// @brief Turns sleeping on or off; turning it off wakes every body.
  void enable_sleep(bool enabled);

  /// @name Bodies and shapes
  /// Destruction is allowed at any time between steps: contacts of the destroyed shapes end
  /// (with end events when they touched) and their neighbours wake.
  /// @{

  /// @brief Adds a body with no shapes (so no mass yet).
  /// @throws InvalidArgumentError naming a non-finite or negative field of `def`.
  BodyId create_body(const BodyDef& def);
  /// @brief Destroys the body and all its shapes; `id` and their ids become stale.
  void destroy_body(BodyId id);
  /// @brief Attaches a shape (a polygon's `points` are hulled here); the body's mass is updated.
  /// @throws StaleIdError for a dead `body`; InvalidArgumentError (or a hull error) for a bad
  /// `def`, for a chain (use create_chain), and for a shape whose positive mass or inertia is
  /// below min_mass_property.
  ShapeId create_shape(BodyId body, const ShapeDef& def);
  /// @brief Attaches a chain: one one-sided segment shape per chain edge, in order, each with
  /// its neighbours as ghost vertices. `def.type` must be ShapeType::chain.
  /// @throws StaleIdError for a dead `body`; InvalidArgumentError for a bad `def`.
  std::vector<ShapeId> create_chain(BodyId body, const ShapeDef& def);
  /// @brief Detaches and destroys the shape; `id` becomes stale.
  void destroy_shape(ShapeId id);
  /// @brief True when `id` names a live body of this world.
  bool is_valid(BodyId id) const noexcept;
  /// @brief True when `id` names a live shape of this world.
  bool is_valid(ShapeId id) const noexcept;
  /// @brief Number of live bodies.
  std::size_t body_count() const noexcept;
  /// @brief Number of live shapes.
  std::size_t shape_count() const noexcept;
  std::vector<BodyId> bodies() const;  ///< live bodies in slot order

  /// @}

  /// @name Body state
  /// Position is the body origin; the centre of mass is world_center.
  /// @{

  /// @brief Static, kinematic or dynamic.
  BodyType body_type(BodyId id) const;
  /// @brief World position of the body origin.
  Vec2 position(BodyId id) const;
  /// @brief Orientation in radians, counter-clockwise.
  Real angle(BodyId id) const;
  /// @brief Position and rotation together: maps body-local points to world.
  Pose pose(BodyId id) const;
  /// @brief Centre of mass in world coordinates.
  Vec2 world_center(BodyId id) const;
  /// @brief Centre of mass in body-local coordinates.
  Vec2 local_center(BodyId id) const;
  /// @brief Velocity of the centre of mass, world frame (m/s).
  Vec2 linear_velocity(BodyId id) const;
  /// @brief Angular velocity in rad/s, counter-clockwise positive.
  Real angular_velocity(BodyId id) const;
  /// @brief Mass in kg from the shapes' areas and densities. 0 for static and kinematic
  /// bodies; a dynamic body with no massive shape gets 1 (and no rotational inertia).
  Real mass(BodyId id) const;
  Real rotational_inertia(BodyId id) const;  ///< about the centre of mass
  /// @brief As given in BodyDef::linear_damping.
  Real linear_damping(BodyId id) const;
  /// @brief As given in BodyDef::angular_damping.
  Real angular_damping(BodyId id) const;
  /// @brief As given in BodyDef::gravity_scale.
  Real gravity_scale(BodyId id) const;
  /// @brief As given in BodyDef::allow_sleep.
  bool allow_sleep(BodyId id) const;
  /// @brief False while the body sleeps.
  bool is_awake(BodyId id) const;
  /// @brief As given in BodyDef::user_data.
  std::uint64_t user_data(BodyId id) const;
  /// @brief The body's live shapes.
  std::vector<ShapeId> body_shapes(BodyId id) const;
  /// @brief False while the body is disabled (kept, but neither simulated nor collided).
  bool is_enabled(BodyId id) const;
  /// @brief True when the body never rotates.
  bool fixed_rotation(BodyId id) const;
  /// @brief True when the body is a bullet (continuous collision against dynamic bodies too).
  bool is_bullet(BodyId id) const;
  /// @brief BodyDef::continuous_threshold: when a step's motion counts as fast.
  Real continuous_threshold(BodyId id) const;
  /// @brief Mass, centre (body-local) and rotational inertia in force.
  MassData mass_data(BodyId id) const;
  /// @brief The body's pose blended between before and after the last step: `alpha` 0 gives
  /// the pose before it, 1 the current one (see AdvanceResult::alpha).
  Pose interpolated_pose(BodyId id, Real alpha) const;
  /// @brief The body's contacts that have manifold points, in contact order.
  std::vector<ContactData> body_contacts(BodyId id) const;

  /// @}

  /// @name Moving bodies
  /// Setters wake the body. Non-finite arguments throw InvalidArgumentError naming the body.
  /// Forces, torques and impulses on non-dynamic bodies are ignored.
  /// @{

  /// @brief Moves the body origin to `position` (world) at `angle` (radians) without velocity
  /// (a teleport).
  void set_transform(BodyId id, const Vec2& position, Real angle);
  /// @brief Velocity of the centre of mass, world frame (m/s).
  void set_linear_velocity(BodyId id, const Vec2& velocity);
  /// @brief Angular velocity in rad/s, counter-clockwise positive.
  void set_angular_velocity(BodyId id, Real velocity);
  /// @brief A force (N, world frame) at a world point, applied during the next step only.
  void apply_force(BodyId id, const Vec2& force, const Vec2& world_point);  ///< until next step
  /// @brief A torque (N m) applied during the next step only.
  void apply_torque(BodyId id, Real torque);
  /// @brief Changes the velocity at once by an impulse (N s, world frame) at a world point.
  void apply_linear_impulse(BodyId id, const Vec2& impulse, const Vec2& world_point);
  /// Wakes the body, or puts a dynamic body to sleep (its velocity is zeroed). No effect on
  /// static bodies.
  void set_awake(BodyId id, bool awake);
  /// @brief Static, kinematic or dynamic; mass is recomputed, contacts are re-made next step.
  void set_body_type(BodyId id, BodyType type);
  /// @brief Disables (removes from simulation and collision, keeping it) or enables a body.
  void set_enabled(BodyId id, bool enabled);
  /// @brief Locks (or unlocks) rotation; the angular velocity is zeroed when locking.
  void set_fixed_rotation(BodyId id, bool fixed);
  /// @brief Marks the body as a bullet (continuous collision against dynamic bodies too).
  void set_bullet(BodyId id, bool bullet);
  /// @brief See BodyDef::continuous_threshold.
  /// @throws InvalidArgumentError for a negative or NaN threshold
  void set_continuous_threshold(BodyId id, Real threshold);
  /// Sets a kinematic body's velocities so that it reaches `position`, `angle` at the end of
  /// the next step of `time_step` seconds run with WorldDef::substeps (moving platforms that
  /// follow a path). Turns of less than a quarter turn per substep are reached.
  /// @throws InvalidArgumentError for a body that is not kinematic or non-finite arguments.
  void set_target_transform(BodyId id, const Vec2& position, Real angle, Real time_step);
  /// Overrides the mass properties the shapes give (a dynamic body only); kept until a shape
  /// is added or removed or set_shape_density is called.
  /// @throws InvalidArgumentError for a negative or non-finite mass or inertia, or a positive
  /// one below min_mass_property.
  void set_mass_data(BodyId id, const MassData& mass);

  /// @}

  /// @name Shapes
  /// @{

  /// @brief The body the shape is attached to.
  BodyId shape_body(ShapeId id) const;
  /// @brief What kind of shape it is (a chain's segments report ShapeType::chain).
  ShapeType shape_type(ShapeId id) const;
  /// @brief The shape's geometry in body-local coordinates.
  const ShapeGeometry& shape_geometry(ShapeId id) const;
  /// @brief A polygon's hull (its core), in body-local coordinates (scale already applied).
  /// @throws InvalidArgumentError when the shape is not a polygon.
  const ConvexHull& shape_hull(ShapeId id) const;
  /// @brief Circle and capsule radius, polygon rounding; 0 for segments and chains.
  Real shape_radius(ShapeId id) const;
  /// @brief The shape's collision filter.
  const Filter& shape_filter(ShapeId id) const;
  /// @brief True for a sensor.
  bool is_sensor(ShapeId id) const;
  /// @brief As given in ShapeDef::user_data.
  std::uint64_t shape_user_data(ShapeId id) const;
  /// @brief As given in ShapeDef::enable_contact_events.
  bool shape_contact_events(ShapeId id) const;
  /// @brief As given in ShapeDef::enable_sensor_events.
  bool shape_sensor_events(ShapeId id) const;
  /// @brief As given in ShapeDef::enable_hit_events.
  bool shape_hit_events(ShapeId id) const;
  /// @brief For a chain's segment: which create_chain call made it (numbered from 0 in each
  /// world) and whether that chain loops; nothing for other shapes.
  std::optional<ChainMembership> shape_chain(ShapeId id) const;
  /// @brief Changes the density; the body's mass is recomputed.
  /// @throws InvalidArgumentError for a negative or non-finite density, or one that gives the
  /// shape a positive mass or inertia below min_mass_property.
  void set_shape_density(ShapeId id, Real density);
  /// @brief Changes the friction of the shape and of its existing contacts.
  /// @throws InvalidArgumentError outside [0, max_setting_magnitude]
  void set_shape_friction(ShapeId id, Real friction);
  /// @brief Changes the restitution of the shape and of its existing contacts.
  /// @throws InvalidArgumentError outside [0, max_setting_magnitude]
  void set_shape_restitution(ShapeId id, Real restitution);
  /// @brief Changes the filter; the shape's pairs are tested again in the next step.
  void set_shape_filter(ShapeId id, const Filter& filter);
  /// @brief As given in ShapeDef::density (kg/m^2).
  Real shape_density(ShapeId id) const;
  /// @brief As given in ShapeDef::friction.
  Real shape_friction(ShapeId id) const;
  /// @brief As given in ShapeDef::restitution.
  Real shape_restitution(ShapeId id) const;
  /// @brief The algorithm that built the hull.
  HullAlgorithm shape_algorithm(ShapeId id) const;
  /// @brief World-space bounding box of the shape.
  Aabb shape_aabb(ShapeId id) const;  ///< tight, at the current pose

  /// @}

  /// @name Joints
  /// A joint is destroyed with either of its bodies (and a gear with either of its joints).
  /// Creating or destroying one wakes its bodies. Settings take effect at the next step.
  /// @{

  /// @brief Adds a joint of the definition's kind.
  /// @throws StaleIdError for a dead body or joint named by `def`; InvalidArgumentError naming
  /// the first bad field (the same body twice, a non-finite value, a negative max force,
  /// lower > upper, a gear on a joint that is neither revolute nor prismatic...).
  JointId create_joint(const JointDef& def);
  /// @brief Destroys the joint (and gears built on it); `id` becomes stale.
  void destroy_joint(JointId id);
  /// @brief True when `id` names a live joint of this world.
  bool is_valid(JointId id) const noexcept;
  /// @brief Number of live joints.
  std::size_t joint_count() const noexcept;
  std::vector<JointId> joints() const;  ///< live joints in slot order
  /// @brief The body's live joints, in slot order.
  std::vector<JointId> body_joints(BodyId id) const;
  JointType joint_type(JointId id) const;  ///< which kind
  /// @brief The joint's current settings (setters below change them), in its kind's definition.
  JointDef joint_def(JointId id) const;
  BodyId joint_body_a(JointId id) const;  ///< for a gear: B of its first joint
  BodyId joint_body_b(JointId id) const;  ///< for a gear: B of its second joint
  /// @brief Anchor on A in world coordinates (a motor joint: A's origin; a gear: A's centre).
  Vec2 joint_anchor_a(JointId id) const;
  /// @brief Anchor on B in world coordinates.
  Vec2 joint_anchor_b(JointId id) const;
  /// @brief Constraint force the joint put on body B during the last step (N, world frame).
  Vec2 joint_force(JointId id) const;
  /// @brief Constraint torque the joint put on body B during the last step (N m).
  Real joint_torque(JointId id) const;
  /// The joint's free coordinate now: revolute angle (radians, counted through full turns),
  /// prismatic and wheel translation, distance and pulley length (pulley: length_a +
  /// ratio * length_b), a gear's coordinate1 + ratio * coordinate2, 0 for the others.
  Real joint_coordinate(JointId id) const;
  /// @brief The coordinate's rate of change now (rad/s or m/s), 0 where it has none.
  Real joint_speed(JointId id) const;

  /// The motor of a revolute, prismatic, distance or wheel joint.
  /// @throws InvalidArgumentError for other kinds, or (setter) negative or non-finite values.
  JointMotor joint_motor(JointId id) const;
  void set_joint_motor(JointId id, const JointMotor& motor);
  /// The spring of a revolute, prismatic, distance or wheel joint.
  /// @throws InvalidArgumentError for other kinds, or (setter) negative or non-finite values.
  JointSpring joint_spring(JointId id) const;
  void set_joint_spring(JointId id, const JointSpring& spring);
  /// The limit of a revolute, prismatic, distance or wheel joint.
  /// @throws InvalidArgumentError for other kinds, or (setter) lower > upper, non-finite values.
  JointLimit joint_limit(JointId id) const;
  void set_joint_limit(JointId id, const JointLimit& limit);
  /// @brief A distance joint's rest length.
  /// @throws InvalidArgumentError for other kinds or a length that is not positive and finite.
  void set_distance_length(JointId id, Real length);
  /// @brief A motor joint's target: B's origin in A's frame and B's angle relative to A.
  /// @throws InvalidArgumentError for other kinds or non-finite values.
  void set_motor_target(JointId id, const Vec2& linear_offset, Real angular_offset);
  /// @brief A motor joint's force and torque bounds.
  /// @throws InvalidArgumentError for other kinds or negative or non-finite values.
  void set_motor_limits(JointId id, Real max_force, Real max_torque);
  /// @brief A weld joint's stiffness (hertz 0: rigid).
  /// @throws InvalidArgumentError for other kinds or negative or non-finite values.
  void set_weld_springs(JointId id, Real linear_hertz, Real linear_damping_ratio,
                        Real angular_hertz, Real angular_damping_ratio);
  /// @brief Break thresholds (see JointBase::break_force), +infinity for none.
  /// @throws InvalidArgumentError for negative or NaN values.
  void set_joint_break(JointId id, Real force, Real torque);

  /// @}

  /// @name Time stepping
  /// @{

  /// @brief Runs exactly one fixed step of WorldDef::time_step; events then cover that step.
  void step();  ///< exactly one fixed step
  /// @brief Runs one step of `time_step` seconds with `substeps` substeps (for callers that
  /// drive their own clock); events then cover that step.
  /// @throws InvalidArgumentError unless time_step > 0 and finite and substeps >= 1.
  void step(Real time_step, int substeps);
  /// Runs the whole steps that fit in the accumulated time (at most max_steps_per_advance).
  /// Events then cover every step the call ran.
  /// @param frame_seconds wall time since the last call, added to the accumulated time
  /// @throws InvalidArgumentError when `frame_seconds` is negative or not finite.
  AdvanceResult advance(Real frame_seconds);
  /// @brief Simulated time in seconds: step_count() times the time step.
  Real time() const noexcept;
  /// @brief Fixed steps run since the world was made.
  std::uint64_t step_count() const noexcept;

  /// @}

  /// @name What the last step (or advance) saw
  /// @{

  /// @brief Shape pairs that started touching.
  std::span<const ContactBeginEvent> contact_begin_events() const noexcept;
  /// @brief Shape pairs that stopped touching (or lost a shape).
  std::span<const ContactEndEvent> contact_end_events() const noexcept;
  /// @brief Contacts that began faster than WorldDef::hit_event_threshold.
  std::span<const ContactHitEvent> contact_hit_events() const noexcept;
  /// @brief Shapes that began overlapping a sensor, in (sensor, visitor) slot order.
  std::span<const SensorBeginEvent> sensor_begin_events() const noexcept;
  /// @brief Shapes that stopped overlapping a sensor, in (sensor, visitor) slot order.
  std::span<const SensorEndEvent> sensor_end_events() const noexcept;
  /// @brief Joints whose force or torque exceeded their break thresholds, in joint slot order.
  std::span<const JointBreakEvent> joint_break_events() const noexcept;
  /// @brief Bodies that moved (were simulated) or fell asleep, in body slot order (an
  /// advance of several steps: step by step, each in body slot order).
  std::span<const BodyMoveEvent> body_move_events() const noexcept;
  /// @brief Bodies the step stopped because its solve diverged on them or on bodies joined to
  /// them (BodyStoppedEvent), in body slot order; empty when every solve held.
  std::span<const BodyStoppedEvent> body_stopped_events() const noexcept;
  /// @brief Pair, contact, island and solver counts.
  const StepCounters& counters() const noexcept;
  /// @brief Wall time per phase, in milliseconds.
  const StepProfile& profile() const noexcept;

  /// @}

  /// @name Queries
  /// Against the current poses, exact (not just the broadphase boxes). Shapes come in slot
  /// order; all coordinates are world.
  /// @{

  /// @brief Shapes that overlap `box`.
  std::vector<ShapeId> query_aabb(const Aabb& box) const;
  /// @brief Solid shapes that contain `point` (boundary included).
  std::vector<ShapeId> query_point(const Vec2& point) const;
  /// @brief Closest hit along origin -> origin + translation, if any.
  std::optional<ShapeRayHit> ray_cast(const Vec2& origin, const Vec2& translation) const;
  /// @brief The shape `def` describes (its geometry; density and materials do not matter),
  /// placed at `pose` and moved without turning along `translation`: the first solid shape
  /// it meets (sensors and shapes `filter` does not collide with are passed through), stopping
  /// the linear slop short of it, as a body swept by continuous collision does. A shape
  /// touching or overlapping something at the start hits it at fraction 0.
  /// @throws InvalidArgumentError for a bad shape, pose or translation
  std::optional<ShapeCastHit> cast_shape(const ShapeDef& def, const Pose& pose,
                                         const Vec2& translation, const Filter& filter = {}) const;

  /// @}

  /// @name Snapshots
  /// A snapshot is the whole simulation state as bytes: bodies, shapes, joints, contacts with
  /// their warm-start impulses and feature ids, sleep timers, constraint colours, the
  /// broadphase's order, the id pools with their free lists and generations, the step count
  /// and the time advance() has accumulated. A world restored from one continues bitwise as
  /// the world it was taken from would have, at any worker count: the worker settings are
  /// not part of it. Snapshots carry a format version, a fingerprint of the build (number
  /// type, byte order, record layouts) and a checksum; they are for this build of the engine,
  /// not an archive format (scene files are).
  /// @{

  /// @brief The whole state, as bytes restore() and from_snapshot() take.
  std::vector<std::uint8_t> snapshot() const;
  /// Rolls the world back (or forward) to `snapshot`, in place: ids issued before the
  /// snapshot was taken name the same objects again; ids of objects made after it are stale
  /// (until their slot is reused). Events and counters are cleared; the worker settings stay.
  /// @throws SnapshotError naming what is wrong (another format version or build, truncated
  /// at byte N, a checksum mismatch, a corrupt field); the world is then left as it was.
  void restore(std::span<const std::uint8_t> snapshot);
  /// @brief A new world in the snapshot's state, with the given workers; its ids carry its
  /// own world number (BodyId::world) but the snapshot's slots and generations.
  /// @throws SnapshotError as restore().
  static World from_snapshot(std::span<const std::uint8_t> snapshot, int worker_count = 1,
                             const TaskSystem& task_system = {});
  /// A 64-bit hash of the state a snapshot holds, for desync checks: two worlds with equal
  /// hashes continue the same (the same on every run of this build, at any worker count).
  std::uint64_t state_hash() const;
  /// @brief This world's number, which every id it issues carries (BodyId::world).
  std::uint32_t serial() const noexcept;

  /// @}

  /// @name Recording
  /// @{

  /// @brief Reports every call that changes the world to `recorder` (null: none), until
  /// changed. The recorder must outlive its use; it is not part of snapshots.
  void set_recorder(Recorder* recorder) noexcept;
  /// Runs a call as Recorder::call received it, with its arguments (ids as recorded, given
  /// this world's number).
  /// @throws SnapshotError for bytes that are not a recorded call; otherwise what the call
  /// throws.
  void replay_call(std::span<const std::uint8_t> encoded);

  /// @}

  /// @brief Describes the world to `draw` in world coordinates, the layers `draw.layers` selects.
  void draw(DebugDraw& draw) const;

 private:
  friend class detail::RecordScope;
  void run_step(bool clear_events, Real time_step, int substeps);
  std::unique_ptr<WorldState> state_;
};

}  // namespace mink
