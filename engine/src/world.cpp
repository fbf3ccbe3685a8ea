#include "mink/engine/world.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "checks.hpp"
#include "mink/engine/stale_id_error.hpp"
#include "mink/error.hpp"
#include "mink/geometry/polygon.hpp"
#include "record_scope.hpp"
#include "world_state.hpp"

namespace mink {

using detail::finite;
using detail::require;

std::string to_string(BodyId id) {
  return detail::id_string("BodyId", id);
}

std::string to_string(ShapeId id) {
  return detail::id_string("ShapeId", id);
}

namespace detail {

void check_world_def(const WorldDef& def) {
  check_step_length(def.time_step, def.substeps, "WorldDef.");
  require(std::isfinite(def.contact_hertz) && def.contact_hertz >= 0,
          "WorldDef.contact_hertz must be finite and non-negative");
  require(std::isfinite(def.contact_damping_ratio) && def.contact_damping_ratio >= 0,
          "WorldDef.contact_damping_ratio must be finite and non-negative");
  require(std::isfinite(def.joint_hertz) && def.joint_hertz >= 0,
          "WorldDef.joint_hertz must be finite and non-negative");
  require(std::isfinite(def.joint_damping_ratio) && def.joint_damping_ratio >= 0,
          "WorldDef.joint_damping_ratio must be finite and non-negative");
  require(def.joint_iterations >= 1 && def.joint_iterations <= max_joint_iterations,
          "WorldDef.joint_iterations must be 1..max_joint_iterations (1000), got " +
              std::to_string(def.joint_iterations));
  require(std::isfinite(def.contact_push_max_velocity) && def.contact_push_max_velocity >= 0,
          "WorldDef.contact_push_max_velocity must be finite and non-negative");
  require(std::isfinite(def.restitution_threshold) && def.restitution_threshold >= 0,
          "WorldDef.restitution_threshold must be finite and non-negative");
  require(std::isfinite(def.hit_event_threshold) && def.hit_event_threshold >= 0,
          "WorldDef.hit_event_threshold must be finite and non-negative");
  require(std::isfinite(def.linear_slop) && def.linear_slop > 0,
          "WorldDef.linear_slop must be positive and finite");
  require(std::isfinite(def.manifold_reuse_distance) && def.manifold_reuse_distance >= 0,
          "WorldDef.manifold_reuse_distance must be finite and non-negative");
  require(std::isfinite(def.max_linear_speed) && def.max_linear_speed > 0,
          "WorldDef.max_linear_speed must be positive and finite");
  require(std::isfinite(def.time_to_sleep) && def.time_to_sleep >= 0,
          "WorldDef.time_to_sleep must be finite and non-negative");
  require(def.linear_sleep_tolerance >= 0 && def.angular_sleep_tolerance >= 0,
          "WorldDef sleep tolerances must be non-negative");
  require(def.max_steps_per_advance >= 1, "WorldDef.max_steps_per_advance must be at least 1");
  require(def.worker_count >= 1 && def.worker_count <= 256,
          "WorldDef.worker_count must be 1..256, got " + std::to_string(def.worker_count));
  require((def.task_system.enqueue == nullptr) == (def.task_system.finish == nullptr),
          "WorldDef.task_system needs both enqueue and finish, or neither");
  check_gravity(def.gravity, "WorldDef.gravity");
  const std::pair<const char*, Real> settings[] = {
      {"contact_hertz", def.contact_hertz},
      {"contact_damping_ratio", def.contact_damping_ratio},
      {"joint_hertz", def.joint_hertz},
      {"joint_damping_ratio", def.joint_damping_ratio},
      {"contact_push_max_velocity", def.contact_push_max_velocity},
      {"restitution_threshold", def.restitution_threshold},
      {"hit_event_threshold", def.hit_event_threshold},
      {"linear_slop", def.linear_slop},
      {"max_linear_speed", def.max_linear_speed},
      {"manifold_reuse_distance", def.manifold_reuse_distance},
  };
  for (const auto& [name, value] : settings) {
    require(within_settings(value), std::string("WorldDef.") + name +
                                        " must not exceed max_setting_magnitude (1e9), got " +
                                        exact_number(value));
  }
}

void check_step_length(Real time_step, int substeps, const std::string& what) {
  require(std::isfinite(time_step) && time_step >= 1 / max_setting_magnitude &&
              time_step <= max_setting_magnitude,
          what + "time_step must be 1e-9..1e9 s (max_setting_magnitude), got " +
              exact_number(time_step));
  require(substeps >= 1 && substeps <= max_substeps,
          what + "substeps must be 1..max_substeps (1000), got " + std::to_string(substeps));
}

void check_gravity(const Vec2& gravity, const std::string& what) {
  require(within_settings(gravity),
          what +
              " must be finite and within max_setting_magnitude (1e9 m/s^2) on each axis, got (" +
              exact_number(gravity.x()) + ", " + exact_number(gravity.y()) + ")");
}

}  // namespace detail

World::World(const WorldDef& def) : state_(std::make_unique<WorldState>()) {
  detail::check_world_def(def);
  state_->def = def;
  state_->tasks.configure(def.worker_count, def.task_system);
  // Serial numbers start at 1 so that a default id (world 0) never names a live object.
  static std::atomic<std::uint32_t> next_serial{1};
  state_->serial = next_serial.fetch_add(1);
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const WorldDef& World::def() const noexcept {
  return state_->def;
}

void World::set_gravity(const Vec2& gravity) {
  const detail::RecordScope record(*this, detail::Call::set_gravity, gravity);
  detail::check_gravity(gravity, "gravity");
  state_->def.gravity = gravity;
  for (detail::Body& b : state_->bodies) {
    if (b.alive) state_->wake(b);
  }
}

void World::enable_sleep(bool enabled) {
  const detail::RecordScope record(*this, detail::Call::enable_sleep, enabled);
  state_->def.enable_sleep = enabled;
  if (!enabled) {
    for (detail::Body& b : state_->bodies) {
      if (b.alive) state_->wake(b);
    }
  }
}

void World::step() {
  const detail::RecordScope record(*this, detail::Call::step);
  run_step(true, state_->def.time_step, state_->def.substeps);
}

void World::step(Real time_step, int substeps) {
  const detail::RecordScope record(*this, detail::Call::step_with, time_step, substeps);
  detail::check_step_length(time_step, substeps, "step: ");
  run_step(true, time_step, substeps);
}

AdvanceResult World::advance(Real frame_seconds) {
  const detail::RecordScope record(*this, detail::Call::advance, frame_seconds);
  require(std::isfinite(frame_seconds) && frame_seconds >= 0,
          "advance: frame_seconds must be finite and non-negative, got " +
              std::to_string(frame_seconds));
  WorldState& w = *state_;
  w.clear_events();
  w.accumulator += frame_seconds;
  AdvanceResult result;
  while (w.accumulator >= w.def.time_step && result.steps < w.def.max_steps_per_advance) {
    run_step(false, w.def.time_step, w.def.substeps);
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
std::span<const ContactHitEvent> World::contact_hit_events() const noexcept {
  return state_->hit_events;
}
std::span<const SensorBeginEvent> World::sensor_begin_events() const noexcept {
  return state_->sensor_begin_events;
}
std::span<const SensorEndEvent> World::sensor_end_events() const noexcept {
  return state_->sensor_end_events;
}
std::span<const BodyMoveEvent> World::body_move_events() const noexcept {
  return state_->move_events;
}
std::span<const BodyStoppedEvent> World::body_stopped_events() const noexcept {
  return state_->stopped_events;
}
const StepCounters& World::counters() const noexcept {
  return state_->counters;
}
const StepProfile& World::profile() const noexcept {
  return state_->profile;
}

}  // namespace mink

namespace mink {

void WorldState::clear_events() {
  begin_events.clear();
  end_events.clear();
  hit_events.clear();
  sensor_begin_events.clear();
  sensor_end_events.clear();
  move_events.clear();
  joint_break_events.clear();
  stopped_events.clear();
}

// One step: pair update -> narrowphase -> islands and sleep -> soft-step solver -> continuous
// collision -> broadphase boxes for the next step -> sensors.
void World::run_step(bool clear_events, Real time_step, int substeps) {
  WorldState& w = *state_;
  if (clear_events) w.clear_events();
  w.dt = time_step;
  w.substeps = substeps;
  w.fell_asleep.clear();
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  const auto t0 = Clock::now();
  w.update_pairs();
  const auto t1 = Clock::now();
  w.collide();
  const auto t2 = Clock::now();
  if (w.def.enable_sleep) {
    w.update_islands();
  } else {
    w.counters.islands = 0;
  }
  const auto t3 = Clock::now();
  w.prepare_contacts();
  w.prepare_joints();
  const auto t4 = Clock::now();
  w.solve();
  w.finish_joints();
  const auto t5 = Clock::now();
  if (w.def.enable_continuous) {
    w.solve_continuous();
  } else {
    w.continuous.fast_list.clear();
    w.counters.fast_bodies = w.counters.continuous_hits = 0;
  }
  const auto t6 = Clock::now();
  w.finish_step();
  w.update_sensors();
  const auto t7 = Clock::now();
  w.profile = {ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t4, t5), ms(t5, t6), ms(t6, t7)};
  w.time += time_step;
  ++w.step_count;
  if (w.recorder != nullptr) w.recorder->stepped(*this);
}

}  // namespace mink
