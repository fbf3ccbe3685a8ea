// Joints: creation with the definition's checks, destruction (with their bodies, and gears
// with their joints), the constraint graph and island links, and the World API to read and
// change them. The per-kind solvers live in <kind>_joint.cpp; the step's part in
// joint_solver.cpp.

#include <algorithm>
#include <cmath>
#include <string>

#include "checks.hpp"
#include "mink/engine/world.hpp"
#include "record_scope.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::finite;
using detail::Joint;
using detail::require;

std::string to_string(JointId id) {
  return detail::id_string("JointId", id);
}

namespace {

// How far apart a world point and a body's anchor can lie: both within max_world_coordinate on
// each axis (an anchor's reach from its body is far less), with room.
constexpr Real kLongestLength = 4 * max_world_coordinate;

// The checks of one definition; `what` names the joint kind in messages.
class DefCheck {
 public:
  explicit DefCheck(std::string what) : what_(std::move(what)) {}
  void finite_value(Real v, const char* field) const {
    require(std::isfinite(v), what_ + "." + field + " must be finite, got " + std::to_string(v));
  }
  void finite_point(const Vec2& v, const char* field) const {
    require(finite(v), what_ + "." + field + " must be finite");
  }
  void non_negative(Real v, const char* field) const {
    require(std::isfinite(v) && v >= 0,
            what_ + "." + field + " must be finite and non-negative, got " + std::to_string(v));
  }
  void positive(Real v, const char* field) const {
    require(std::isfinite(v) && v > 0,
            what_ + "." + field + " must be positive and finite, got " + std::to_string(v));
  }
  void unit(const Vec2& v, const char* field) const {
    require(finite(v) && std::abs(v.norm() - 1) < 1e-6,
            what_ + "." + field + " must be a unit vector");
  }
  template <typename Def>
  void anchors(const Def& d) const {
    within_reach(d.local_anchor_a, "local_anchor_a");
    within_reach(d.local_anchor_b, "local_anchor_b");
  }
  // The solver works in single precision: a lever arm beyond max_joint_reach would overflow
  // its squared terms (an anchor 2e17 m from its body turned a chain NaN in one step).
  void within_reach(const Vec2& v, const char* field) const {
    finite_point(v, field);
    require(v.norm() <= max_joint_reach,
            what_ + "." + field + " must lie within " + detail::exact_number(max_joint_reach) +
                " m of its body's origin, got (" + detail::exact_number(v.x()) + ", " +
                detail::exact_number(v.y()) + ")");
  }
  // A frequency or damping ratio. Beyond max_setting_magnitude a spring's softness overflows
  // (a weld spring of 1e300 hertz held NaN in its joint's state) and is rigid long before.
  void rate(Real v, const char* field) const {
    require(detail::within_settings(v) && v >= 0,
            what_ + "." + field + " must be non-negative and within max_setting_magnitude (" +
                detail::exact_number(max_setting_magnitude) + "), got " + detail::exact_number(v));
  }
  void motor(const JointMotor& m) const {
    // As a body's velocity: a motor drives one at this speed.
    require(detail::within_settings(m.speed),
            what_ + ".motor.speed must be finite and within max_setting_magnitude (" +
                detail::exact_number(max_setting_magnitude) + "), got " +
                detail::exact_number(m.speed));
    non_negative(m.max_force, "motor.max_force");
  }
  void spring(const JointSpring& s) const {
    rate(s.hertz, "spring.hertz");
    rate(s.damping_ratio, "spring.damping_ratio");
    finite_value(s.target, "spring.target");
  }
  void limit(const JointLimit& l) const {
    finite_value(l.lower, "limit.lower");
    finite_value(l.upper, "limit.upper");
    require(l.lower <= l.upper, what_ + ".limit.lower must not exceed limit.upper, got " +
                                    std::to_string(l.lower) + " > " + std::to_string(l.upper));
  }
  void base(const JointBase& b) const {
    require(!std::isnan(b.break_force) && b.break_force >= 0,
            what_ + ".break_force must be non-negative");
    require(!std::isnan(b.break_torque) && b.break_torque >= 0,
            what_ + ".break_torque must be non-negative");
  }
  void in_world(const Vec2& v, const char* field) const {
    require(detail::within_world(v),
            what_ + "." + field + " must be finite and within max_world_coordinate (" +
                detail::exact_number(max_world_coordinate) + " m) on each axis");
  }
  // A rope or rod between a world point and a body's anchor.
  void length(Real v, const char* field) const {
    positive(v, field);
    require(v <= kLongestLength, what_ + "." + field + " must not exceed " +
                                     detail::exact_number(kLongestLength) + " m, got " +
                                     detail::exact_number(v));
  }
  const std::string& what() const { return what_; }

