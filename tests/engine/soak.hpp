#pragma once

// The soak: randomised worlds with every shape kind (circle, capsule, segment, chain, polygon)
// and every joint kind, random materials, kinematic movers, bullets and creation/destruction
// churn, stepped for a long time while invariants are checked every few steps:
//   - every body's state is finite;
//   - no solve diverges (no body is stopped: World::body_stopped_events);
//   - no body leaves the arena (a closed chain box) by more than a margin; one that does is
//     counted as escaped and removed (the kill floor), so the run goes on;
//   - in quiet phases (no movers, no motors, no churn) mechanical energy (kinetic plus
//     gravitational) never grows by more than a small tolerance;
//   - resident memory stays flat after warm-up (/proc/self/statm).
// Each scene is run at 1 and 2 workers; the two runs must also end in bitwise equal states.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mink/engine/joint_def.hpp"
#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink::soak {

struct SoakOptions {
  std::uint64_t seed = 1;
  int steps = 10'000;  // per run
  int workers = 1;
  int check_every = 10;     // invariants checked every this many steps
  int target_bodies = 120;  // churn keeps the population about here
};

struct SoakResult {
  int steps = 0;
  std::size_t bodies_created = 0;
  std::size_t bodies_destroyed = 0;  // by churn
  std::size_t joints_created = 0;
  std::size_t bullets_fired = 0;
  std::size_t escaped = 0;     // left the arena: removed and counted
  std::size_t non_finite = 0;  // checks that found a NaN or infinity
  std::size_t stopped = 0;     // bodies a diverged solve stopped (World::body_stopped_events)
  int quiet_phases = 0;
  double worst_energy_gain = 0;       // J, largest rise of energy in a quiet phase
  double energy_tolerance = 0;        // J, the largest tolerance a quiet phase allowed
  std::size_t energy_violations = 0;  // quiet-phase checks above their tolerance
  double peak_kinetic_energy = 0;     // J
  long warm_rss_kb = 0;               // after warm-up
  long final_rss_kb = 0;              // at the end
  long peak_rss_kb = 0;               // largest seen after warm-up
  std::uint64_t final_hash = 0;       // test::state_hash at the end
};

inline long resident_kb() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

class Soak {
 public:
  explicit Soak(const SoakOptions& options)
      : options_(options), random_(options.seed), world_(world_def(options)) {
    build_arena();
    while (static_cast<int>(dynamic_.size()) < options_.target_bodies) add_random_body();
  }

  SoakResult run() {
    const int phase = 600;  // steps: a driven phase, then a quiet one, alternating
    const int warm_up = std::min(options_.steps / 5, 4 * phase);
    for (int step = 1; step <= options_.steps; ++step) {
      const bool quiet = (step / phase) % 2 == 1;
      const int in_phase = step % phase;
      if (quiet && in_phase == 1) begin_quiet();
      if (!quiet) drive(step);
      world_.step();
      result_.stopped += world_.body_stopped_events().size();
      ++result_.steps;
      if (step % options_.check_every == 0) check(quiet && in_phase > kQuietSettle, in_phase);
      if (step == warm_up) result_.warm_rss_kb = resident_kb();
      if (step > warm_up && step % 500 == 0) {
        result_.peak_rss_kb = std::max(result_.peak_rss_kb, resident_kb());
      }
    }
    result_.final_rss_kb = resident_kb();
    result_.peak_rss_kb = std::max(result_.peak_rss_kb, result_.final_rss_kb);
    result_.final_hash = test::state_hash(world_);
    return result_;
  }

  // Arena: a closed box, inside it a platform, a ramp and a bumpy chain floor.
  static constexpr Real kHalfWidth = 30;
  static constexpr Real kHeight = 60;
  static constexpr Real kMargin = 2;       // a body this far outside the arena has escaped
  static constexpr int kQuietSettle = 60;  // steps of a quiet phase before energy is watched

