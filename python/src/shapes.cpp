// minkowski.Shape and the Body.add_* methods that make every kind of shape.
#include <optional>

#include "bindings.hpp"

// The keyword arguments every Body.add_* takes, for their docstrings.
#define MINK_SHAPE_SETTINGS                                                                \
  " Keyword arguments are ShapeDef's properties (density, friction, restitution, filter, " \
  "sensor, hit_events, ...)."

namespace mink::python {

namespace {

// A chain makes one shape per segment; every other kind one shape.
py::object create(const BodyRef& body, const ShapeDef& def) {
  if (def.type == ShapeType::chain) {
    std::vector<ShapeRef> out;
    for (const ShapeId id : body.w().create_chain(body.id, def)) out.push_back({body.world, id});
    return py::cast(out);
  }
  return py::cast(ShapeRef{body.world, body.w().create_shape(body.id, def)});
}

// The core's points in the body frame: a circle's centre, a capsule's two centres, a
// segment's ends (a chain segment's, without its ghosts), a polygon's hull.
std::vector<Vec2> core_points(const ShapeRef& s) {
  const ShapeGeometry& geometry = s.w().shape_geometry(s.id);
  if (const auto* circle = std::get_if<Circle>(&geometry)) return {circle->center};
  if (const auto* capsule = std::get_if<Capsule>(&geometry)) {
    return {capsule->center1, capsule->center2};
  }
  if (const auto* segment = std::get_if<Segment>(&geometry)) {
    return {segment->point1, segment->point2};
  }
  if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
    return {chain->segment.point1, chain->segment.point2};
  }
  const auto vertices = s.w().shape_hull(s.id).vertices();
  return {vertices.begin(), vertices.end()};
}

}  // namespace