 private:
  std::string what_;
};

void check_def(const DefCheck& c, const RevoluteJointDef& d) {
  c.anchors(d);
  c.finite_value(d.reference_angle, "reference_angle");
  c.limit(d.limit);
  c.motor(d.motor);
  c.spring(d.spring);
}
void check_def(const DefCheck& c, const PrismaticJointDef& d) {
  c.anchors(d);
  c.unit(d.local_axis_a, "local_axis_a");
  c.finite_value(d.reference_angle, "reference_angle");
  c.limit(d.limit);
  c.motor(d.motor);
  c.spring(d.spring);
}
void check_def(const DefCheck& c, const DistanceJointDef& d) {
  c.anchors(d);
  c.positive(d.length, "length");
  c.limit(d.limit);
  c.non_negative(d.limit.lower, "limit.lower");
  c.motor(d.motor);
  c.spring(d.spring);
}
void check_def(const DefCheck& c, const WeldJointDef& d) {
  c.anchors(d);
  c.finite_value(d.reference_angle, "reference_angle");
  c.rate(d.linear_hertz, "linear_hertz");
  c.rate(d.linear_damping_ratio, "linear_damping_ratio");
  c.rate(d.angular_hertz, "angular_hertz");
  c.rate(d.angular_damping_ratio, "angular_damping_ratio");
}
void check_def(const DefCheck& c, const WheelJointDef& d) {
  c.anchors(d);
  c.unit(d.local_axis_a, "local_axis_a");
  c.limit(d.limit);
  c.motor(d.motor);
  c.spring(d.spring);
}
void check_def(const DefCheck& c, const MotorJointDef& d) {
  c.finite_point(d.linear_offset, "linear_offset");
  c.finite_value(d.angular_offset, "angular_offset");
  c.non_negative(d.max_force, "max_force");
  c.non_negative(d.max_torque, "max_torque");
  require(
      std::isfinite(d.correction_factor) && d.correction_factor >= 0 && d.correction_factor <= 1,
      c.what() + ".correction_factor must be in [0, 1]");
}
void check_def(const DefCheck& c, const GearJointDef& d) {
  require(std::isfinite(d.ratio) && d.ratio != 0, c.what() + ".ratio must be finite and non-zero");
  require(!(d.joint1 == d.joint2), c.what() + ": joint1 and joint2 must differ");
}
// The ground anchors are world points, so within the world; the lengths within what two
// points there can lie apart; the ratio within max_setting_magnitude. Beyond them the rope's
// coordinate, length_a + ratio * length_b, and its speed overflowed to infinity (a ratio or a
// ground anchor of 1.8e308).
void check_def(const DefCheck& c, const PulleyJointDef& d) {
  c.in_world(d.ground_anchor_a, "ground_anchor_a");
  c.in_world(d.ground_anchor_b, "ground_anchor_b");
  c.anchors(d);
  c.length(d.length_a, "length_a");
  c.length(d.length_b, "length_b");
  c.positive(d.ratio, "ratio");
  require(d.ratio <= max_setting_magnitude, c.what() +
                                                ".ratio must not exceed max_setting_magnitude (" +
                                                detail::exact_number(max_setting_magnitude) +
                                                "), got " + detail::exact_number(d.ratio));
}

void add_unique(std::vector<std::uint32_t>& list, std::uint32_t value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}
void remove_value(std::vector<std::uint32_t>& list, std::uint32_t value) {
  list.erase(std::remove(list.begin(), list.end(), value), list.end());
}

// The kind-specific state a new joint starts from (JointKind lists the kinds in JointDef's order).
template <std::size_t I = 0>
detail::JointKind make_kind(const JointDef& def) {
  if constexpr (I + 1 < std::variant_size_v<JointDef>) {
    if (def.index() != I) return make_kind<I + 1>(def);
  }
  std::variant_alternative_t<I, detail::JointKind> kind;
  kind.def = std::get<I>(def);
  return kind;
}

}  // namespace

