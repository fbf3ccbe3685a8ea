// Joint definitions: names, and definitions filled in from world points.

#include "mink/engine/joint_def.hpp"

#include "mink/engine/world.hpp"

namespace mink {

std::string_view to_string(JointType type) noexcept {
  switch (type) {
    case JointType::revolute:
      return "revolute";
    case JointType::prismatic:
      return "prismatic";
    case JointType::distance:
      return "distance";
    case JointType::weld:
      return "weld";
    case JointType::wheel:
      return "wheel";
    case JointType::motor:
      return "motor";
    case JointType::gear:
      return "gear";
    case JointType::pulley:
      return "pulley";
  }
  return "unknown";
}

JointType joint_type(const JointDef& def) noexcept {
  return static_cast<JointType>(def.index());
}

JointBase& joint_base(JointDef& def) noexcept {
  return std::visit([](auto& d) -> JointBase& { return d; }, def);
}

const JointBase& joint_base(const JointDef& def) noexcept {
  return std::visit([](const auto& d) -> const JointBase& { return d; }, def);
}

namespace {

// A definition joining a and b with its anchors at world points, taken in each body's frame.
template <typename Def>
Def anchored(const World& world, BodyId a, BodyId b, const Vec2& anchor_a, const Vec2& anchor_b) {
  Def def;
  def.body_a = a;
  def.body_b = b;
  def.local_anchor_a = world.pose(a).apply_inverse(anchor_a);
  def.local_anchor_b = world.pose(b).apply_inverse(anchor_b);
  return def;
}

Real relative_angle(const World& world, BodyId a, BodyId b) {
  return world.angle(b) - world.angle(a);
}

// A world direction as a unit vector in a's frame (a zero vector stays zero and is refused
// by create_joint).
Vec2 local_axis(const World& world, BodyId a, const Vec2& axis) {
  const Real length = axis.norm();
  return world.pose(a).rotation.apply_inverse(length > 0 ? Vec2(axis / length) : axis);
}

}  // namespace

RevoluteJointDef revolute_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor) {
  auto def = anchored<RevoluteJointDef>(world, a, b, anchor, anchor);
  def.reference_angle = relative_angle(world, a, b);
  return def;
}

PrismaticJointDef prismatic_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor,
                                     const Vec2& axis) {
  auto def = anchored<PrismaticJointDef>(world, a, b, anchor, anchor);
  def.local_axis_a = local_axis(world, a, axis);
  def.reference_angle = relative_angle(world, a, b);
  return def;
}

DistanceJointDef distance_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor_a,
                                   const Vec2& anchor_b) {
  auto def = anchored<DistanceJointDef>(world, a, b, anchor_a, anchor_b);
  def.length = (anchor_b - anchor_a).norm();
  return def;
}

WeldJointDef weld_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor) {
  auto def = anchored<WeldJointDef>(world, a, b, anchor, anchor);
  def.reference_angle = relative_angle(world, a, b);
  return def;
}

WheelJointDef wheel_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor,
                             const Vec2& axis) {
  auto def = anchored<WheelJointDef>(world, a, b, anchor, anchor);
  def.local_axis_a = local_axis(world, a, axis);
  return def;
}

MotorJointDef motor_joint_at(const World& world, BodyId a, BodyId b) {
  MotorJointDef def;
  def.body_a = a;
  def.body_b = b;
  def.linear_offset = world.pose(a).apply_inverse(world.position(b));
  def.angular_offset = relative_angle(world, a, b);
  return def;
}

PulleyJointDef pulley_joint_at(const World& world, BodyId a, BodyId b, const Vec2& ground_a,
                               const Vec2& ground_b, const Vec2& anchor_a, const Vec2& anchor_b,
                               Real ratio) {
  auto def = anchored<PulleyJointDef>(world, a, b, anchor_a, anchor_b);
  def.ground_anchor_a = ground_a;
  def.ground_anchor_b = ground_b;
  def.length_a = (anchor_a - ground_a).norm();
  def.length_b = (anchor_b - ground_b).norm();
  def.ratio = ratio;
  return def;
}

}  // namespace mink