void bind_shapes(py::module_& m, WorldClass& world) {
  py::class_<ShapeRef> shape(m, "Shape", R"(A shape of a body (Body.add_*, Body.shapes).

Handles compare equal when they name the same shape; events and queries name shapes by
Shape.index (World.shape(index) gives the handle back).)");
  bind_identity(shape);
  shape
      .def_property_readonly(
          "index", [](const ShapeRef& s) { return s.id.index; }, "Slot index, as events name it.")
      .def_property_readonly(
          "valid", [](const ShapeRef& s) { return s.w().is_valid(s.id); },
          "False once the shape was destroyed.")
      .def_property_readonly(
          "body",
          [](const ShapeRef& s) {
            return BodyRef{s.world, s.w().shape_body(s.id)};
          },
          "The body it is attached to.")
      .def_property_readonly(
          "type", [](const ShapeRef& s) { return std::string(to_string(s.w().shape_type(s.id))); },
          "'polygon', 'circle', 'capsule', 'segment' or 'chain' (a chain's segments).")
      .def_property_readonly(
          "radius", [](const ShapeRef& s) { return s.w().shape_radius(s.id); },
          "Circle and capsule radius, polygon rounding; 0 for segments and chains.")
      .def_property_readonly(
          "points", [](const ShapeRef& s) { return points_array(core_points(s)); },
          "The core in the body frame, (n, 2): a circle's centre, a capsule's centres, a "
          "segment's ends, a polygon's hull (counter-clockwise).")
      .def_property_readonly(
          "world_points",
          [](const ShapeRef& s) {
            std::vector<Vec2> points = core_points(s);
            const Pose pose = s.w().pose(s.w().shape_body(s.id));
            for (Vec2& p : points) p = pose.apply(p);
            return points_array(points);
          },
          "The core in world coordinates, (n, 2).")
      .def_property(
          "density", [](const ShapeRef& s) { return s.w().shape_density(s.id); },
          [](const ShapeRef& s, Real density) { s.w().set_shape_density(s.id, density); },
          "kg/m^2; setting it recomputes the body's mass.")
      .def_property(
          "friction", [](const ShapeRef& s) { return s.w().shape_friction(s.id); },
          [](const ShapeRef& s, Real friction) { s.w().set_shape_friction(s.id, friction); },
          "Coulomb coefficient (its contacts too).")
      .def_property(
          "restitution", [](const ShapeRef& s) { return s.w().shape_restitution(s.id); },
          [](const ShapeRef& s, Real restitution) {
            s.w().set_shape_restitution(s.id, restitution);
          },
          "Bounciness (its contacts too).")
      .def_property(
          "filter", [](const ShapeRef& s) { return s.w().shape_filter(s.id); },
          [](const ShapeRef& s, const Filter& filter) { s.w().set_shape_filter(s.id, filter); },
          "Its Filter; a new one is applied from the next step.")
      .def_property_readonly(
          "sensor", [](const ShapeRef& s) { return s.w().is_sensor(s.id); }, "True for a sensor.")
      .def_property_readonly(
          "contact_events", [](const ShapeRef& s) { return s.w().shape_contact_events(s.id); },
          "As created.")
      .def_property_readonly(
          "sensor_events", [](const ShapeRef& s) { return s.w().shape_sensor_events(s.id); },
          "As created.")
      .def_property_readonly(
          "hit_events", [](const ShapeRef& s) { return s.w().shape_hit_events(s.id); },
          "As created.")
      .def_property_readonly(
          "user_data", [](const ShapeRef& s) { return s.w().shape_user_data(s.id); }, "As created.")
      .def_property_readonly(
          "algorithm",
          [](const ShapeRef& s) { return std::string(to_string(s.w().shape_algorithm(s.id))); },
          "The hull algorithm that built a polygon.")
      .def_property_readonly(
          "aabb",
          [](const ShapeRef& s) {
            const Aabb box = s.w().shape_aabb(s.id);
            return py::make_tuple(box.lower, box.upper);
          },
          "Tight world box at the current pose: (lower, upper).")
      .def_property_readonly(
          "chain",
          [](const ShapeRef& s) -> py::object {
            const auto chain = s.w().shape_chain(s.id);
            if (!chain) return py::none();
            return py::make_tuple(chain->chain, chain->loop);
          },
          "For a chain's segment, (chain number, loops); None for other shapes.")
      .def(
          "destroy", [](const ShapeRef& s) { s.w().destroy_shape(s.id); },
          "Detaches and destroys the shape.")
      .def("__repr__", [](const ShapeRef& s) {
        if (!s.world->world().is_valid(s.id)) {
          return "<minkowski.Shape " + std::to_string(s.id.index) + " (destroyed)>";
        }
        return "<minkowski.Shape " + std::to_string(s.id.index) + " " +
               std::string(to_string(s.w().shape_type(s.id))) + " on body " +
               std::to_string(s.w().shape_body(s.id).index) + ">";
      });

  auto body = py::reinterpret_borrow<py::class_<BodyRef>>(m.attr("Body"));
  body.def(
          "add_shape", [](const BodyRef& b, const ShapeDef& def) { return create(b, def); },
          py::arg("definition"),
          "Attaches the ShapeDef's shape (a list of segment shapes for a chain).")
      .def(
          "add_circle",
          [](const BodyRef& b, Real radius, const Vec2& center, const py::kwargs& settings) {
            return create(b,
                          with_settings(ShapeDef::circle(radius, center), settings, "add_circle"));
          },
          py::arg("radius"), py::arg("center") = Vec2(0, 0),
          "Attaches a disk of `radius` about `center` (body frame)." MINK_SHAPE_SETTINGS)
      .def(
          "add_capsule",
          [](const BodyRef& b, const Vec2& center1, const Vec2& center2, Real radius,
             const py::kwargs& settings) {
            return create(b, with_settings(ShapeDef::capsule(center1, center2, radius), settings,
                                           "add_capsule"));
          },
          py::arg("center1"), py::arg("center2"), py::arg("radius"),
          "Attaches the points within `radius` of the segment center1-center2." MINK_SHAPE_SETTINGS)
      .def(
          "add_segment",
          [](const BodyRef& b, const Vec2& point1, const Vec2& point2, const py::kwargs& settings) {
            return create(
                b, with_settings(ShapeDef::segment(point1, point2), settings, "add_segment"));
          },
          py::arg("point1"), py::arg("point2"), "Attaches a two-sided segment." MINK_SHAPE_SETTINGS)
      .def(
          "add_polygon",
          [](const BodyRef& b, std::vector<Vec2> points, Real radius, const py::kwargs& settings) {
            ShapeDef def;
            def.points = std::move(points);
            def.radius = radius;
            return create(b, with_settings(std::move(def), settings, "add_polygon"));
          },
          py::arg("points"), py::arg("radius") = 0.0,
          "Attaches the convex hull of `points` (any point set, body frame), "
          "rounded by `radius`." MINK_SHAPE_SETTINGS)
      .def(
          "add_box",
          [](const BodyRef& b, Real hx, Real hy, const Vec2& center, Real angle,
             const py::kwargs& settings) {
            return create(b,
                          with_settings(ShapeDef::box(hx, hy, center, angle), settings, "add_box"));
          },
          py::arg("hx"), py::arg("hy"), py::arg("center") = Vec2(0, 0), py::arg("angle") = 0.0,
          "Attaches a box of half extents (hx, hy) about `center`, turned by "
          "`angle` (radius= rounds it)." MINK_SHAPE_SETTINGS)
      .def(
          "add_regular_polygon",
          [](const BodyRef& b, int count, Real radius, const Vec2& center,
             const py::kwargs& settings) {
            return create(b, with_settings(ShapeDef::regular_polygon(count, radius, center),
                                           settings, "add_regular_polygon"));
          },
          py::arg("count"), py::arg("radius"), py::arg("center") = Vec2(0, 0),
          "Attaches `count` vertices on a circle of `radius` about `center`." MINK_SHAPE_SETTINGS)
      .def(
          "add_chain",
          [](const BodyRef& b, std::vector<Vec2> points, bool loop, const py::kwargs& settings) {
            return create(
                b, with_settings(ShapeDef::chain(std::move(points), loop), settings, "add_chain"));
          },
          py::arg("points"), py::arg("loop") = false,
          "Attaches a chain: one one-sided segment shape per edge (a list), each "
          "colliding on its right side (a counter-clockwise loop faces out)." MINK_SHAPE_SETTINGS);

  world.def(
      "destroy_shape", [](WorldHandle& w, const ShapeRef& s) { w.world().destroy_shape(s.id); },
      py::arg("shape"), "Detaches and destroys the shape.");
}

}  // namespace mink::python
