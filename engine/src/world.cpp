#include "mink/engine/world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mink/engine/stale_id_error.hpp"
#include "mink/error.hpp"
#include "mink/geometry/polygon.hpp"
#include "world_state.hpp"

namespace mink {

std::string to_string(BodyId id) {
  return "BodyId{index " + std::to_string(id.index) + ", generation " +
         std::to_string(id.generation) + "}";
}

std::string to_string(ShapeId id) {
  return "ShapeId{index " + std::to_string(id.index) + ", generation " +
         std::to_string(id.generation) + "}";
}

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidArgumentError(what);
}

bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

void check_world_def(const WorldDef& def) {
  require(finite(def.gravity), "WorldDef.gravity must be finite");
  require(std::isfinite(def.time_step) && def.time_step > 0,
          "WorldDef.time_step must be positive and finite, got " + std::to_string(def.time_step));
  require(def.substeps >= 1,
          "WorldDef.substeps must be at least 1, got " + std::to_string(def.substeps));
  require(std::isfinite(def.contact_hertz) && def.contact_hertz >= 0,
          "WorldDef.contact_hertz must be finite and non-negative");
  require(std::isfinite(def.contact_damping_ratio) && def.contact_damping_ratio >= 0,
          "WorldDef.contact_damping_ratio must be finite and non-negative");
  require(std::isfinite(def.contact_push_max_velocity) && def.contact_push_max_velocity >= 0,
          "WorldDef.contact_push_max_velocity must be finite and non-negative");
  require(std::isfinite(def.restitution_threshold) && def.restitution_threshold >= 0,
          "WorldDef.restitution_threshold must be finite and non-negative");
  require(std::isfinite(def.linear_slop) && def.linear_slop > 0,
          "WorldDef.linear_slop must be positive and finite");
  require(std::isfinite(def.max_linear_speed) && def.max_linear_speed > 0,
          "WorldDef.max_linear_speed must be positive and finite");
  require(std::isfinite(def.time_to_sleep) && def.time_to_sleep >= 0,
          "WorldDef.time_to_sleep must be finite and non-negative");
  require(def.linear_sleep_tolerance >= 0 && def.angular_sleep_tolerance >= 0,
          "WorldDef sleep tolerances must be non-negative");
  require(def.max_steps_per_advance >= 1, "WorldDef.max_steps_per_advance must be at least 1");
}

void check_body_def(const BodyDef& def) {
  require(finite(def.position), "BodyDef.position must be finite");
  require(std::isfinite(def.angle), "BodyDef.angle must be finite");
  require(finite(def.linear_velocity), "BodyDef.linear_velocity must be finite");
  require(std::isfinite(def.angular_velocity), "BodyDef.angular_velocity must be finite");
  require(std::isfinite(def.linear_damping) && def.linear_damping >= 0,
          "BodyDef.linear_damping must be finite and non-negative");
  require(std::isfinite(def.angular_damping) && def.angular_damping >= 0,
          "BodyDef.angular_damping must be finite and non-negative");
  require(std::isfinite(def.gravity_scale), "BodyDef.gravity_scale must be finite");
}

}  // namespace

detail::Body& WorldState::body(BodyId id) {
  if (id.index >= bodies.size() || !bodies[id.index].alive ||
      bodies[id.index].generation != id.generation) {
    throw StaleIdError(to_string(id) + " does not name a live body");
  }
  return bodies[id.index];
}

const detail::Body& WorldState::body(BodyId id) const {
  return const_cast<WorldState*>(this)->body(id);
}

detail::Shape& WorldState::shape(ShapeId id) {
  if (id.index >= shapes.size() || !shapes[id.index].alive ||
      shapes[id.index].generation != id.generation) {
    throw StaleIdError(to_string(id) + " does not name a live shape");
  }
  return shapes[id.index];
}

const detail::Shape& WorldState::shape(ShapeId id) const {
  return const_cast<WorldState*>(this)->shape(id);
}

void WorldState::wake(detail::Body& b) {
  if (b.type == BodyType::static_body) return;
  b.awake = true;
  b.sleep_time = 0;
}