void detail::check_joint_def(const JointDef& def) {
  const DefCheck check(std::string(to_string(mink::joint_type(def))) + " joint");
  std::visit([&](const auto& d) { check_def(check, d); }, def);
  check.base(joint_base(def));
}

JointId World::create_joint(const JointDef& def) {
  const detail::RecordScope record(*this, detail::Call::create_joint, def);
  WorldState& w = *state_;
  detail::check_joint_def(def);
  const DefCheck check(std::string(to_string(mink::joint_type(def))) + " joint");
  const JointBase& b = joint_base(def);

  Joint joint;
  if (const auto* gear = std::get_if<GearJointDef>(&def)) {
    const Joint& j1 = w.joint(gear->joint1);
    const Joint& j2 = w.joint(gear->joint2);
    for (const Joint* j : {&j1, &j2}) {
      const JointType t = detail::type_of(*j);
      require(t == JointType::revolute || t == JointType::prismatic,
              check.what() + ": joint1 and joint2 must be revolute or prismatic, got " +
                  std::string(to_string(t)));
    }
    joint.body = {j1.body[1], j2.body[1], j1.body[0], j2.body[0]};
    joint.body_count = 4;
    joint.gear_joints = {gear->joint1.index, gear->joint2.index};
  } else {
    w.body(b.body_a);
    w.body(b.body_b);
    require(!(b.body_a == b.body_b), check.what() + ": body_a and body_b must differ, got " +
                                         to_string(b.body_a) + " twice");
    joint.body = {b.body_a.index, b.body_b.index, 0, 0};
  }
  joint.kind = make_kind(def);
  if (auto* gear = std::get_if<detail::GearJoint>(&joint.kind)) {
    // The gear acts on its joints' bodies; its definition says so too.
    gear->def.body_a = w.body_id(joint.body[0]);
    gear->def.body_b = w.body_id(joint.body[1]);
    // It follows its joints' coordinates from their definitions, and holds their sum as now.
    for (std::size_t g = 0; g < 2; ++g) {
      const std::uint32_t geared = joint.gear_joints[g];
      detail::attach(*gear, g, detail::def_of(w.joints[geared]), w.joint_coordinate(geared));
    }
  }

  const std::uint32_t index = w.joints.allocate();
  Joint& slot = w.joints[index];
  const std::uint32_t generation = slot.generation;
  slot = std::move(joint);
  slot.alive = true;
  slot.generation = generation;
  if (detail::type_of(slot) == JointType::gear) {
    w.joints[slot.gear_joints[0]].gears.push_back(index);
    w.joints[slot.gear_joints[1]].gears.push_back(index);
  }
  for (int k = 0; k < slot.body_count; ++k) add_unique(w.bodies[slot.body[k]].joints, index);
  w.set_joint_bodies(index);
  // Settled state: a revolute's angle counts from where the bodies are now.
  const detail::JointBodyState sa = w.joint_body_state(slot.body[0]);
  const detail::JointBodyState sb = w.joint_body_state(slot.body[1]);
  std::visit([&](auto& k) { detail::finish_kind(k, sa, sb); }, slot.kind);
  w.recolor_joint(index);
  // Shapes of bodies that may no longer collide stop doing so at once.
  if (!b.collide_connected && slot.body_count == 2) {
    w.destroy_contacts_between(slot.body[0], slot.body[1]);
  }
  w.wake_joint_bodies(index);
  return w.joint_id(index);
}

void WorldState::destroy_joint(std::uint32_t index) {
  // Gears built on this joint go first.
  while (!joints[index].gears.empty()) destroy_joint(joints[index].gears.back());
  Joint& joint = joints[index];
  if (detail::type_of(joint) == JointType::gear) {
    remove_value(joints[joint.gear_joints[0]].gears, index);
    remove_value(joints[joint.gear_joints[1]].gears, index);
  }
  if (joint.color != detail::kNoColor) {
    graph.remove(joint.color, joint.body[0], joint.a_fixed, joint.body[1], joint.b_fixed);
    joint.color = detail::kNoColor;
  }
  const bool collide_connected = base(joint).collide_connected;
  for (int k = 0; k < joint.body_count; ++k) {
    Body& b = bodies[joint.body[k]];
    remove_value(b.joints, index);
    wake(b);
  }
  // Shapes the joint kept apart are paired again from the next step.
  if (!collide_connected && joint.body_count == 2) {
    for (const std::uint32_t s : bodies[joint.body[0]].shapes) refresh_proxy(s);
  }
  joints.release(index);
  set_joint_bodies(index);
}

