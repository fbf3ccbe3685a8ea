#pragma once

#include <cstdint>
#include <limits>
#include <string_view>
#include <variant>

#include "mink/engine/ids.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

class World;

/// @brief Which constraint a joint is.
enum class JointType : std::uint8_t {
  revolute,   ///< a shared point; the bodies turn freely about it
  prismatic,  ///< slides along an axis fixed in body A, no relative rotation
  distance,   ///< keeps two anchors at a length (rigid, sprung, or a rope between limits)
  weld,       ///< glues two bodies (rigid, or soft with linear and angular springs)
  wheel,      ///< a point on a line with a suspension spring, free to spin (vehicle wheels)
  motor,      ///< drives body B towards a target offset from body A with bounded force
  gear,       ///< couples the coordinates of two revolute or prismatic joints by a ratio
  pulley,     ///< two ropes over fixed ground anchors: length_a + ratio * length_b is constant
};

/// How far (m) a joint's local anchor may lie from its body's origin. The solver works in
/// single precision, where a longer lever arm would overflow the joint's squared terms and turn
/// the bodies' states into NaN; a joint definition with an anchor farther out is refused.
inline constexpr Real max_joint_reach = 1e6;

/// @brief "revolute", "prismatic", "distance", "weld", "wheel", "motor", "gear" or "pulley".
std::string_view to_string(JointType type) noexcept;

/// A motor on a joint's free coordinate: drives its speed to `speed` (rad/s for angles, m/s
/// for translations and lengths) with at most `max_force` (N m for angular motors, N for linear).
struct JointMotor {
  bool enabled = false;  ///< off: the coordinate runs free
  Real speed = 0;        ///< target speed of the coordinate; within max_setting_magnitude
  Real max_force = 0;    ///< N m for revolute and wheel, N for prismatic and distance; >= 0
};

/// A spring on a joint's free coordinate, pulling it towards `target` (radians, or metres) with
/// the stiffness of an oscillator of `hertz` and damping ratio `damping_ratio`. Stiffness is
/// given as a frequency so that it does not depend on the masses involved.
struct JointSpring {
  bool enabled = false;    ///< off: no spring
  Real hertz = 0;          ///< natural frequency, 0..max_setting_magnitude (0: holds the speed)
  Real damping_ratio = 0;  ///< 1 is critical; 0..max_setting_magnitude
  Real target = 0;         ///< rest value of the coordinate (distance: unused, see length)
};

/// @brief Lower and upper bounds on a joint's free coordinate (radians, or metres).
struct JointLimit {
  bool enabled = false;  ///< off: no bounds
  Real lower = 0;        ///< lower <= upper
  Real upper = 0;
};

/// What every joint has: its two bodies and how it reports and collides.
struct JointBase {
  BodyId body_a;                   ///< the first body (the reference frame of axes and angles)
  BodyId body_b;                   ///< the second body
  bool collide_connected = false;  ///< let the two bodies' shapes collide with each other
  /// A joint event is reported each step the constraint force exceeds this (N)...
  Real break_force = std::numeric_limits<Real>::infinity();
  /// ... or the constraint torque exceeds this (N m). The joint stays until destroyed.
  Real break_torque = std::numeric_limits<Real>::infinity();
  std::uint64_t user_data = 0;  ///< kept for the caller
};

/// Pins a point of body B to a point of body A; the bodies turn about it. The angle is B's
/// rotation relative to A, minus `reference_angle` (0 where the joint was made, by
/// revolute_joint_at).
struct RevoluteJointDef : JointBase {
  Vec2 local_anchor_a{0, 0};  ///< body-local (about the body origin)
  Vec2 local_anchor_b{0, 0};
  Real reference_angle = 0;  ///< B's angle minus A's at which the joint angle is 0
  JointLimit limit;          ///< angle bounds, radians (the angle counts full turns)
  JointMotor motor;          ///< max_force is a torque
  JointSpring spring;        ///< rotational spring, target an angle
};

/// Body B slides along `local_axis_a` (fixed in A) and may not rotate relative to A. The
/// translation is the anchors' offset along the axis.
struct PrismaticJointDef : JointBase {
  Vec2 local_anchor_a{0, 0};
  Vec2 local_anchor_b{0, 0};
  Vec2 local_axis_a{1, 0};  ///< unit, in A's frame
  Real reference_angle = 0;
  JointLimit limit;    ///< translation bounds, metres
  JointMotor motor;    ///< max_force is a force
  JointSpring spring;  ///< along the axis, target a translation
};

/// Keeps the anchors `length` apart: rigid; or sprung (`spring`); or, with `limit`, a rope
/// (slack below limit.upper) or a rod with play. `motor` drives the length's rate.
struct DistanceJointDef : JointBase {
  Vec2 local_anchor_a{0, 0};
  Vec2 local_anchor_b{0, 0};
  Real length = 1;     ///< rest length, > 0
  JointLimit limit;    ///< min and max length (lower >= 0)
  JointMotor motor;    ///< max_force is a force
  JointSpring spring;  ///< enabled: soft towards `length` (spring.target is not used)
};