 private:
  static WorldDef world_def(const SoakOptions& options) {
    WorldDef def;
    def.worker_count = options.workers;
    def.gravity = Vec2(0, -10);
    // Even seeds leave fast bodies' boxes bare, as Box2D v3 does: both ways are soaked.
    def.fast_body_margin = options.seed % 2 == 1;
    return def;
  }

  Real uniform(Real lo, Real hi) { return std::uniform_real_distribution<Real>(lo, hi)(random_); }
  int pick(int count) { return std::uniform_int_distribution<int>(0, count - 1)(random_); }

  void build_arena() {
    const BodyId ground = world_.create_body({});
    // Clockwise: a chain collides on the right of each segment, here the inside.
    std::vector<Vec2> box = {{-kHalfWidth, kHeight}, {kHalfWidth, kHeight}, {kHalfWidth, 0}};
    for (int i = 59; i >= 1; --i) {
      const Real x = -kHalfWidth + 2 * kHalfWidth * i / 60;
      box.emplace_back(x, 0.4 * std::sin(0.7 * x) + 0.4);
    }
    box.emplace_back(-kHalfWidth, 0);
    world_.create_chain(ground, ShapeDef::chain(box, true));
    // Belt and braces under the chain: a thick floor and walls of polygons.
    world_.create_shape(ground, ShapeDef::box(kHalfWidth + 1, 1, Vec2(0, -1)));
    world_.create_shape(ground, ShapeDef::box(1, kHeight / 2, Vec2(-kHalfWidth - 1, kHeight / 2)));
    world_.create_shape(ground, ShapeDef::box(1, kHeight / 2, Vec2(kHalfWidth + 1, kHeight / 2)));
    world_.create_shape(ground, ShapeDef::box(kHalfWidth + 1, 1, Vec2(0, kHeight + 1)));
    world_.create_shape(ground, ShapeDef::segment(Vec2(-20, 15), Vec2(-5, 12)));
    world_.create_shape(ground, ShapeDef::box(4, 0.3, Vec2(12, 20), 0.2));
    ground_ = ground;
    // Kinematic movers: a paddle sliding to and fro and a spinning bar.
    for (int i = 0; i < 2; ++i) {
      BodyDef def;
      def.type = BodyType::kinematic;
      def.position = Vec2(i == 0 ? -10 : 10, i == 0 ? 4 : 30);
      const BodyId mover = world_.create_body(def);
      world_.create_shape(
          mover, i == 0 ? ShapeDef::box(3, 0.4) : ShapeDef::capsule(Vec2(-4, 0), Vec2(4, 0), 0.3));
      movers_.push_back(mover);
    }
  }

  ShapeDef random_material(ShapeDef shape) {
    shape.density = uniform(0.2, 5);
    shape.friction = uniform(0, 1);
    shape.restitution = pick(4) == 0 ? uniform(0, 0.9) : 0;
    return shape;
  }

  ShapeDef random_shape(Real size) {
    switch (pick(4)) {
      case 0:
        return random_material(ShapeDef::circle(size));
      case 1:
        return random_material(
            ShapeDef::capsule(Vec2(-size, 0), Vec2(size, 0), size * uniform(0.2, 0.6)));
      case 2:
        return random_material(ShapeDef::box(size * uniform(0.3, 1), size * uniform(0.3, 1)));
      default: {
        ShapeDef polygon;
        const int count = 3 + pick(6);
        for (int i = 0; i < count; ++i) {
          const Real angle = 2 * std::numbers::pi * (i + uniform(0, 0.6)) / count;
          polygon.points.emplace_back(size * std::cos(angle), size * std::sin(angle));
        }
        polygon.radius = pick(3) == 0 ? 0.05 * size : 0;
        return random_material(polygon);
      }
    }
  }