void WorldState::set_joint_bodies(std::uint32_t index) {
  if (joint_bodies.size() < joints.size()) joint_bodies.resize(joints.size());
  const Joint& joint = joints.slots()[index];
  detail::JointBodies& ends = joint_bodies[index];
  ends = {};
  if (!joint.alive) return;
  ends.body = joint.body;
  ends.count = static_cast<std::uint32_t>(joint.body_count);
  ends.color = joint.color;
}

void WorldState::recolor_joint(std::uint32_t index) {
  Joint& joint = joints[index];
  if (joint.color != detail::kNoColor) {
    graph.remove(joint.color, joint.body[0], joint.a_fixed, joint.body[1], joint.b_fixed);
  }
  if (joint.body_count == 4) {
    // Four bodies do not fit the graph's pairs: a gear is solved one at a time.
    joint.color = detail::kOverflowColor;
  } else {
    joint.a_fixed = bodies[joint.body[0]].type != BodyType::dynamic;
    joint.b_fixed = bodies[joint.body[1]].type != BodyType::dynamic;
    joint.color = graph.add(joint.body[0], joint.a_fixed, joint.body[1], joint.b_fixed);
  }
  set_joint_bodies(index);
}

bool WorldState::joint_prevents_contact(std::uint32_t body_a, std::uint32_t body_b) const {
  const Body& a = bodies[body_a];
  const Body& b = bodies[body_b];
  const std::vector<std::uint32_t>& fewer =
      a.joints.size() <= b.joints.size() ? a.joints : b.joints;
  for (const std::uint32_t j : fewer) {
    const Joint& joint = joints[j];
    if (joint.body_count != 2 || base(joint).collide_connected) continue;
    if ((joint.body[0] == body_a && joint.body[1] == body_b) ||
        (joint.body[0] == body_b && joint.body[1] == body_a)) {
      return true;
    }
  }
  return false;
}

detail::JointBodyState WorldState::joint_body_state(std::uint32_t index) const {
  const Body& b = bodies[index];
  return {b.pose(), b.center, b.velocity, b.angular_velocity};
}

Real WorldState::joint_coordinate(std::uint32_t index) const {
  const Joint& j = joints[index];
  if (const auto* gear = std::get_if<detail::GearJoint>(&j.kind)) {
    return joint_coordinate(j.gear_joints[0]) +
           gear->def.ratio * joint_coordinate(j.gear_joints[1]);
  }
  const detail::JointBodyState a = joint_body_state(j.body[0]);
  const detail::JointBodyState b = joint_body_state(j.body[1]);
  return std::visit([&](const auto& k) { return detail::coordinate_of(k, a, b); }, j.kind);
}

Real WorldState::joint_speed(std::uint32_t index) const {
  const Joint& j = joints[index];
  if (const auto* gear = std::get_if<detail::GearJoint>(&j.kind)) {
    return joint_speed(j.gear_joints[0]) + gear->def.ratio * joint_speed(j.gear_joints[1]);
  }
  const detail::JointBodyState a = joint_body_state(j.body[0]);
  const detail::JointBodyState b = joint_body_state(j.body[1]);
  return std::visit([&](const auto& k) { return detail::speed_of(k, a, b); }, j.kind);
}

void WorldState::wake_joint_bodies(std::uint32_t index) {
  const Joint& joint = joints[index];
  for (int k = 0; k < joint.body_count; ++k) wake(bodies[joint.body[k]]);
}

void World::destroy_joint(JointId id) {
  const detail::RecordScope record(*this, detail::Call::destroy_joint, id);
  state_->joint(id);
  state_->destroy_joint(id.index);
}

bool World::is_valid(JointId id) const noexcept {
  return state_->joints.valid(id, state_->serial);
}

std::size_t World::joint_count() const noexcept {
  return state_->joints.live();
}

std::vector<JointId> World::joints() const {
  return state_->joints.live_ids<JointId>(state_->serial);
}

std::vector<JointId> World::body_joints(BodyId id) const {
  std::vector<std::uint32_t> slots = state_->body(id).joints;
  std::sort(slots.begin(), slots.end());
  std::vector<JointId> ids;
  for (const std::uint32_t j : slots) ids.push_back(state_->joint_id(j));
  return ids;
}