/// Glues B to A at an anchor. With hertz 0 a part is rigid; with hertz > 0 it is a spring.
struct WeldJointDef : JointBase {
  Vec2 local_anchor_a{0, 0};
  Vec2 local_anchor_b{0, 0};
  Real reference_angle = 0;
  /// 0 hertz: rigid. Each 0..max_setting_magnitude.
  Real linear_hertz = 0, linear_damping_ratio = 0;
  Real angular_hertz = 0, angular_damping_ratio = 0;  ///< 0 hertz: rigid
};

/// A wheel: B's anchor stays on the line through A's anchor along `local_axis_a`, sprung along
/// it (the suspension), and B spins freely (the motor drives the spin).
struct WheelJointDef : JointBase {
  Vec2 local_anchor_a{0, 0};
  Vec2 local_anchor_b{0, 0};
  Vec2 local_axis_a{0, 1};              ///< unit suspension axis, in A's frame
  JointSpring spring{true, 1, 0.7, 0};  ///< suspension along the axis, target a translation
  JointLimit limit;                     ///< suspension travel, metres
  JointMotor motor;                     ///< drives B's spin relative to A; max_force a torque
};

/// Drives B towards `linear_offset` (its origin in A's frame) and `angular_offset` (its angle
/// relative to A) with at most `max_force` and `max_torque`; the sandbox drags bodies with it.
struct MotorJointDef : JointBase {
  Vec2 linear_offset{0, 0};  ///< B's origin in A's frame, the target
  Real angular_offset = 0;   ///< B's angle minus A's, the target
  Real max_force = 1;        ///< N, >= 0
  Real max_torque = 1;       ///< N m, >= 0
  /// Fraction of the position error turned into target speed per substep, [0, 1].
  Real correction_factor = 0.3;
};

/// Couples two revolute or prismatic joints: coordinate1 + ratio * coordinate2 stays constant.
/// body_a and body_b are ignored: the gear acts on the bodies of its joints (B of each moves,
/// A of each is the reference).
struct GearJointDef : JointBase {
  JointId joint1;  ///< a revolute or prismatic joint
  JointId joint2;  ///< a revolute or prismatic joint
  Real ratio = 1;  ///< non-zero
};

/// Hangs A and B from fixed ground points on ropes: length_a + ratio * length_b is constant
/// (the lengths when the joint is made, by pulley_joint_at).
struct PulleyJointDef : JointBase {
  Vec2 ground_anchor_a{0, 0};  ///< world point A's rope runs over, within max_world_coordinate
  Vec2 ground_anchor_b{0, 0};  ///< world point B's rope runs over, within max_world_coordinate
  Vec2 local_anchor_a{0, 0};
  Vec2 local_anchor_b{0, 0};
  Real length_a = 1;  ///< rope length on A's side when made, > 0, <= 4 max_world_coordinate
  Real length_b = 1;  ///< on B's side, > 0, <= 4 max_world_coordinate
  Real ratio = 1;     ///< > 0, <= max_setting_magnitude
};

/// @brief Any joint's definition; World::joint_def returns a joint's current settings as one.
using JointDef = std::variant<RevoluteJointDef, PrismaticJointDef, DistanceJointDef, WeldJointDef,
                              WheelJointDef, MotorJointDef, GearJointDef, PulleyJointDef>;

/// @brief The kind a definition makes.
JointType joint_type(const JointDef& def) noexcept;
/// @brief What every kind's definition shares (bodies, collide_connected, break thresholds).
JointBase& joint_base(JointDef& def) noexcept;
const JointBase& joint_base(const JointDef& def) noexcept;

/// @name Definitions from world points
/// Joints are defined in body-local terms; these fill them in from the bodies' current poses
/// in `world`, so the joint holds the bodies as they are now (angle and translation 0).
/// @{

/// @throws StaleIdError for a dead body.
RevoluteJointDef revolute_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor);
PrismaticJointDef prismatic_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor,
                                     const Vec2& axis);
/// @brief Length = the anchors' current distance.
DistanceJointDef distance_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor_a,
                                   const Vec2& anchor_b);
WeldJointDef weld_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor);
WheelJointDef wheel_joint_at(const World& world, BodyId a, BodyId b, const Vec2& anchor,
                             const Vec2& axis);
/// @brief Target = B's current offset from A.
MotorJointDef motor_joint_at(const World& world, BodyId a, BodyId b);
/// @brief Lengths from the current anchors to the ground anchors.
PulleyJointDef pulley_joint_at(const World& world, BodyId a, BodyId b, const Vec2& ground_a,
                               const Vec2& ground_b, const Vec2& anchor_a, const Vec2& anchor_b,
                               Real ratio);

/// @}

}  // namespace mink