  BodyId add_random_body() {
    BodyDef def;
    def.type = BodyType::dynamic;
    def.position = Vec2(uniform(-kHalfWidth + 3, kHalfWidth - 3), uniform(8, kHeight - 5));
    def.angle = uniform(-3, 3);
    def.linear_velocity = Vec2(uniform(-3, 3), uniform(-3, 3));
    const BodyId body = world_.create_body(def);
    const Real size = uniform(0.2, 0.8);
    world_.create_shape(body, random_shape(size));
    // Now and then a second shape, and a segment (no area) riding along.
    if (pick(4) == 0) {
      ShapeDef extra = random_shape(size * 0.6);
      for (Vec2& p : extra.points) p += Vec2(size, 0);
      world_.create_shape(body, extra);
    }
    if (pick(6) == 0) world_.create_shape(body, ShapeDef::segment(Vec2(-size, 0), Vec2(0, size)));
    dynamic_.push_back(body);
    ++result_.bodies_created;
    return body;
  }

  // Two new bodies joined by a random kind of joint (a gear couples two new revolute joints to
  // the ground; a pulley hangs from two ground points).
  void add_jointed_pair() {
    const BodyId a = add_random_body();
    const BodyId b = add_random_body();
    world_.set_transform(b, world_.position(a) + Vec2(1.2, 0), 0);
    const Vec2 pa = world_.position(a);
    Vec2 pb = world_.position(b);
    const Vec2 middle = 0.5 * (pa + pb);
    JointMotor motor{true, uniform(-3, 3), uniform(5, 50)};
    JointSpring spring{true, uniform(0.5, 4), uniform(0.1, 1), 0};
    JointLimit limit{true, -uniform(0, 1), uniform(0, 1)};
    switch (pick(8)) {
      case 0: {
        RevoluteJointDef def = revolute_joint_at(world_, a, b, middle);
        if (pick(2) == 0) def.limit = limit;
        if (pick(2) == 0) def.motor = motor;
        if (pick(2) == 0) def.spring = spring;
        add_joint(def);
        break;
      }
      case 1: {
        PrismaticJointDef def = prismatic_joint_at(world_, a, b, middle, Vec2(1, 0));
        if (pick(2) == 0) def.limit = limit;
        if (pick(2) == 0) def.motor = motor;
        if (pick(2) == 0) def.spring = spring;
        add_joint(def);
        break;
      }
      case 2: {
        DistanceJointDef def = distance_joint_at(world_, a, b, pa, pb);
        if (pick(2) == 0) def.spring = spring;
        if (pick(2) == 0) def.limit = {true, 0.5 * def.length, 1.5 * def.length};
        add_joint(def);
        break;
      }
      case 3: {
        WeldJointDef def = weld_joint_at(world_, a, b, middle);
        if (pick(2) == 0) {
          def.linear_hertz = uniform(1, 5);
          def.linear_damping_ratio = uniform(0.2, 1);
          def.angular_hertz = uniform(1, 5);
          def.angular_damping_ratio = uniform(0.2, 1);
        }
        add_joint(def);
        break;
      }
      case 4: {
        WheelJointDef def = wheel_joint_at(world_, a, b, pb, Vec2(0, 1));
        if (pick(2) == 0) def.motor = motor;
        add_joint(def);
        break;
      }
      case 5: {
        MotorJointDef def = motor_joint_at(world_, a, b);
        def.max_force = uniform(1, 50);
        def.max_torque = uniform(1, 20);
        add_joint(def);
        break;
      }
      case 6: {
        // Both pinned to the ground and free to collide: apart, or the contacts' push-out
        // (an energy source by design) would spin a pair that can never separate.
        world_.set_transform(b, pa + Vec2(pa.x() > 0 ? -3.5 : 3.5, 0), 0);
        pb = world_.position(b);
        const JointId j1 = add_joint(revolute_joint_at(world_, ground_, a, pa));
        const JointId j2 = add_joint(revolute_joint_at(world_, ground_, b, pb));
        GearJointDef def;
        def.joint1 = j1;
        def.joint2 = j2;
        def.ratio = uniform(0.5, 2) * (pick(2) == 0 ? 1 : -1);
        add_joint(def);
        break;
      }
      default: {
        const Vec2 ground_a = Vec2(pa.x(), std::min<Real>(pa.y() + 4, kHeight - 1));
        const Vec2 ground_b = Vec2(pb.x(), std::min<Real>(pb.y() + 4, kHeight - 1));
        add_joint(pulley_joint_at(world_, a, b, ground_a, ground_b, pa, pb, uniform(0.5, 2)));
        break;
      }
    }
  }