JointType World::joint_type(JointId id) const {
  return detail::type_of(state_->joint(id));
}

JointDef World::joint_def(JointId id) const {
  return detail::def_of(state_->joint(id));
}

BodyId World::joint_body_a(JointId id) const {
  return state_->body_id(state_->joint(id).body[0]);
}
BodyId World::joint_body_b(JointId id) const {
  return state_->body_id(state_->joint(id).body[1]);
}

namespace {

// The body-local anchors of kinds that have them; the body origins otherwise.
std::pair<Vec2, Vec2> local_anchors(const Joint& joint) {
  return std::visit(
      [](const auto& k) -> std::pair<Vec2, Vec2> {
        if constexpr (requires { k.def.local_anchor_a; }) {
          return {k.def.local_anchor_a, k.def.local_anchor_b};
        } else {
          return {Vec2(0, 0), Vec2(0, 0)};
        }
      },
      joint.kind);
}

}  // namespace

Vec2 World::joint_anchor_a(JointId id) const {
  const Joint& j = state_->joint(id);
  return state_->bodies[j.body[0]].pose().apply(local_anchors(j).first);
}
Vec2 World::joint_anchor_b(JointId id) const {
  const Joint& j = state_->joint(id);
  return state_->bodies[j.body[1]].pose().apply(local_anchors(j).second);
}
Vec2 World::joint_force(JointId id) const {
  return state_->joint(id).reaction.force;
}
Real World::joint_torque(JointId id) const {
  return state_->joint(id).reaction.torque;
}

Real World::joint_coordinate(JointId id) const {
  state_->joint(id);
  return state_->joint_coordinate(id.index);
}
Real World::joint_speed(JointId id) const {
  state_->joint(id);
  return state_->joint_speed(id.index);
}

namespace {

// The named part of a kind's definition (motor, spring, limit), or an error naming the kind.
template <typename Part, typename Get>
Part& part_of(Joint& joint, JointId id, const char* what, Get get) {
  Part* part = std::visit([&](auto& k) -> Part* { return get(k.def); }, joint.kind);
  require(part != nullptr, std::string(what) + " of " + to_string(id) + ": a " +
                               std::string(to_string(detail::type_of(joint))) + " joint has none");
  return *part;
}

template <typename Def>
concept HasMotor = requires(Def d) {
  d.motor;
};
template <typename Def>
concept HasSpring = requires(Def d) {
  d.spring;
};
template <typename Def>
concept HasLimit = requires(Def d) {
  d.limit;
};

JointMotor& motor_of(Joint& joint, JointId id, const char* what) {
  return part_of<JointMotor>(joint, id, what, [](auto& d) -> JointMotor* {
    if constexpr (HasMotor<std::decay_t<decltype(d)>>) return &d.motor;
    return nullptr;
  });
}
JointSpring& spring_of(Joint& joint, JointId id, const char* what) {
  return part_of<JointSpring>(joint, id, what, [](auto& d) -> JointSpring* {
    if constexpr (HasSpring<std::decay_t<decltype(d)>>) return &d.spring;
    return nullptr;
  });
}
JointLimit& limit_of(Joint& joint, JointId id, const char* what) {
  return part_of<JointLimit>(joint, id, what, [](auto& d) -> JointLimit* {
    if constexpr (HasLimit<std::decay_t<decltype(d)>>) return &d.limit;
    return nullptr;
  });
}

template <typename Kind>
Kind& kind_of(Joint& joint, JointId id, const char* what, JointType type) {
  Kind* k = std::get_if<Kind>(&joint.kind);
  require(k != nullptr, std::string(what) + " of " + to_string(id) + ": the joint is " +
                            std::string(to_string(detail::type_of(joint))) + ", not " +
                            std::string(to_string(type)));
  return *k;
}

}  // namespace

JointMotor World::joint_motor(JointId id) const {
  return motor_of(const_cast<Joint&>(state_->joint(id)), id, "joint_motor");
}
void World::set_joint_motor(JointId id, const JointMotor& motor) {
  const detail::RecordScope record(*this, detail::Call::set_joint_motor, id, motor);
  Joint& j = state_->joint(id);
  JointMotor& m = motor_of(j, id, "set_joint_motor");
  DefCheck("set_joint_motor of " + to_string(id)).motor(motor);
  m = motor;
  state_->wake_joint_bodies(id.index);
}