// Mass, centre of mass and inertia from the hulls (area_properties), density-weighted.
void WorldState::update_mass(detail::Body& b) {
  b.mass = b.inv_mass = b.inertia = b.inv_inertia = 0;
  b.local_center = Vec2(0, 0);
  b.extent = 0;
  if (b.type == BodyType::dynamic) {
    Real mass = 0;
    Vec2 weighted(0, 0);
    Real inertia_about_origin = 0;
    for (std::uint32_t s : b.shapes) {
      const detail::Shape& shape_slot = shapes[s];
      const AreaProperties props = area_properties(shape_slot.hull->vertices());
      const Real m = shape_slot.density * props.area;
      mass += m;
      weighted += m * props.centroid;
      inertia_about_origin +=
          shape_slot.density * props.polar_moment + m * props.centroid.squaredNorm();
    }
    if (mass > 0) {
      b.mass = mass;
      b.inv_mass = 1 / mass;
      b.local_center = weighted / mass;
      b.inertia = inertia_about_origin - mass * b.local_center.squaredNorm();
      b.inv_inertia = b.inertia > 0 ? 1 / b.inertia : 0;
    } else {
      // A dynamic body needs mass to respond to contacts; Box2D's convention: unit mass, no
      // rotational inertia.
      b.mass = 1;
      b.inv_mass = 1;
    }
  }
  for (std::uint32_t s : b.shapes) {
    for (const Vec2& v : shapes[s].hull->vertices()) {
      b.extent = std::max(b.extent, (v - b.local_center).norm());
    }
  }
  const Vec2 old_center = b.center;
  b.center = b.origin + b.rotation.apply(b.local_center);
  // Keep the velocity of the origin point unchanged when the centre moves.
  const Vec2 shift = b.center - old_center;
  b.velocity += b.angular_velocity * Vec2(-shift.y(), shift.x());
}