  template <typename Def>
  JointId add_joint(const Def& def) {
    ++result_.joints_created;
    return world_.create_joint(def);
  }

  void fire_bullet() {
    BodyDef def;
    def.type = BodyType::dynamic;
    def.position = Vec2(uniform(-kHalfWidth + 2, kHalfWidth - 2), uniform(5, kHeight - 5));
    const Real angle = uniform(0, 2 * std::numbers::pi);
    def.linear_velocity = uniform(60, 150) * Vec2(std::cos(angle), std::sin(angle));
    def.bullet = true;
    const BodyId bullet = world_.create_body(def);
    world_.create_shape(bullet, random_material(ShapeDef::circle(uniform(0.05, 0.15))));
    dynamic_.push_back(bullet);
    ++result_.bodies_created;
    ++result_.bullets_fired;
  }

  void destroy_random_body() {
    const std::size_t index = static_cast<std::size_t>(pick(static_cast<int>(dynamic_.size())));
    destroy_at(index);
    ++result_.bodies_destroyed;
  }

  void destroy_at(std::size_t index) {
    const BodyId body = dynamic_[index];
    // A gear goes with either of its joints' bodies: destroy the joints touching the body
    // first, gears before the joints they couple.
    std::vector<JointId> joints = world_.body_joints(body);
    std::sort(joints.begin(), joints.end(), [&](JointId x, JointId y) {
      return (world_.joint_type(x) == JointType::gear) > (world_.joint_type(y) == JointType::gear);
    });
    for (const JointId joint : joints) {
      if (!world_.is_valid(joint)) continue;
      for (const JointId other : world_.joints()) {
        if (world_.joint_type(other) != JointType::gear) continue;
        const auto gear = std::get<GearJointDef>(world_.joint_def(other));
        if (gear.joint1 == joint || gear.joint2 == joint) world_.destroy_joint(other);
      }
      if (world_.is_valid(joint)) world_.destroy_joint(joint);
    }
    world_.destroy_body(body);
    dynamic_[index] = dynamic_.back();
    dynamic_.pop_back();
  }

  // Movers on, motors on, churn: the energy sources.
  void drive(int step) {
    const Real t = step * world_.def().time_step;
    // Along a path, so that the paddle never wanders however the phases cut its motion.
    world_.set_target_transform(movers_[0], Vec2(-10 + 4 * std::sin(1.5 * t), 4), 0,
                                world_.def().time_step);
    world_.set_angular_velocity(movers_[1], 2);
    if (step % 7 == 0) {
      if (static_cast<int>(dynamic_.size()) > options_.target_bodies) destroy_random_body();
      if (static_cast<int>(dynamic_.size()) < options_.target_bodies + 10) {
        if (pick(3) == 0) {
          add_jointed_pair();
        } else {
          add_random_body();
        }
      }
    }
    if (step % 41 == 0) fire_bullet();
    if (step % 97 == 0) {
      // Turn the motors back on (a quiet phase turned them off).
      for (const JointId joint : world_.joints()) {
        const JointType type = world_.joint_type(joint);
        if (type == JointType::motor) world_.set_motor_limits(joint, 30, 10);
        if (type == JointType::revolute || type == JointType::prismatic ||
            type == JointType::wheel) {
          world_.set_joint_motor(joint, {pick(2) == 0, uniform(-3, 3), uniform(5, 50)});
        }
      }
    }
  }

  // Stops every energy source: movers halt, motors off, no churn until the next driven phase.
  void begin_quiet() {
    ++result_.quiet_phases;
    for (const BodyId mover : movers_) {
      world_.set_linear_velocity(mover, Vec2(0, 0));
      world_.set_angular_velocity(mover, 0);
    }
    for (const JointId joint : world_.joints()) {
      const JointType type = world_.joint_type(joint);
      if (type == JointType::motor) world_.set_motor_limits(joint, 0, 0);
      if (type == JointType::revolute || type == JointType::prismatic || type == JointType::wheel ||
          type == JointType::distance) {
        world_.set_joint_motor(joint, {});
      }
    }
    quiet_baseline_set_ = false;
  }

