// minkowski.Body: a body's state as properties, forces and impulses, its shapes and joints.
#include <optional>
#include <type_traits>

#include "bindings.hpp"
#include "names.hpp"

namespace mink::python {

namespace {

// A read-write property of a body: a World getter and setter.
template <class T, class U>
void body_property(py::class_<BodyRef>& cls, const char* name, T (World::*get)(BodyId) const,
                   void (World::*set)(BodyId, U), const char* doc) {
  cls.def_property(
      name, [get](const BodyRef& b) { return (b.w().*get)(b.id); },
      [set](const BodyRef& b, std::decay_t<U> value) { (b.w().*set)(b.id, value); }, doc);
}

template <class T>
void body_readonly(py::class_<BodyRef>& cls, const char* name, T (World::*get)(BodyId) const,
                   const char* doc) {
  cls.def_property_readonly(
      name, [get](const BodyRef& b) { return (b.w().*get)(b.id); }, doc);
}

}  // namespace

void bind_bodies(py::module_& m, WorldClass& world) {
  py::class_<BodyRef> body(m, "Body", R"(A body of a World (World.create_body, World.bodies).

Handles compare equal when they name the same body. Using one after its body was destroyed
raises StaleIdError. Vectors are (x, y) tuples; position is the body origin's.)");
  bind_identity(body);
  body.def_property_readonly(
          "index", [](const BodyRef& b) { return b.id.index; },
          "Slot index: the row of the batch arrays while no body was destroyed, and how events "
          "name the body.")
      .def_property_readonly(
          "world", [](const BodyRef& b) { return b.world; }, "The World it belongs to.")
      .def_property_readonly(
          "valid", [](const BodyRef& b) { return b.w().is_valid(b.id); },
          "False once the body was destroyed.")
      .def_property(
          "type", [](const BodyRef& b) { return std::string(to_string(b.w().body_type(b.id))); },
          [](const BodyRef& b, const std::string& type) {
            b.w().set_body_type(b.id, parse_body_type(type));
          },
          "'static', 'kinematic' or 'dynamic'; setting it recomputes the mass.")
      .def_property(
          "position", [](const BodyRef& b) { return b.w().position(b.id); },
          [](const BodyRef& b, const Vec2& position) {
            b.w().set_transform(b.id, position, b.w().angle(b.id));
          },
          "World position of the origin; setting it teleports the body (angle kept).")
      .def_property(
          "angle", [](const BodyRef& b) { return b.w().angle(b.id); },
          [](const BodyRef& b, Real angle) {
            b.w().set_transform(b.id, b.w().position(b.id), angle);
          },
          "Radians, counter-clockwise; setting it turns the body about its origin.");
  body_property(body, "linear_velocity", &World::linear_velocity, &World::set_linear_velocity,
                "Velocity of the centre of mass, m/s.");
  body_property(body, "angular_velocity", &World::angular_velocity, &World::set_angular_velocity,
                "rad/s, counter-clockwise positive.");
  body_property(body, "awake", &World::is_awake, &World::set_awake,
                "False while asleep; setting False puts a dynamic body to sleep.");
  body_property(body, "enabled", &World::is_enabled, &World::set_enabled,
                "False: kept but neither simulated nor collided.");
  body_property(body, "fixed_rotation", &World::fixed_rotation, &World::set_fixed_rotation,
                "True: never rotates.");
  body_property(body, "bullet", &World::is_bullet, &World::set_bullet,
                "Continuous collision against dynamic bodies too.");
  body_property(body, "continuous_threshold", &World::continuous_threshold,
                &World::set_continuous_threshold,
                "A step moving it farther than this fraction of its thinnest half-width is swept.");
  body_property(body, "mass_data", &World::mass_data, &World::set_mass_data,
                "MassData in force; setting it overrides what the shapes give.");
  body_readonly(body, "world_center", &World::world_center, "Centre of mass, world.");
  body_readonly(body, "local_center", &World::local_center, "Centre of mass, body frame.");
  body_readonly(body, "mass", &World::mass, "kg (0 for static and kinematic bodies).");
  body_readonly(body, "rotational_inertia", &World::rotational_inertia,
                "About the centre of mass, kg m^2.");
  body_readonly(body, "linear_damping", &World::linear_damping, "As created.");
  body_readonly(body, "angular_damping", &World::angular_damping, "As created.");
  body_readonly(body, "gravity_scale", &World::gravity_scale, "As created.");
  body_readonly(body, "allow_sleep", &World::allow_sleep, "As created.");
  body_readonly(body, "user_data", &World::user_data, "As created.");
  body.def_property_readonly(
          "shapes",
          [](const BodyRef& b) {
            std::vector<ShapeRef> out;
            for (const ShapeId id : b.w().body_shapes(b.id)) out.push_back({b.world, id});
            return out;
          },
          "Its live shapes.")
      .def_property_readonly(
          "joints",
          [](const BodyRef& b) {
            std::vector<JointRef> out;
            for (const JointId id : b.w().body_joints(b.id)) out.push_back({b.world, id});
            return out;
          },
          "Its live joints.")
      .def(
          "set_transform",
          [](const BodyRef& b, const Vec2& position, Real angle) {
            b.w().set_transform(b.id, position, angle);
          },
          py::arg("position"), py::arg("angle"), "Teleports the origin to `position` at `angle`.")
      .def(
          "set_target_transform",
          [](const BodyRef& b, const Vec2& position, Real angle, std::optional<Real> time_step) {
            b.w().set_target_transform(b.id, position, angle,
                                       time_step.value_or(b.w().def().time_step));
          },
          py::arg("position"), py::arg("angle"), py::arg("time_step") = py::none(),
          "A kinematic body's velocities so that it reaches the pose after the next step.")
      .def(
          "apply_force",
          [](const BodyRef& b, const Vec2& force, std::optional<Vec2> point) {
            b.w().apply_force(b.id, force, point.value_or(b.w().world_center(b.id)));
          },
          py::arg("force"), py::arg("point") = py::none(),
          "A force (N, world) at a world point (default: the centre of mass), next step only.")
      .def(
          "apply_torque", [](const BodyRef& b, Real torque) { b.w().apply_torque(b.id, torque); },
          py::arg("torque"), "A torque (N m), next step only.")
      .def(
          "apply_impulse",
          [](const BodyRef& b, const Vec2& impulse, std::optional<Vec2> point) {
            b.w().apply_linear_impulse(b.id, impulse, point.value_or(b.w().world_center(b.id)));
          },
          py::arg("impulse"), py::arg("point") = py::none(),
          "Changes the velocity at once by an impulse (N s, world) at a world point (default: "
          "the centre of mass).")
      .def(
          "interpolated_pose",
          [](const BodyRef& b, Real alpha) {
            const Pose pose = b.w().interpolated_pose(b.id, alpha);
            return py::make_tuple(pose.position, pose.rotation.angle());
          },
          py::arg("alpha"),
          "(position, angle) blended between before (0) and after (1) the last step.")
      .def(
          "contacts",
          [](const BodyRef& b) {
            py::list out;
            for (const ContactData& c : b.w().body_contacts(b.id)) {
              py::list points;
              py::list separations;
              for (int i = 0; i < c.manifold.point_count; ++i) {
                points.append(c.manifold.points[static_cast<std::size_t>(i)].point);
                separations.append(c.manifold.points[static_cast<std::size_t>(i)].separation);
              }
              py::dict contact;
              contact["shape_a"] = ShapeRef{b.world, c.shape_a};
              contact["shape_b"] = ShapeRef{b.world, c.shape_b};
              contact["normal"] = c.manifold.normal;
              contact["points"] = points;
              contact["separations"] = separations;
              out.append(contact);
            }
            return out;
          },
          "Its contacts with manifold points: dicts of shape_a, shape_b, normal (A to B), "
          "points and separations.")
      .def(
          "destroy", [](const BodyRef& b) { b.w().destroy_body(b.id); },
          "Destroys the body, its shapes and joints.")
      .def("__repr__", [](const BodyRef& b) {
        if (!b.world->world().is_valid(b.id)) {
          return "<minkowski.Body " + std::to_string(b.id.index) + " (destroyed)>";
        }
        const Vec2 p = b.w().position(b.id);
        return "<minkowski.Body " + std::to_string(b.id.index) + " " +
               std::string(to_string(b.w().body_type(b.id))) + " at (" + std::to_string(p.x()) +
               ", " + std::to_string(p.y()) + ")>";
      });

  world.def(
      "destroy_body", [](WorldHandle& w, const BodyRef& b) { w.world().destroy_body(b.id); },
      py::arg("body"), "Destroys the body, its shapes and joints.");
}

}  // namespace mink::python
