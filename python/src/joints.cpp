// minkowski.Joint and the World methods that make each kind: anchors given as world points
// (the *_joint_at helpers) or body-local through the definition's properties.
#include <optional>

#include "bindings.hpp"

namespace mink::python {

namespace {

template <class Def>
JointRef create(const WorldPtr& w, Def def, const py::kwargs& settings, const char* name) {
  def = with_settings(std::move(def), settings, name);
  return JointRef{w, w->world().create_joint(def)};
}

template <class Def>
Def between(const BodyRef& a, const BodyRef& b) {
  Def def;
  def.body_a = a.id;
  def.body_b = b.id;
  return def;
}

// Both anchors, or neither (then the definition's local anchors hold).
void require_pair(const std::optional<Vec2>& a, const std::optional<Vec2>& b,
                  const char* function) {
  if (a.has_value() != b.has_value()) {
    throw InvalidArgumentError(std::string(function) +
                               ": give both anchor_a and anchor_b (world points) or neither");
  }
}

}  // namespace

void bind_joints(py::module_& m, WorldClass& world) {
  py::class_<JointRef> joint(m, "Joint", R"(A joint between two bodies (World.*_joint).

Handles compare equal when they name the same joint. A joint is destroyed with either of its
bodies (a gear with either of its joints).)");
  bind_identity(joint);
  joint
      .def_property_readonly(
          "index", [](const JointRef& j) { return j.id.index; }, "Slot index, as events name it.")
      .def_property_readonly(
          "valid", [](const JointRef& j) { return j.w().is_valid(j.id); },
          "False once the joint was destroyed.")
      .def_property_readonly(
          "type", [](const JointRef& j) { return std::string(to_string(j.w().joint_type(j.id))); },
          "'revolute', 'prismatic', 'distance', 'weld', 'wheel', 'motor', 'gear' or 'pulley'.")
      .def_property_readonly(
          "body_a",
          [](const JointRef& j) {
            return BodyRef{j.world, j.w().joint_body_a(j.id)};
          },
          "Body A (the frame of axes and angles); a gear's: B of its first joint.")
      .def_property_readonly(
          "body_b",
          [](const JointRef& j) {
            return BodyRef{j.world, j.w().joint_body_b(j.id)};
          },
          "Body B; a gear's: B of its second joint.")
      .def_property_readonly(
          "anchor_a", [](const JointRef& j) { return j.w().joint_anchor_a(j.id); },
          "Anchor on A, world.")
      .def_property_readonly(
          "anchor_b", [](const JointRef& j) { return j.w().joint_anchor_b(j.id); },
          "Anchor on B, world.")
      .def_property_readonly(
          "force", [](const JointRef& j) { return j.w().joint_force(j.id); },
          "Constraint force on B during the last step, N, world.")
      .def_property_readonly(
          "torque", [](const JointRef& j) { return j.w().joint_torque(j.id); },
          "Constraint torque on B during the last step, N m.")
      .def_property_readonly(
          "coordinate", [](const JointRef& j) { return j.w().joint_coordinate(j.id); },
          "The free coordinate: revolute angle, prismatic or wheel translation, distance or "
          "pulley length, a gear's combination; 0 for weld and motor joints.")
      .def_property_readonly(
          "speed", [](const JointRef& j) { return j.w().joint_speed(j.id); },
          "The coordinate's rate of change.")
      .def_property(
          "motor", [](const JointRef& j) { return j.w().joint_motor(j.id); },
          [](const JointRef& j, const JointMotor& motor) { j.w().set_joint_motor(j.id, motor); },
          "JointMotor of a revolute, prismatic, distance or wheel joint.")
      .def_property(
          "spring", [](const JointRef& j) { return j.w().joint_spring(j.id); },
          [](const JointRef& j, const JointSpring& spring) {
            j.w().set_joint_spring(j.id, spring);
          },
          "JointSpring of a revolute, prismatic, distance or wheel joint.")
      .def_property(
          "limit", [](const JointRef& j) { return j.w().joint_limit(j.id); },
          [](const JointRef& j, const JointLimit& limit) { j.w().set_joint_limit(j.id, limit); },
          "JointLimit of a revolute, prismatic, distance or wheel joint.")
      .def_property_readonly(
          "settings", [](const JointRef& j) { return j.w().joint_def(j.id); },
          "The joint's current settings as its kind's definition (RevoluteJointDef, ...).")
      .def_property_readonly(
          "user_data",
          [](const JointRef& j) { return joint_base(j.w().joint_def(j.id)).user_data; },
          "As created.")
      .def(
          "set_length",
          [](const JointRef& j, Real length) { j.w().set_distance_length(j.id, length); },
          py::arg("length"), "A distance joint's rest length.")
      .def(
          "set_motor_target",
          [](const JointRef& j, const Vec2& linear_offset, Real angular_offset) {
            j.w().set_motor_target(j.id, linear_offset, angular_offset);
          },
          py::arg("linear_offset"), py::arg("angular_offset"),
          "A motor joint's target: B's origin in A's frame and B's angle relative to A.")
      .def(
          "set_motor_limits",
          [](const JointRef& j, Real max_force, Real max_torque) {
            j.w().set_motor_limits(j.id, max_force, max_torque);
          },
          py::arg("max_force"), py::arg("max_torque"), "A motor joint's force and torque bounds.")
      .def(
          "set_weld_springs",
          [](const JointRef& j, Real linear_hertz, Real linear_damping_ratio, Real angular_hertz,
             Real angular_damping_ratio) {
            j.w().set_weld_springs(j.id, linear_hertz, linear_damping_ratio, angular_hertz,
                                   angular_damping_ratio);
          },
          py::arg("linear_hertz"), py::arg("linear_damping_ratio"), py::arg("angular_hertz"),
          py::arg("angular_damping_ratio"), "A weld joint's stiffness (hertz 0: rigid).")
      .def(
          "set_break",
          [](const JointRef& j, Real force, Real torque) {
            j.w().set_joint_break(j.id, force, torque);
          },
          py::arg("force"), py::arg("torque"), "Break thresholds (math.inf: none).")
      .def(
          "destroy", [](const JointRef& j) { j.w().destroy_joint(j.id); },
          "Destroys the joint (and gears built on it).")
      .def("__repr__", [](const JointRef& j) {
        if (!j.world->world().is_valid(j.id)) {
          return "<minkowski.Joint " + std::to_string(j.id.index) + " (destroyed)>";
        }
        return "<minkowski.Joint " + std::to_string(j.id.index) + " " +
               std::string(to_string(j.w().joint_type(j.id))) + ">";
      });

  world
      .def(
          "revolute_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, std::optional<Vec2> anchor,
             const py::kwargs& settings) {
            auto def = anchor ? revolute_joint_at(w->world(), a.id, b.id, *anchor)
                              : between<RevoluteJointDef>(a, b);
            return create(w, def, settings, "revolute_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("anchor") = py::none(),
          "Pins the bodies at the world point `anchor` (else at the local anchors given); "
          "keyword arguments are RevoluteJointDef's properties (limit, motor, spring, ...).")
      .def(
          "prismatic_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, std::optional<Vec2> anchor,
             std::optional<Vec2> axis, const py::kwargs& settings) {
            PrismaticJointDef def = between<PrismaticJointDef>(a, b);
            if (anchor) {
              def = prismatic_joint_at(w->world(), a.id, b.id, *anchor, axis.value_or(Vec2(1, 0)));
            } else if (axis) {
              throw InvalidArgumentError(
                  "prismatic_joint: a world axis needs a world anchor (or give local_axis_a)");
            }
            return create(w, def, settings, "prismatic_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("anchor") = py::none(),
          py::arg("axis") = py::none(),
          "B slides along the world `axis` through `anchor`; keyword arguments are "
          "PrismaticJointDef's properties.")
      .def(
          "distance_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, std::optional<Vec2> anchor_a,
             std::optional<Vec2> anchor_b, const py::kwargs& settings) {
            require_pair(anchor_a, anchor_b, "distance_joint");
            auto def = anchor_a ? distance_joint_at(w->world(), a.id, b.id, *anchor_a, *anchor_b)
                                : between<DistanceJointDef>(a, b);
            return create(w, def, settings, "distance_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("anchor_a") = py::none(),
          py::arg("anchor_b") = py::none(),
          "Keeps the world points anchor_a (on A) and anchor_b (on B) at their distance; keyword "
          "arguments are DistanceJointDef's properties (length, limit, spring, motor, ...).")
      .def(
          "weld_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, std::optional<Vec2> anchor,
             const py::kwargs& settings) {
            auto def = anchor ? weld_joint_at(w->world(), a.id, b.id, *anchor)
                              : between<WeldJointDef>(a, b);
            return create(w, def, settings, "weld_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("anchor") = py::none(),
          "Glues the bodies as they are at the world point `anchor`; keyword arguments are "
          "WeldJointDef's properties (linear_hertz, angular_hertz, ...).")
      .def(
          "wheel_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, std::optional<Vec2> anchor,
             std::optional<Vec2> axis, const py::kwargs& settings) {
            WheelJointDef def = between<WheelJointDef>(a, b);
            if (anchor) {
              def = wheel_joint_at(w->world(), a.id, b.id, *anchor, axis.value_or(Vec2(0, 1)));
            } else if (axis) {
              throw InvalidArgumentError(
                  "wheel_joint: a world axis needs a world anchor (or give local_axis_a)");
            }
            return create(w, def, settings, "wheel_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("anchor") = py::none(),
          py::arg("axis") = py::none(),
          "A wheel B on A at the world point `anchor`, sprung along the world `axis`; keyword "
          "arguments are WheelJointDef's properties (spring, motor, limit, ...).")
      .def(
          "motor_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, const py::kwargs& settings) {
            return create(w, motor_joint_at(w->world(), a.id, b.id), settings, "motor_joint");
          },
          py::arg("body_a"), py::arg("body_b"),
          "Drives B towards its current offset from A (or linear_offset, angular_offset); "
          "keyword arguments are MotorJointDef's properties (max_force, max_torque, ...).")
      .def(
          "gear_joint",
          [](const WorldPtr& w, const JointRef& joint1, const JointRef& joint2, Real ratio,
             const py::kwargs& settings) {
            GearJointDef def;
            def.joint1 = joint1.id;
            def.joint2 = joint2.id;
            def.ratio = ratio;
            return create(w, def, settings, "gear_joint");
          },
          py::arg("joint1"), py::arg("joint2"), py::arg("ratio") = 1.0,
          "Couples two revolute or prismatic joints: coordinate1 + ratio * coordinate2 stays "
          "constant.")
      .def(
          "pulley_joint",
          [](const WorldPtr& w, const BodyRef& a, const BodyRef& b, const Vec2& ground_a,
             const Vec2& ground_b, const Vec2& anchor_a, const Vec2& anchor_b, Real ratio,
             const py::kwargs& settings) {
            return create(w,
                          pulley_joint_at(w->world(), a.id, b.id, ground_a, ground_b, anchor_a,
                                          anchor_b, ratio),
                          settings, "pulley_joint");
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("ground_a"), py::arg("ground_b"),
          py::arg("anchor_a"), py::arg("anchor_b"), py::arg("ratio") = 1.0,
          "Hangs A and B on ropes over the world points ground_a and ground_b from their world "
          "anchors: length_a + ratio * length_b stays constant.")
      .def(
          "destroy_joint", [](WorldHandle& w, const JointRef& j) { w.world().destroy_joint(j.id); },
          py::arg("joint"), "Destroys the joint (and gears built on it).");
}

}  // namespace mink::python
