// Bodies: mass from shapes, waking, and the body half of the World API.

#include "body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "checks.hpp"
#include "mink/error.hpp"
#include "record_scope.hpp"
#include "world_state.hpp"

namespace mink {

using detail::finite;
using detail::require;
using detail::within_settings;
using detail::within_world;

using detail::Body;

void detail::check_body_def(const BodyDef& def) {
  require(within_world(def.position),
          "BodyDef.position must be finite and within max_world_coordinate (1e15 m) on each axis");
  require(std::isfinite(def.angle), "BodyDef.angle must be finite");
  require(within_settings(def.linear_velocity),
          "BodyDef.linear_velocity must be finite and within max_setting_magnitude (1e9 m/s)");
  require(within_settings(def.angular_velocity),
          "BodyDef.angular_velocity must be finite and within max_setting_magnitude (1e9 rad/s)");
  require(std::isfinite(def.linear_damping) && def.linear_damping >= 0,
          "BodyDef.linear_damping must be finite and non-negative");
  require(std::isfinite(def.angular_damping) && def.angular_damping >= 0,
          "BodyDef.angular_damping must be finite and non-negative");
  require(within_settings(def.gravity_scale),
          "BodyDef.gravity_scale must lie within max_setting_magnitude (1e9), got " +
              detail::exact_number(def.gravity_scale));
  require(!std::isnan(def.continuous_threshold) && def.continuous_threshold >= 0,
          "BodyDef.continuous_threshold must be non-negative");
}

void WorldState::wake(Body& b) {
  if (b.type == BodyType::static_body) return;
  b.awake = true;
  b.sleep_time = 0;
  add_to_awake_list(b);
}

void WorldState::add_to_awake_list(Body& b) {
  if (b.in_awake_list) return;
  b.in_awake_list = true;
  awake_list.push_back(static_cast<std::uint32_t>(&b - bodies.slots().data()));
  awake_list_compact = false;
}

// Drops the bodies that went to sleep, died or stopped moving, and restores slot order (the
// order the solver and the events have always used).
void WorldState::compact_awake_list() {
  if (awake_list_compact) return;  // large worlds: a read of every awake body record saved
  std::size_t kept = 0;
  for (const std::uint32_t i : awake_list) {
    Body& b = bodies[i];
    if (b.alive && detail::moves(b)) {
      awake_list[kept++] = i;
    } else {
      b.in_awake_list = false;
    }
  }
  awake_list.resize(kept);
  if (!std::is_sorted(awake_list.begin(), awake_list.end())) {
    std::sort(awake_list.begin(), awake_list.end());
  }
  // A slot freed and reused within one step can be listed twice.
  awake_list.erase(std::unique(awake_list.begin(), awake_list.end()), awake_list.end());
  awake_list_compact = true;
}

// Mass, centre of mass and inertia from the shapes (compute_mass), density-weighted, unless
// set_mass_data overrides them.
void WorldState::update_mass(Body& b) {
  b.mass = b.inv_mass = b.inertia = b.inv_inertia = 0;
  b.local_center = Vec2(0, 0);
  b.extent = 0;
  if (b.type == BodyType::dynamic) {
    if (b.mass_override) {
      b.mass = b.override_mass.mass;
      b.local_center = b.override_mass.center;
      b.inertia = b.override_mass.rotational_inertia;
    } else {
      Real mass = 0;
      Vec2 weighted(0, 0);
      Real inertia_about_origin = 0;
      for (std::uint32_t s : b.shapes) {
        const detail::Shape& shape = shapes[s];
        if (shape.density == 0) continue;
        const MassData m = compute_mass(shape.geometry, shape.density);
        mass += m.mass;
        weighted += m.mass * m.center;
        inertia_about_origin += m.rotational_inertia + m.mass * m.center.squaredNorm();
      }
      if (mass > 0) {
        b.mass = mass;
        b.local_center = weighted / mass;
        b.inertia = inertia_about_origin - mass * b.local_center.squaredNorm();
      }
    }
    if (b.mass > 0) {
      b.inv_mass = 1 / b.mass;
    } else {
      // A dynamic body needs mass to respond to contacts; Box2D's convention: unit mass, no
      // rotational inertia.
      b.mass = 1;
      b.inv_mass = 1;
      b.inertia = 0;
    }
    if (b.fixed_rotation) b.inertia = 0;
    b.inv_inertia = b.inertia > 0 ? 1 / b.inertia : 0;
  }
  // Segments have no width: they count only when the body has nothing else.
  b.min_extent = std::numeric_limits<Real>::infinity();
  for (std::uint32_t s : b.shapes) {
    b.extent = std::max(b.extent, detail::shape_extent(shapes[s].geometry, b.local_center));
    const Real thin = detail::shape_min_extent(shapes[s].geometry);
    if (thin > 0) b.min_extent = std::min(b.min_extent, thin);
  }
  if (!std::isfinite(b.min_extent)) b.min_extent = def.linear_slop;
  const Vec2 old_center = b.center;
  detail::place_center(b);
  // Material points keep their velocity when the centre moves within the body.
  const Vec2 shift = b.center - old_center;
  b.velocity += b.angular_velocity * Vec2(-shift.y(), shift.x());
}

BodyId World::create_body(const BodyDef& def) {
  const detail::RecordScope record(*this, detail::Call::create_body, def);
  detail::check_body_def(def);
  WorldState& w = *state_;
  const std::uint32_t index = w.bodies.allocate();
  Body& b = w.bodies[index];
  b.type = def.type;
  b.origin = def.position;
  b.center = def.position;
  b.rotation = Rotation::from_angle(def.angle);
  if (def.type != BodyType::static_body) {
    b.velocity = def.linear_velocity;
    b.angular_velocity = def.fixed_rotation ? 0 : def.angular_velocity;
  }
  b.linear_damping = def.linear_damping;
  b.angular_damping = def.angular_damping;
  b.gravity_scale = def.gravity_scale;
  b.allow_sleep = def.allow_sleep;
  b.awake = def.type != BodyType::static_body && def.awake;
  b.sleep_time = b.awake ? 0 : w.def.time_to_sleep;
  b.user_data = def.user_data;
  b.enabled = def.enabled;
  b.fixed_rotation = def.fixed_rotation;
  b.bullet = def.bullet;
  b.continuous_threshold = def.continuous_threshold;
  // A body that may not sleep starts awake (as in Box2D), whatever `awake` says.
  if (def.type != BodyType::static_body && !def.allow_sleep) b.awake = true;
  if (b.awake) w.add_to_awake_list(b);
  if (def.type == BodyType::dynamic) b.mass = b.inv_mass = 1;
  return w.body_id(index);
}

void World::destroy_body(BodyId id) {
  const detail::RecordScope record(*this, detail::Call::destroy_body, id);
  Body& b = state_->body(id);
  while (!b.joints.empty()) state_->destroy_joint(b.joints.back());
  while (!b.shapes.empty()) destroy_shape(state_->shape_id(b.shapes.back()));
  b.contacts.clear();
  state_->bodies.release(id.index);  // a stale awake-list entry is dropped next step
  state_->awake_list_compact = false;
}

bool World::is_valid(BodyId id) const noexcept {
  return state_->bodies.valid(id, state_->serial);
}

std::size_t World::body_count() const noexcept {
  return state_->bodies.live();
}

std::vector<BodyId> World::bodies() const {
  return state_->bodies.live_ids<BodyId>(state_->serial);
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
bool World::is_enabled(BodyId id) const {
  return state_->body(id).enabled;
}
bool World::fixed_rotation(BodyId id) const {
  return state_->body(id).fixed_rotation;
}
bool World::is_bullet(BodyId id) const {
  return state_->body(id).bullet;
}
Real World::continuous_threshold(BodyId id) const {
  return state_->body(id).continuous_threshold;
}

MassData World::mass_data(BodyId id) const {
  const Body& b = state_->body(id);
  return {b.mass, b.local_center, b.inertia};
}

Pose World::interpolated_pose(BodyId id, Real alpha) const {
  require(std::isfinite(alpha), "interpolated_pose of " + to_string(id) + ": alpha must be finite");
  const Body& b = state_->body(id);
  if (b.moved_step + 1 != state_->step_count) return b.pose();  // did not move in the last step
  const Real a = std::clamp(alpha, Real{0}, Real{1});
  Pose pose;
  pose.position = (1 - a) * b.previous_origin + a * b.origin;
  // Blend the angle along the shorter way round.
  const Rotation& r0 = b.previous_rotation;
  const Rotation& r1 = b.rotation;
  const Real turn =
      std::atan2(r0.cos * r1.sin - r0.sin * r1.cos, r0.cos * r1.cos + r0.sin * r1.sin);
  pose.rotation = Rotation::from_angle(r0.angle() + a * turn);
  return pose;
}

std::vector<ShapeId> World::body_shapes(BodyId id) const {
  std::vector<ShapeId> ids;
  for (std::uint32_t s : state_->body(id).shapes) ids.push_back(state_->shape_id(s));
  return ids;
}

std::vector<ContactData> World::body_contacts(BodyId id) const {
  const WorldState& w = *state_;
  w.body(id);
  std::vector<ContactData> found;
  std::vector<std::uint32_t> indices = w.bodies[id.index].contacts;
  std::sort(indices.begin(), indices.end());
  for (const std::uint32_t i : indices) {
    const detail::Contact& c = w.contacts[i];
    if (c.manifold.point_count == 0) continue;
    found.push_back({w.shape_id(c.shape_a), w.shape_id(c.shape_b), c.manifold});
  }
  return found;
}

void World::set_transform(BodyId id, const Vec2& position, Real angle) {
  const detail::RecordScope record(*this, detail::Call::set_transform, id, position, angle);
  require(within_world(position) && std::isfinite(angle),
          "set_transform of " + to_string(id) +
              ": position and angle must be finite, the position within max_world_coordinate");
  WorldState& w = *state_;
  Body& b = w.body(id);
  for (std::uint32_t s : b.shapes) w.update_seams(s, true);  // the old neighbours
  b.origin = position;
  b.rotation = Rotation::from_angle(angle);
  detail::place_center(b);
  for (std::uint32_t s : b.shapes) {
    detail::Shape& shape = w.shapes[s];
    w.update_shape_aabb(shape, b);
    if (shape.proxy != null_proxy) w.broadphase.move_proxy(shape.proxy, shape.aabb);
  }
  for (std::uint32_t s : b.shapes) w.update_seams(s, false);
  w.wake(b);
}

void World::set_linear_velocity(BodyId id, const Vec2& velocity) {
  const detail::RecordScope record(*this, detail::Call::set_linear_velocity, id, velocity);
  require(within_settings(velocity), "set_linear_velocity of " + to_string(id) +
                                         ": must be finite and within max_setting_magnitude");
  Body& b = state_->body(id);
  if (b.type == BodyType::static_body) return;
  b.velocity = velocity;
  state_->wake(b);
}

void World::set_angular_velocity(BodyId id, Real velocity) {
  const detail::RecordScope record(*this, detail::Call::set_angular_velocity, id, velocity);
  require(within_settings(velocity), "set_angular_velocity of " + to_string(id) +
                                         ": must be finite and within max_setting_magnitude");
  Body& b = state_->body(id);
  if (b.type == BodyType::static_body || b.fixed_rotation) return;
  b.angular_velocity = velocity;
  state_->wake(b);
}

void World::apply_force(BodyId id, const Vec2& force, const Vec2& world_point) {
  const detail::RecordScope record(*this, detail::Call::apply_force, id, force, world_point);
  require(finite(force) && finite(world_point),
          "apply_force to " + to_string(id) + ": force and point must be finite");
  Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  const Vec2 r = world_point - b.center;
  const Vec2 total_force = b.force + force;
  const Real total_torque = b.torque + (r.x() * force.y() - r.y() * force.x());
  require(finite(total_force) && std::isfinite(total_torque),
          "apply_force to " + to_string(id) + ": the force so far and its torque overflow");
  b.force = total_force;
  b.torque = total_torque;
  state_->wake(b);
}

void World::apply_torque(BodyId id, Real torque) {
  const detail::RecordScope record(*this, detail::Call::apply_torque, id, torque);
  require(std::isfinite(torque), "apply_torque to " + to_string(id) + ": must be finite");
  Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  require(std::isfinite(b.torque + torque),
          "apply_torque to " + to_string(id) + ": the torque so far overflows");
  b.torque += torque;
  state_->wake(b);
}

void World::apply_linear_impulse(BodyId id, const Vec2& impulse, const Vec2& world_point) {
  const detail::RecordScope record(*this, detail::Call::apply_linear_impulse, id, impulse,
                                   world_point);
  require(finite(impulse) && finite(world_point),
          "apply_linear_impulse to " + to_string(id) + ": impulse and point must be finite");
  Body& b = state_->body(id);
  if (b.type != BodyType::dynamic) return;
  const Vec2 r = world_point - b.center;
  const Vec2 velocity = b.velocity + b.inv_mass * impulse;
  const Real angular_velocity =
      b.angular_velocity + b.inv_inertia * (r.x() * impulse.y() - r.y() * impulse.x());
  require(within_settings(velocity) && within_settings(angular_velocity),
          "apply_linear_impulse to " + to_string(id) +
              ": the velocity it gives lies beyond max_setting_magnitude");
  b.velocity = velocity;
  b.angular_velocity = angular_velocity;
  state_->wake(b);
}

void World::set_awake(BodyId id, bool awake) {
  const detail::RecordScope record(*this, detail::Call::set_awake, id, awake);
  Body& b = state_->body(id);
  if (b.type == BodyType::static_body) return;
  if (awake) {
    state_->wake(b);
  } else if (b.type == BodyType::dynamic && b.allow_sleep) {
    b.awake = false;
    state_->awake_list_compact = false;
    b.sleep_time = state_->def.time_to_sleep;
    b.velocity = Vec2(0, 0);
    b.angular_velocity = 0;
  }
}

void World::set_body_type(BodyId id, BodyType type) {
  const detail::RecordScope record(*this, detail::Call::set_body_type, id, type);
  WorldState& w = *state_;
  Body& b = w.body(id);
  if (b.type == type) return;
  for (std::uint32_t s : b.shapes) w.update_seams(s, true);
  b.type = type;
  w.awake_list_compact = false;
  if (type == BodyType::static_body) {
    b.velocity = Vec2(0, 0);
    b.angular_velocity = 0;
    b.awake = false;
  } else {
    w.wake(b);
  }
  b.sleep_time = 0;
  w.update_mass(b);
  // The broadphase files static and moving proxies apart, and contacts depend on the types.
  for (std::uint32_t s : b.shapes) w.refresh_proxy(s);
  for (std::uint32_t s : b.shapes) w.update_seams(s, false);
  for (std::uint32_t j : b.joints) {
    w.recolor_joint(j);
    w.wake_joint_bodies(j);
  }
}

void World::set_enabled(BodyId id, bool enabled) {
  const detail::RecordScope record(*this, detail::Call::set_enabled, id, enabled);
  WorldState& w = *state_;
  Body& b = w.body(id);
  if (b.enabled == enabled) return;
  if (!enabled) {
    for (std::uint32_t s : b.shapes) w.update_seams(s, true);
  }
  b.enabled = enabled;
  w.awake_list_compact = false;
  for (std::uint32_t s : b.shapes) {
    w.destroy_shape_contacts(s);
    w.destroy_proxy(w.shapes[s]);
    if (enabled) w.create_proxy(s);
  }
  if (enabled) {
    for (std::uint32_t s : b.shapes) w.update_seams(s, false);
  }
  w.wake(b);
}

void World::set_fixed_rotation(BodyId id, bool fixed) {
  const detail::RecordScope record(*this, detail::Call::set_fixed_rotation, id, fixed);
  WorldState& w = *state_;
  Body& b = w.body(id);
  if (b.fixed_rotation == fixed) return;
  b.fixed_rotation = fixed;
  if (fixed) b.angular_velocity = 0;
  w.update_mass(b);
  w.wake(b);
}

void World::set_bullet(BodyId id, bool bullet) {
  const detail::RecordScope record(*this, detail::Call::set_bullet, id, bullet);
  state_->body(id).bullet = bullet;
}

void World::set_continuous_threshold(BodyId id, Real threshold) {
  const detail::RecordScope record(*this, detail::Call::set_continuous_threshold, id, threshold);
  require(!std::isnan(threshold) && threshold >= 0,
          "continuous_threshold must be non-negative, got " + std::to_string(threshold));
  state_->body(id).continuous_threshold = threshold;
}

void World::set_target_transform(BodyId id, const Vec2& position, Real angle, Real time_step) {
  const detail::RecordScope record(*this, detail::Call::set_target_transform, id, position, angle,
                                   time_step);
  require(within_world(position) && std::isfinite(angle),
          "set_target_transform of " + to_string(id) +
              ": position and angle must be finite, the position within max_world_coordinate");
  require(std::isfinite(time_step) && time_step >= 1 / max_setting_magnitude,
          "set_target_transform of " + to_string(id) +
              ": time_step must be finite and at least 1 / max_setting_magnitude (1e-9 s)");
  WorldState& w = *state_;
  Body& b = w.body(id);
  require(b.type == BodyType::kinematic, "set_target_transform of " + to_string(id) +
                                             ": the body is " + std::string(to_string(b.type)) +
                                             ", not kinematic");
  const Rotation target = Rotation::from_angle(angle);
  const Vec2 target_center = position + target.apply(b.local_center);
  b.velocity = (target_center - b.center) / time_step;
  // The turn to the target along the shorter way round.
  const Rotation& now = b.rotation;
  const Real turn = std::atan2(now.cos * target.sin - now.sin * target.cos,
                               now.cos * target.cos + now.sin * target.sin);
  // The integrator turns by atan(h w) per substep of length h (it renormalises q + h w q'),
  // so this w lands on the target angle rather than short of it.
  const int substeps = w.def.substeps;
  const Real h = time_step / substeps;
  b.angular_velocity = std::tan(turn / substeps) / h;
  w.wake(b);
}

void World::set_mass_data(BodyId id, const MassData& mass) {
  const detail::RecordScope record(*this, detail::Call::set_mass_data, id, mass);
  require(std::isfinite(mass.mass) && mass.mass >= 0 && std::isfinite(mass.rotational_inertia) &&
              mass.rotational_inertia >= 0 && within_world(mass.center),
          "set_mass_data of " + to_string(id) +
              ": mass and inertia must be finite and non-negative, the centre finite and within "
              "max_world_coordinate");
  require(mass.mass <= max_mass_property && mass.rotational_inertia <= max_mass_property,
          "set_mass_data of " + to_string(id) + ": mass " + detail::exact_number(mass.mass) +
              " and rotational inertia " + detail::exact_number(mass.rotational_inertia) +
              " must not exceed max_mass_property (1e30)");
  if ((mass.mass > 0 && mass.mass < min_mass_property) ||
      (mass.rotational_inertia > 0 && mass.rotational_inertia < min_mass_property)) {
    throw InvalidArgumentError("set_mass_data of " + to_string(id) + ": mass " +
                               detail::exact_number(mass.mass) + " and rotational inertia " +
                               detail::exact_number(mass.rotational_inertia) +
                               " must each be 0 or at least min_mass_property (1e-30)");
  }
  WorldState& w = *state_;
  Body& b = w.body(id);
  if (b.type != BodyType::dynamic) return;
  b.mass_override = true;
  b.override_mass = mass;
  w.update_mass(b);
  w.wake(b);
}

}  // namespace mink