World::World(const WorldDef& def) : state_(std::make_unique<WorldState>()) {
  check_world_def(def);
  state_->def = def;
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const WorldDef& World::def() const noexcept {
  return state_->def;
}

void World::set_gravity(const Vec2& gravity) {
  require(finite(gravity), "gravity must be finite");
  state_->def.gravity = gravity;
  for (detail::Body& b : state_->bodies) {
    if (b.alive) state_->wake(b);
  }
}

void World::enable_sleep(bool enabled) {
  state_->def.enable_sleep = enabled;
  if (!enabled) {
    for (detail::Body& b : state_->bodies) {
      if (b.alive) state_->wake(b);
    }
  }
}

BodyId World::create_body(const BodyDef& def) {
  check_body_def(def);
  WorldState& w = *state_;
  std::uint32_t index;
  if (!w.free_bodies.empty()) {
    index = w.free_bodies.back();
    w.free_bodies.pop_back();
  } else {
    index = static_cast<std::uint32_t>(w.bodies.size());
    w.bodies.emplace_back();
  }
  detail::Body& b = w.bodies[index];
  const std::uint32_t generation = b.generation;
  b = detail::Body{};
  b.generation = generation;
  b.alive = true;
  b.type = def.type;
  b.origin = def.position;
  b.center = def.position;
  b.rotation = Rotation::from_angle(def.angle);
  if (def.type != BodyType::static_body) {
    b.velocity = def.linear_velocity;
    b.angular_velocity = def.angular_velocity;
  }
  b.linear_damping = def.linear_damping;
  b.angular_damping = def.angular_damping;
  b.gravity_scale = def.gravity_scale;
  b.allow_sleep = def.allow_sleep;
  b.awake = def.type != BodyType::static_body && def.awake;
  b.sleep_time = b.awake ? 0 : w.def.time_to_sleep;
  b.user_data = def.user_data;
  if (def.type == BodyType::dynamic) b.mass = b.inv_mass = 1;
  ++w.live_bodies;
  return {index, generation};
}

void World::destroy_body(BodyId id) {
  detail::Body& b = state_->body(id);
  while (!b.shapes.empty()) {
    destroy_shape(state_->shape_id(b.shapes.back()));
  }
  b.alive = false;
  ++b.generation;
  state_->free_bodies.push_back(id.index);
  --state_->live_bodies;
}

ShapeId World::create_shape(BodyId body_id, const ShapeDef& def) {
  WorldState& w = *state_;
  w.body(body_id);  // validates before any work
  ConvexHull hull = make_shape_hull(def);
  std::uint32_t index;
  if (!w.free_shapes.empty()) {
    index = w.free_shapes.back();
    w.free_shapes.pop_back();
  } else {
    index = static_cast<std::uint32_t>(w.shapes.size());
    w.shapes.emplace_back();
  }
  detail::Shape& s = w.shapes[index];
  const std::uint32_t generation = s.generation;
  s = detail::Shape{};
  s.generation = generation;
  s.alive = true;
  s.hull.emplace(std::move(hull));
  s.density = def.density;
  s.friction = def.friction;
  s.restitution = def.restitution;
  s.algorithm = def.algorithm;
  s.body = body_id.index;
  detail::Body& b = w.bodies[body_id.index];
  b.shapes.push_back(index);
  w.update_mass(b);
  w.update_shape_aabb(s, b, 0);
  s.proxy = w.broadphase.create_proxy(
      s.aabb, b.type == BodyType::static_body ? ProxyKind::static_body : ProxyKind::moving, index);
  w.wake(b);
  ++w.live_shapes;
  return {index, generation};
}

void World::destroy_shape(ShapeId id) {
  WorldState& w = *state_;
  detail::Shape& s = w.shape(id);
  w.destroy_shape_contacts(id.index);
  w.pending_proxy_destroys.push_back(s.proxy);
  detail::Body& b = w.bodies[s.body];
  b.shapes.erase(std::find(b.shapes.begin(), b.shapes.end(), id.index));
  s.alive = false;
  s.hull.reset();
  s.proxy = null_proxy;
  ++s.generation;
  w.free_shapes.push_back(id.index);
  --w.live_shapes;
  w.update_mass(b);
  w.wake(b);
}

bool World::is_valid(BodyId id) const noexcept {
  return id.index < state_->bodies.size() && state_->bodies[id.index].alive &&
         state_->bodies[id.index].generation == id.generation;
}

bool World::is_valid(ShapeId id) const noexcept {
  return id.index < state_->shapes.size() && state_->shapes[id.index].alive &&
         state_->shapes[id.index].generation == id.generation;
}

std::size_t World::body_count() const noexcept {
  return state_->live_bodies;
}
std::size_t World::shape_count() const noexcept {
  return state_->live_shapes;
}

std::vector<BodyId> World::bodies() const {
  std::vector<BodyId> ids;
  ids.reserve(state_->live_bodies);
  for (std::uint32_t i = 0; i < state_->bodies.size(); ++i) {
    if (state_->bodies[i].alive) ids.push_back({i, state_->bodies[i].generation});
  }
  return ids;
}

BodyType World::body_type(BodyId id) const {
  return state_->body(id).type;
}
Vec2 World::position(BodyId id) const {
  return state_->body(id).origin;
}
Real World::angle(BodyId id) const {
  return state_->body(id).rotation.angle();
}
Pose World::pose(BodyId id) const {
  return state_->body(id).pose();
}
Vec2 World::world_center(BodyId id) const {
  return state_->body(id).center;
}
Vec2 World::local_center(BodyId id) const {
  return state_->body(id).local_center;
}
Vec2 World::linear_velocity(BodyId id) const {
  return state_->body(id).velocity;
}
Real World::angular_velocity(BodyId id) const {
  return state_->body(id).angular_velocity;
}
Real World::mass(BodyId id) const {
  return state_->body(id).mass;
}
Real World::rotational_inertia(BodyId id) const {
  return state_->body(id).inertia;
}
Real World::linear_damping(BodyId id) const {
  return state_->body(id).linear_damping;
}
Real World::angular_damping(BodyId id) const {
  return state_->body(id).angular_damping;
}
Real World::gravity_scale(BodyId id) const {
  return state_->body(id).gravity_scale;
}
bool World::allow_sleep(BodyId id) const {
  return state_->body(id).allow_sleep;
}
bool World::is_awake(BodyId id) const {
  return state_->body(id).awake;
}
std::uint64_t World::user_data(BodyId id) const {
  return state_->body(id).user_data;
}

std::vector<ShapeId> World::body_shapes(BodyId id) const {
  std::vector<ShapeId> ids;
  for (std::uint32_t s : state_->body(id).shapes) ids.push_back(state_->shape_id(s));
  return ids;
}

void World::set_transform(BodyId id, const Vec2& position, Real angle) {
  require(finite(position) && std::isfinite(angle),
          "set_transform of " + to_string(id) + ": position and angle must be finite");
  WorldState& w = *state_;
  detail::Body& b = w.body(id);
  b.origin = position;
  b.rotation = Rotation::from_angle(angle);
  b.center = b.origin + b.rotation.apply(b.local_center);
  for (std::uint32_t s : b.shapes) {
    w.update_shape_aabb(w.shapes[s], b, 0);
    w.broadphase.move_proxy(w.shapes[s].proxy, w.shapes[s].aabb);
  }
  w.wake(b);
}

void World::set_linear_velocity(BodyId id, const Vec2& velocity) {
  require(finite(velocity), "set_linear_velocity of " + to_string(id) + ": must be finite");
  detail::Body& b = state_->body(id);
  if (b.type == BodyType::static_body) return;
  b.velocity = velocity;
  state_->wake(b);
}

void World::set_angular_velocity(BodyId id, Real velocity) {
  require(std::isfinite(velocity), "set_angular_velocity of " + to_string(id) + ": must be finite");
  detail::Body& b = state_->body(id);
  if (b.type == BodyType::static_body) return;
  b.angular_velocity = velocity;
  state_->wake(b);
}

void World::apply_force(BodyId id, const Vec2& force, const Vec2& world_point) {
  require(finite(force) && finite(world_point),
          "apply_force to " + to_string(id) + ": force and point must be finite");
  detail::Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  b.force += force;
  const Vec2 r = world_point - b.center;
  b.torque += r.x() * force.y() - r.y() * force.x();
  state_->wake(b);
}

void World::apply_torque(BodyId id, Real torque) {
  require(std::isfinite(torque), "apply_torque to " + to_string(id) + ": must be finite");
  detail::Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  b.torque += torque;
  state_->wake(b);
}

void World::apply_linear_impulse(BodyId id, const Vec2& impulse, const Vec2& world_point) {
  require(finite(impulse) && finite(world_point),
          "apply_linear_impulse to " + to_string(id) + ": impulse and point must be finite");
  detail::Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  b.velocity += b.inv_mass * impulse;
  const Vec2 r = world_point - b.center;
  b.angular_velocity += b.inv_inertia * (r.x() * impulse.y() - r.y() * impulse.x());
  state_->wake(b);
}

void World::set_awake(BodyId id, bool awake) {
  detail::Body& b = state_->body(id);
  if (b.type == BodyType::static_body) return;
  if (awake) {
    state_->wake(b);
  } else if (b.type == BodyType::dynamic) {
    b.awake = false;
    b.sleep_time = state_->def.time_to_sleep;
    b.velocity = Vec2(0, 0);
    b.angular_velocity = 0;
  }
}

BodyId World::shape_body(ShapeId id) const {
  const detail::Shape& s = state_->shape(id);
  return {s.body, state_->bodies[s.body].generation};
}
const ConvexHull& World::shape_hull(ShapeId id) const {
  return state_->shape(id).hull->hull();
}
Real World::shape_density(ShapeId id) const {
  return state_->shape(id).density;
}
Real World::shape_friction(ShapeId id) const {
  return state_->shape(id).friction;
}
Real World::shape_restitution(ShapeId id) const {
  return state_->shape(id).restitution;
}
HullAlgorithm World::shape_algorithm(ShapeId id) const {
  return state_->shape(id).algorithm;
}

Aabb World::shape_aabb(ShapeId id) const {
  const detail::Shape& s = state_->shape(id);
  const Pose pose = state_->bodies[s.body].pose();
  Aabb box{pose.apply(s.hull->vertices()[0]), pose.apply(s.hull->vertices()[0])};
  for (const Vec2& v : s.hull->vertices()) {
    const Vec2 p = pose.apply(v);
    box.lower = box.lower.cwiseMin(p);
    box.upper = box.upper.cwiseMax(p);
  }
  return box;
}

void World::step() {
  run_step(true);
}

AdvanceResult World::advance(Real frame_seconds) {
  require(std::isfinite(frame_seconds) && frame_seconds >= 0,
          "advance: frame_seconds must be finite and non-negative, got " +
              std::to_string(frame_seconds));
  WorldState& w = *state_;
  w.begin_events.clear();
  w.end_events.clear();
  w.accumulator += frame_seconds;
  AdvanceResult result;
  while (w.accumulator >= w.def.time_step && result.steps < w.def.max_steps_per_advance) {
    run_step(false);
    w.accumulator -= w.def.time_step;
    ++result.steps;
  }
  // Drop what could not be run rather than carry an ever-growing debt.
  if (w.accumulator >= w.def.time_step) w.accumulator = std::fmod(w.accumulator, w.def.time_step);
  result.alpha = w.accumulator / w.def.time_step;
  return result;
}

Real World::time() const noexcept {
  return state_->time;
}
std::uint64_t World::step_count() const noexcept {
  return state_->step_count;
}

std::span<const ContactBeginEvent> World::contact_begin_events() const noexcept {
  return state_->begin_events;
}
std::span<const ContactEndEvent> World::contact_end_events() const noexcept {
  return state_->end_events;
}
const StepCounters& World::counters() const noexcept {
  return state_->counters;
}
const StepProfile& World::profile() const noexcept {
  return state_->profile;
}

}  // namespace mink