JointSpring World::joint_spring(JointId id) const {
  return spring_of(const_cast<Joint&>(state_->joint(id)), id, "joint_spring");
}
void World::set_joint_spring(JointId id, const JointSpring& spring) {
  const detail::RecordScope record(*this, detail::Call::set_joint_spring, id, spring);
  Joint& j = state_->joint(id);
  JointSpring& s = spring_of(j, id, "set_joint_spring");
  DefCheck("set_joint_spring of " + to_string(id)).spring(spring);
  s = spring;
  state_->wake_joint_bodies(id.index);
}

JointLimit World::joint_limit(JointId id) const {
  return limit_of(const_cast<Joint&>(state_->joint(id)), id, "joint_limit");
}
void World::set_joint_limit(JointId id, const JointLimit& limit) {
  const detail::RecordScope record(*this, detail::Call::set_joint_limit, id, limit);
  Joint& j = state_->joint(id);
  JointLimit& l = limit_of(j, id, "set_joint_limit");
  const DefCheck check("set_joint_limit of " + to_string(id));
  check.limit(limit);
  if (detail::type_of(j) == JointType::distance) check.non_negative(limit.lower, "limit.lower");
  l = limit;
  state_->wake_joint_bodies(id.index);
}

void World::set_distance_length(JointId id, Real length) {
  const detail::RecordScope record(*this, detail::Call::set_distance_length, id, length);
  Joint& j = state_->joint(id);
  auto& k = kind_of<detail::DistanceJoint>(j, id, "set_distance_length", JointType::distance);
  DefCheck("set_distance_length of " + to_string(id)).positive(length, "length");
  k.def.length = length;
  state_->wake_joint_bodies(id.index);
}

void World::set_motor_target(JointId id, const Vec2& linear_offset, Real angular_offset) {
  const detail::RecordScope record(*this, detail::Call::set_motor_target, id, linear_offset,
                                   angular_offset);
  Joint& j = state_->joint(id);
  auto& k = kind_of<detail::MotorJoint>(j, id, "set_motor_target", JointType::motor);
  const DefCheck check("set_motor_target of " + to_string(id));
  check.finite_point(linear_offset, "linear_offset");
  check.finite_value(angular_offset, "angular_offset");
  k.def.linear_offset = linear_offset;
  k.def.angular_offset = angular_offset;
  state_->wake_joint_bodies(id.index);
}

void World::set_motor_limits(JointId id, Real max_force, Real max_torque) {
  const detail::RecordScope record(*this, detail::Call::set_motor_limits, id, max_force,
                                   max_torque);
  Joint& j = state_->joint(id);
  auto& k = kind_of<detail::MotorJoint>(j, id, "set_motor_limits", JointType::motor);
  const DefCheck check("set_motor_limits of " + to_string(id));
  check.non_negative(max_force, "max_force");
  check.non_negative(max_torque, "max_torque");
  k.def.max_force = max_force;
  k.def.max_torque = max_torque;
  state_->wake_joint_bodies(id.index);
}

void World::set_weld_springs(JointId id, Real linear_hertz, Real linear_damping_ratio,
                             Real angular_hertz, Real angular_damping_ratio) {
  const detail::RecordScope record(*this, detail::Call::set_weld_springs, id, linear_hertz,
                                   linear_damping_ratio, angular_hertz, angular_damping_ratio);
  Joint& j = state_->joint(id);
  auto& k = kind_of<detail::WeldJoint>(j, id, "set_weld_springs", JointType::weld);
  WeldJointDef d = k.def;
  d.linear_hertz = linear_hertz;
  d.linear_damping_ratio = linear_damping_ratio;
  d.angular_hertz = angular_hertz;
  d.angular_damping_ratio = angular_damping_ratio;
  check_def(DefCheck("set_weld_springs of " + to_string(id)), d);
  k.def = d;
  state_->wake_joint_bodies(id.index);
}

void World::set_joint_break(JointId id, Real force, Real torque) {
  const detail::RecordScope record(*this, detail::Call::set_joint_break, id, force, torque);
  Joint& j = state_->joint(id);
  JointBase b = base(j);
  b.break_force = force;
  b.break_torque = torque;
  DefCheck("set_joint_break of " + to_string(id)).base(b);
  base(j).break_force = force;
  base(j).break_torque = torque;
}

std::span<const JointBreakEvent> World::joint_break_events() const noexcept {
  return state_->joint_break_events;
}

}  // namespace mink
