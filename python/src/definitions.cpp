// The plain-data definitions as Python classes with keyword constructors: Filter, the joint
// motor, spring and limit, mass data, BodyDef, ShapeDef and every joint kind's definition.
// Kinds and names travel as the scene files spell them ("dynamic", "capsule", "chan").
#include <pybind11/operators.h>

#include "bindings.hpp"
#include "names.hpp"

namespace mink::python {

namespace {

// A keyword constructor for a definition: every keyword is one of its properties.
template <class Def, class Class>
void keyword_constructor(Class& cls, const char* name) {
  cls.def(py::init(
      [name](const py::kwargs& settings) { return with_settings(Def{}, settings, name); }));
}

template <class Def, class Class>
void bind_joint_base(Class& cls) {
  cls.def_readwrite("collide_connected", &Def::collide_connected,
                    "let the two bodies' shapes collide with each other")
      .def_readwrite("break_force", &Def::break_force,
                     "N: a joint-break event each step the joint's force exceeds it (inf: none)")
      .def_readwrite("break_torque", &Def::break_torque,
                     "N m: a joint-break event each step the joint's torque exceeds it")
      .def_readwrite("user_data", &Def::user_data, "an integer kept for the caller");
}

template <class Def, class Class>
void bind_anchors(Class& cls) {
  cls.def_readwrite("local_anchor_a", &Def::local_anchor_a, "the anchor on body A, in A's frame")
      .def_readwrite("local_anchor_b", &Def::local_anchor_b, "the anchor on body B, in B's frame");
}

std::string vec_text(const Vec2& v) {
  return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ")";
}

}  // namespace

void bind_definitions(py::module_& m) {
  py::class_<Filter>(m, "Filter",
                     "Which shapes may touch. Two shapes collide when they share a non-zero group "
                     "(positive: always, negative: never), or else when each one's category "
                     "meets the other's mask.")
      .def(py::init<>())
      .def(py::init([](std::uint64_t category, std::uint64_t mask, std::int32_t group) {
             return Filter{category, mask, group};
           }),
           py::arg("category") = 1, py::arg("mask") = ~std::uint64_t{0}, py::arg("group") = 0)
      .def_readwrite("category", &Filter::category, "the bits this shape is")
      .def_readwrite("mask", &Filter::mask, "the bits this shape collides with")
      .def_readwrite("group", &Filter::group,
                     "0: none; same positive: always collide; same negative: never")
      .def("collides_with", &should_collide, py::arg("other"),
           "True when shapes with these two filters may touch.")
      .def(py::self == py::self)
      .def(py::pickle([](const Filter& f) { return py::make_tuple(f.category, f.mask, f.group); },
                      [](const py::tuple& t) {
                        return Filter{t[0].cast<std::uint64_t>(), t[1].cast<std::uint64_t>(),
                                      t[2].cast<std::int32_t>()};
                      }))
      .def("__repr__", [](const Filter& f) {
        return "Filter(category=" + std::to_string(f.category) +
               ", mask=" + std::to_string(f.mask) + ", group=" + std::to_string(f.group) + ")";
      });

  py::class_<JointMotor>(m, "JointMotor",
                         "A motor on a joint's free coordinate: drives its speed to `speed` "
                         "(rad/s or m/s) with at most `max_force` (N m for angular motors).")
      .def(py::init([](Real speed, Real max_force, bool enabled) {
             return JointMotor{enabled, speed, max_force};
           }),
           py::arg("speed") = 0.0, py::arg("max_force") = 0.0, py::arg("enabled") = true)
      .def_readwrite("enabled", &JointMotor::enabled)
      .def_readwrite("speed", &JointMotor::speed)
      .def_readwrite("max_force", &JointMotor::max_force)
      .def("__repr__", [](const JointMotor& j) {
        return "JointMotor(speed=" + std::to_string(j.speed) +
               ", max_force=" + std::to_string(j.max_force) +
               ", enabled=" + (j.enabled ? "True" : "False") + ")";
      });

  py::class_<JointSpring>(m, "JointSpring",
                          "A spring on a joint's free coordinate, towards `target`, as stiff as "
                          "an oscillator of `hertz` with `damping_ratio` (1: critical).")
      .def(py::init([](Real hertz, Real damping_ratio, Real target, bool enabled) {
             return JointSpring{enabled, hertz, damping_ratio, target};
           }),
           py::arg("hertz") = 0.0, py::arg("damping_ratio") = 0.0, py::arg("target") = 0.0,
           py::arg("enabled") = true)
      .def_readwrite("enabled", &JointSpring::enabled)
      .def_readwrite("hertz", &JointSpring::hertz)
      .def_readwrite("damping_ratio", &JointSpring::damping_ratio)
      .def_readwrite("target", &JointSpring::target)
      .def("__repr__", [](const JointSpring& j) {
        return "JointSpring(hertz=" + std::to_string(j.hertz) +
               ", damping_ratio=" + std::to_string(j.damping_ratio) +
               ", target=" + std::to_string(j.target) +
               ", enabled=" + (j.enabled ? "True" : "False") + ")";
      });

  py::class_<JointLimit>(m, "JointLimit",
                         "Bounds on a joint's free coordinate (radians or metres), lower <= upper.")
      .def(py::init([](Real lower, Real upper, bool enabled) {
             return JointLimit{enabled, lower, upper};
           }),
           py::arg("lower") = 0.0, py::arg("upper") = 0.0, py::arg("enabled") = true)
      .def_readwrite("enabled", &JointLimit::enabled)
      .def_readwrite("lower", &JointLimit::lower)
      .def_readwrite("upper", &JointLimit::upper)
      .def("__repr__", [](const JointLimit& j) {
        return "JointLimit(lower=" + std::to_string(j.lower) +
               ", upper=" + std::to_string(j.upper) +
               ", enabled=" + (j.enabled ? "True" : "False") + ")";
      });

  py::class_<MassData>(m, "MassData",
                       "Mass (kg), centre of mass (body frame) and rotational "
                       "inertia about it.")
      .def(py::init([](Real mass, const Vec2& center, Real rotational_inertia) {
             return MassData{mass, center, rotational_inertia};
           }),
           py::arg("mass") = 0.0, py::arg("center") = Vec2(0, 0),
           py::arg("rotational_inertia") = 0.0)
      .def_readwrite("mass", &MassData::mass)
      .def_readwrite("center", &MassData::center)
      .def_readwrite("rotational_inertia", &MassData::rotational_inertia)
      .def("__repr__", [](const MassData& d) {
        return "MassData(mass=" + std::to_string(d.mass) + ", center=" + vec_text(d.center) +
               ", rotational_inertia=" + std::to_string(d.rotational_inertia) + ")";
      });

  py::class_<BodyDef> body(m, "BodyDef",
                           "Everything World.create_body needs; its keyword arguments are these "
                           "properties (the scene file's body keys).");
  keyword_constructor<BodyDef>(body, "BodyDef");
  body.def_property(
          "type", [](const BodyDef& d) { return std::string(to_string(d.type)); },
          [](BodyDef& d, const std::string& type) { d.type = parse_body_type(type); },
          "'static', 'kinematic' or 'dynamic'")
      .def_readwrite("position", &BodyDef::position, "of the body origin, world")
      .def_readwrite("angle", &BodyDef::angle, "radians, counter-clockwise")
      .def_readwrite("linear_velocity", &BodyDef::linear_velocity, "m/s")
      .def_readwrite("angular_velocity", &BodyDef::angular_velocity, "rad/s")
      .def_readwrite("linear_damping", &BodyDef::linear_damping, ">= 0")
      .def_readwrite("angular_damping", &BodyDef::angular_damping, ">= 0")
      .def_readwrite("gravity_scale", &BodyDef::gravity_scale, "multiplies the world's gravity")
      .def_readwrite("allow_sleep", &BodyDef::allow_sleep, "False keeps the body awake")
      .def_readwrite("awake", &BodyDef::awake, "False creates it asleep")
      .def_readwrite("enabled", &BodyDef::enabled, "False: kept but neither simulated nor collided")
      .def_readwrite("fixed_rotation", &BodyDef::fixed_rotation, "True: never rotates")
      .def_readwrite("bullet", &BodyDef::bullet, "continuous collision against dynamic bodies too")
      .def_readwrite("continuous_threshold", &BodyDef::continuous_threshold,
                     "a step moving it farther than this fraction of its thinnest half-width "
                     "is swept")
      .def_readwrite("user_data", &BodyDef::user_data, "an integer kept for the caller");

  py::class_<ShapeDef> shape(
      m, "ShapeDef",
      "A shape: a convex core (`points`, body frame) plus a rounding `radius`, its material, "
      "filter and event flags. The class methods make each kind; keyword arguments are these "
      "properties (the scene file's shape keys).");
  keyword_constructor<ShapeDef>(shape, "ShapeDef");
  shape
      .def_property(
          "type", [](const ShapeDef& d) { return std::string(to_string(d.type)); },
          [](ShapeDef& d, const std::string& type) { d.type = parse_shape_type(type); },
          "'polygon', 'circle', 'capsule', 'segment' or 'chain'")
      .def_property(
          "points", [](const ShapeDef& d) { return points_array(d.points); },
          [](ShapeDef& d, std::vector<Vec2> points) { d.points = std::move(points); },
          "core points, body frame, as an (n, 2) array")
      .def_readwrite("radius", &ShapeDef::radius, "circle and capsule radius, polygon rounding")
      .def_readwrite("loop", &ShapeDef::loop, "chains: join the last point to the first")
      .def_property(
          "algorithm", [](const ShapeDef& d) { return std::string(to_string(d.algorithm)); },
          [](ShapeDef& d, const std::string& name) { d.algorithm = parse_hull_algorithm(name); },
          "polygons: the hull algorithm ('chan', 'divide-conquer', 'graham', 'jarvis', "
          "'monotone-chain')")
      .def_readwrite("density", &ShapeDef::density, "kg/m^2")
      .def_readwrite("friction", &ShapeDef::friction, "Coulomb coefficient")
      .def_readwrite("restitution", &ShapeDef::restitution, "bounciness (0: none)")
      .def_property(
          "scale",
          [](const ShapeDef& d) -> py::object {
            if (!d.scale) return py::none();
            return py::make_tuple(d.scale->fixed_point, d.scale->factor);
          },
          [](ShapeDef& d, const std::optional<std::pair<Vec2, Vec2>>& scale) {
            if (scale) {
              d.scale = ShapeScale{scale->first, scale->second};
            } else {
              d.scale.reset();
            }
          },
          "polygons: None, or (fixed_point, factor) applied to the points before hulling")
      .def_readwrite("filter", &ShapeDef::filter, "which shapes it may touch")
      .def_readwrite("sensor", &ShapeDef::is_sensor,
                     "detects overlap (sensor events), never pushes")
      .def_readwrite("contact_events", &ShapeDef::enable_contact_events,
                     "begin and end contact events for its pairs")
      .def_readwrite("sensor_events", &ShapeDef::enable_sensor_events,
                     "sensors see this shape (and a sensor reports at all)")
      .def_readwrite("hit_events", &ShapeDef::enable_hit_events, "hit events for its pairs")
      .def_readwrite("user_data", &ShapeDef::user_data, "an integer kept for the caller")
      .def_static(
          "box",
          [](Real hx, Real hy, const Vec2& center, Real angle, const py::kwargs& settings) {
            return with_settings(ShapeDef::box(hx, hy, center, angle), settings, "box");
          },
          py::arg("hx"), py::arg("hy"), py::arg("center") = Vec2(0, 0), py::arg("angle") = 0.0,
          "A box of half extents (hx, hy) about `center`, turned by `angle`.")
      .def_static(
          "circle",
          [](Real radius, const Vec2& center, const py::kwargs& settings) {
            return with_settings(ShapeDef::circle(radius, center), settings, "circle");
          },
          py::arg("radius"), py::arg("center") = Vec2(0, 0), "A disk.")
      .def_static(
          "capsule",
          [](const Vec2& center1, const Vec2& center2, Real radius, const py::kwargs& settings) {
            return with_settings(ShapeDef::capsule(center1, center2, radius), settings, "capsule");
          },
          py::arg("center1"), py::arg("center2"), py::arg("radius"),
          "The points within `radius` of the segment center1-center2.")
      .def_static(
          "segment",
          [](const Vec2& point1, const Vec2& point2, const py::kwargs& settings) {
            return with_settings(ShapeDef::segment(point1, point2), settings, "segment");
          },
          py::arg("point1"), py::arg("point2"), "A two-sided segment.")
      .def_static(
          "polygon",
          [](std::vector<Vec2> points, Real radius, const py::kwargs& settings) {
            ShapeDef def;
            def.points = std::move(points);
            def.radius = radius;
            return with_settings(std::move(def), settings, "polygon");
          },
          py::arg("points"), py::arg("radius") = 0.0,
          "The convex hull of `points` (any point set), rounded by `radius`.")
      .def_static(
          "regular_polygon",
          [](int count, Real radius, const Vec2& center, const py::kwargs& settings) {
            return with_settings(ShapeDef::regular_polygon(count, radius, center), settings,
                                 "regular_polygon");
          },
          py::arg("count"), py::arg("radius"), py::arg("center") = Vec2(0, 0),
          "`count` vertices on a circle of `radius` (not a rounding).")
      .def_static(
          "chain",
          [](std::vector<Vec2> points, bool loop, const py::kwargs& settings) {
            return with_settings(ShapeDef::chain(std::move(points), loop), settings, "chain");
          },
          py::arg("points"), py::arg("loop") = false,
          "One-sided segments through `points`, colliding on the right of each.")
      .def("__repr__", [](const ShapeDef& d) {
        return "ShapeDef(type='" + std::string(to_string(d.type)) +
               "', points=" + std::to_string(d.points.size()) +
               ", radius=" + std::to_string(d.radius) + ")";
      });

  py::class_<RevoluteJointDef> revolute(
      m, "RevoluteJointDef",
      "A shared point; the bodies turn about it. The angle is B's rotation relative to A, less "
      "reference_angle.");
  keyword_constructor<RevoluteJointDef>(revolute, "RevoluteJointDef");
  bind_anchors<RevoluteJointDef>(revolute);
  bind_joint_base<RevoluteJointDef>(revolute);
  revolute.def_readwrite("reference_angle", &RevoluteJointDef::reference_angle)
      .def_readwrite("limit", &RevoluteJointDef::limit, "angle bounds, radians")
      .def_readwrite("motor", &RevoluteJointDef::motor, "max_force is a torque")
      .def_readwrite("spring", &RevoluteJointDef::spring, "target an angle");

  py::class_<PrismaticJointDef> prismatic(
      m, "PrismaticJointDef",
      "B slides along local_axis_a (fixed in A) without turning relative to A.");
  keyword_constructor<PrismaticJointDef>(prismatic, "PrismaticJointDef");
  bind_anchors<PrismaticJointDef>(prismatic);
  bind_joint_base<PrismaticJointDef>(prismatic);
  prismatic.def_readwrite("local_axis_a", &PrismaticJointDef::local_axis_a, "unit, A's frame")
      .def_readwrite("reference_angle", &PrismaticJointDef::reference_angle)
      .def_readwrite("limit", &PrismaticJointDef::limit, "translation bounds, metres")
      .def_readwrite("motor", &PrismaticJointDef::motor, "max_force is a force")
      .def_readwrite("spring", &PrismaticJointDef::spring, "target a translation");

  py::class_<DistanceJointDef> distance(
      m, "DistanceJointDef",
      "Keeps the anchors `length` apart: rigid, sprung, or with a limit a rope.");
  keyword_constructor<DistanceJointDef>(distance, "DistanceJointDef");
  bind_anchors<DistanceJointDef>(distance);
  bind_joint_base<DistanceJointDef>(distance);
  distance.def_readwrite("length", &DistanceJointDef::length, "rest length, > 0")
      .def_readwrite("limit", &DistanceJointDef::limit, "min and max length")
      .def_readwrite("motor", &DistanceJointDef::motor, "max_force is a force")
      .def_readwrite("spring", &DistanceJointDef::spring, "soft towards `length`");

  py::class_<WeldJointDef> weld(m, "WeldJointDef",
                                "Glues B to A; a part with hertz 0 is rigid, else a spring.");
  keyword_constructor<WeldJointDef>(weld, "WeldJointDef");
  bind_anchors<WeldJointDef>(weld);
  bind_joint_base<WeldJointDef>(weld);
  weld.def_readwrite("reference_angle", &WeldJointDef::reference_angle)
      .def_readwrite("linear_hertz", &WeldJointDef::linear_hertz)
      .def_readwrite("linear_damping_ratio", &WeldJointDef::linear_damping_ratio)
      .def_readwrite("angular_hertz", &WeldJointDef::angular_hertz)
      .def_readwrite("angular_damping_ratio", &WeldJointDef::angular_damping_ratio);

  py::class_<WheelJointDef> wheel(
      m, "WheelJointDef",
      "A wheel: B's anchor stays on A's axis, sprung along it; B spins freely (motor: the spin).");
  keyword_constructor<WheelJointDef>(wheel, "WheelJointDef");
  bind_anchors<WheelJointDef>(wheel);
  bind_joint_base<WheelJointDef>(wheel);
  wheel.def_readwrite("local_axis_a", &WheelJointDef::local_axis_a, "unit suspension axis")
      .def_readwrite("spring", &WheelJointDef::spring, "the suspension")
      .def_readwrite("limit", &WheelJointDef::limit, "suspension travel, metres")
      .def_readwrite("motor", &WheelJointDef::motor, "drives the spin; max_force a torque");

  py::class_<MotorJointDef> motor(
      m, "MotorJointDef",
      "Drives B towards linear_offset (its origin in A's frame) and angular_offset with "
      "bounded force and torque.");
  keyword_constructor<MotorJointDef>(motor, "MotorJointDef");
  bind_joint_base<MotorJointDef>(motor);
  motor.def_readwrite("linear_offset", &MotorJointDef::linear_offset)
      .def_readwrite("angular_offset", &MotorJointDef::angular_offset)
      .def_readwrite("max_force", &MotorJointDef::max_force)
      .def_readwrite("max_torque", &MotorJointDef::max_torque)
      .def_readwrite("correction_factor", &MotorJointDef::correction_factor, "in [0, 1]");

  py::class_<GearJointDef> gear(
      m, "GearJointDef",
      "Couples two revolute or prismatic joints: coordinate1 + ratio * coordinate2 is constant.");
  keyword_constructor<GearJointDef>(gear, "GearJointDef");
  bind_joint_base<GearJointDef>(gear);
  gear.def_readwrite("ratio", &GearJointDef::ratio, "non-zero");

  py::class_<PulleyJointDef> pulley(
      m, "PulleyJointDef",
      "Two ropes over fixed ground points: length_a + ratio * length_b is constant.");
  keyword_constructor<PulleyJointDef>(pulley, "PulleyJointDef");
  bind_anchors<PulleyJointDef>(pulley);
  bind_joint_base<PulleyJointDef>(pulley);
  pulley.def_readwrite("ground_anchor_a", &PulleyJointDef::ground_anchor_a, "world")
      .def_readwrite("ground_anchor_b", &PulleyJointDef::ground_anchor_b, "world")
      .def_readwrite("length_a", &PulleyJointDef::length_a)
      .def_readwrite("length_b", &PulleyJointDef::length_b)
      .def_readwrite("ratio", &PulleyJointDef::ratio, "> 0");
}

}  // namespace mink::python