  double kinetic_energy() const {
    double energy = 0;
    for (const BodyId body : dynamic_) {
      const Vec2 v = world_.linear_velocity(body);
      const Real w = world_.angular_velocity(body);
      energy +=
          0.5 * world_.mass(body) * v.squaredNorm() + 0.5 * world_.rotational_inertia(body) * w * w;
    }
    return energy;
  }

  double mechanical_energy() const {
    double energy = kinetic_energy();
    for (const BodyId body : dynamic_) {
      energy -= world_.mass(body) * world_.def().gravity.dot(world_.world_center(body));
    }
    return energy;
  }

  void check(bool watch_energy, int in_phase) {
    for (std::size_t i = 0; i < dynamic_.size();) {
      const BodyId body = dynamic_[i];
      if (!test::finite_state(world_, body)) {
        ++result_.non_finite;
        destroy_at(i);
        continue;
      }
      const Vec2 p = world_.position(body);
      if (std::abs(p.x()) > kHalfWidth + kMargin || p.y() < -kMargin || p.y() > kHeight + kMargin) {
        ++result_.escaped;  // the kill floor: removed, counted
        destroy_at(i);
        continue;
      }
      ++i;
    }
    const double kinetic = kinetic_energy();
    result_.peak_kinetic_energy = std::max(result_.peak_kinetic_energy, kinetic);
    if (!watch_energy) return;
    const double energy = mechanical_energy();
    if (!quiet_baseline_set_ && in_phase > kQuietSettle) {
      quiet_baseline_set_ = true;
      quiet_energy_ = energy;
      // Rounding, sprung joints settling and soft contacts pushing out: 1% of the kinetic
      // energy at the start, and 1 mJ per body.
      quiet_tolerance_ = 0.01 * kinetic + 1e-3 * static_cast<double>(dynamic_.size());
      result_.energy_tolerance = std::max(result_.energy_tolerance, quiet_tolerance_);
      return;
    }
    const double gain = energy - quiet_energy_;
    result_.worst_energy_gain = std::max(result_.worst_energy_gain, gain);
    if (gain > quiet_tolerance_) ++result_.energy_violations;
  }

  SoakOptions options_;
  std::mt19937_64 random_;
  World world_;
  BodyId ground_;
  std::vector<BodyId> movers_;
  std::vector<BodyId> dynamic_;
  SoakResult result_;
  bool quiet_baseline_set_ = false;
  double quiet_energy_ = 0;
  double quiet_tolerance_ = 0;
};

inline SoakResult run_soak(const SoakOptions& options) {
  return Soak(options).run();
}

inline void print_soak(const SoakOptions& options, const SoakResult& r, std::FILE* out) {
  std::fprintf(
      out,
      "seed %llu, %d workers: %d steps, %zu bodies made, %zu destroyed, %zu joints, "
      "%zu bullets; escaped %zu, non-finite %zu, stopped %zu; %d quiet phases, worst energy gain "
      "%.3g J (tolerance up to %.3g J, %zu over), peak kinetic energy %.4g J; RSS %ld kB "
      "after warm-up, %ld kB peak, %ld kB at the end; state hash %016llx\n",
      static_cast<unsigned long long>(options.seed), options.workers, r.steps, r.bodies_created,
      r.bodies_destroyed, r.joints_created, r.bullets_fired, r.escaped, r.non_finite, r.stopped,
      r.quiet_phases, r.worst_energy_gain, r.energy_tolerance, r.energy_violations,
      r.peak_kinetic_energy, r.warm_rss_kb, r.peak_rss_kb, r.final_rss_kb,
      static_cast<unsigned long long>(r.final_hash));
}

}  // namespace mink::soak
