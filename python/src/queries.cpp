// World queries (boxes, points, rays, shape casts) against the current poses, and the
// paper's hull algorithms on a point array.
#include <optional>

#include "bindings.hpp"
#include "mink/geometry/convex_hull.hpp"

namespace mink::python {

namespace {

/// @brief What a ray or shape cast met first.
struct CastHit {
  ShapeRef shape;
  Real fraction = 0;
  Vec2 point{0, 0};
  Vec2 normal{0, 0};
};

struct RayRecord {
  bool hit;
  std::int32_t shape, body;
  double fraction;
  double point[2];
  double normal[2];
};

std::vector<ShapeRef> shape_refs(const WorldPtr& w, const std::vector<ShapeId>& ids) {
  std::vector<ShapeRef> out;
  out.reserve(ids.size());
  for (const ShapeId id : ids) out.push_back({w, id});
  return out;
}

}  // namespace

void bind_queries(py::module_& m, WorldClass& world) {
  PYBIND11_NUMPY_DTYPE(RayRecord, hit, shape, body, fraction, point, normal);
  py::class_<CastHit>(m, "CastHit",
                      "What a ray or shape cast met first: the shape, the fraction of the "
                      "translation, the point and the normal (world).")
      .def_readonly("shape", &CastHit::shape)
      .def_readonly("fraction", &CastHit::fraction)
      .def_readonly("point", &CastHit::point)
      .def_readonly("normal", &CastHit::normal)
      .def("__repr__", [](const CastHit& h) {
        return "<minkowski.CastHit shape " + std::to_string(h.shape.id.index) + " at fraction " +
               std::to_string(h.fraction) + ">";
      });

  world
      .def(
          "query_aabb",
          [](const WorldPtr& w, const Vec2& lower, const Vec2& upper) {
            return shape_refs(w, w->world().query_aabb(Aabb{lower, upper}));
          },
          py::arg("lower"), py::arg("upper"),
          "Shapes overlapping the box [lower, upper], exactly (not only their boxes), in slot "
          "order.")
      .def(
          "query_point",
          [](const WorldPtr& w, const Vec2& point) {
            return shape_refs(w, w->world().query_point(point));
          },
          py::arg("point"), "Solid shapes containing the world point (boundary included).")
      .def(
          "ray_cast",
          [](const WorldPtr& w, const Vec2& origin,
             const Vec2& translation) -> std::optional<CastHit> {
            const auto hit = w->world().ray_cast(origin, translation);
            if (!hit) return std::nullopt;
            return CastHit{{w, hit->shape}, hit->hit.fraction, hit->hit.point, hit->hit.normal};
          },
          py::arg("origin"), py::arg("translation"),
          "The first shape met along origin -> origin + translation (a CastHit), or None. A "
          "ray starting inside a solid shape does not hit it.")
      .def(
          "ray_casts",
          [](WorldHandle& w, const py::object& origins, const py::object& translations) {
            using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
            const Doubles from = Doubles::ensure(origins);
            const Doubles along = Doubles::ensure(translations);
            const auto rows = [](const Doubles& a) {
              return a && a.ndim() == 2 && a.shape(1) == 2 ? a.shape(0) : py::ssize_t{-1};
            };
            const py::ssize_t count = rows(from);
            if (count < 0 || rows(along) != count) {
              throw InvalidArgumentError(
                  "ray_casts: origins and translations must be (N, 2) arrays of the same N");
            }
            const World& world = w.world();
            py::array_t<RayRecord> out(count);
            RayRecord* data = out.mutable_data();
            for (py::ssize_t i = 0; i < count; ++i) {
              const Vec2 origin(from.at(i, 0), from.at(i, 1));
              const Vec2 translation(along.at(i, 0), along.at(i, 1));
              RayRecord record{false, -1, -1, 1.0, {0, 0}, {0, 0}};
              if (const auto hit = world.ray_cast(origin, translation)) {
                record.hit = true;
                record.shape = static_cast<std::int32_t>(hit->shape.index);
                record.body = static_cast<std::int32_t>(world.shape_body(hit->shape).index);
                record.fraction = hit->hit.fraction;
                record.point[0] = hit->hit.point.x();
                record.point[1] = hit->hit.point.y();
                record.normal[0] = hit->hit.normal.x();
                record.normal[1] = hit->hit.normal.y();
              }
              data[i] = record;
            }
            return out;
          },
          py::arg("origins"), py::arg("translations"),
          "Many ray casts in one call (lidar): (N, 2) origins and translations give a "
          "structured array of hit, shape, body, fraction (1 on a miss), point (2), normal (2).")
      .def(
          "cast_shape",
          [](const WorldPtr& w, const ShapeDef& def, const Vec2& translation, const Vec2& position,
             Real angle, const Filter& filter) -> std::optional<CastHit> {
            const Pose pose{position, Rotation::from_angle(angle)};
            const auto hit = w->world().cast_shape(def, pose, translation, filter);
            if (!hit) return std::nullopt;
            return CastHit{{w, hit->shape}, hit->fraction, hit->point, hit->normal};
          },
          py::arg("shape"), py::arg("translation"), py::arg("position") = Vec2(0, 0),
          py::arg("angle") = 0.0, py::arg("filter") = Filter{},
          "Moves the ShapeDef's shape, placed at position and angle, along `translation` "
          "without turning: the first solid shape it meets (a CastHit: fraction of the "
          "translation, point, normal from that shape towards the cast one), or None. Sensors "
          "and shapes `filter` does not collide with are passed through.");

  m.def(
      "convex_hull",
      [](const std::vector<Vec2>& points, const std::string& algorithm, bool prefilter) {
        const ConvexHull hull =
            build_hull(points, parse_hull_algorithm(algorithm), HullOptions{prefilter});
        return points_array(hull.vertices());
      },
      py::arg("points"), py::arg("algorithm") = "chan", py::arg("prefilter") = false,
      "The convex hull of a point set, (k, 2), counter-clockwise from the lowest-x (then "
      "lowest-y) vertex, by one of the paper's algorithms: 'chan', 'divide-conquer', 'graham', "
      "'jarvis', 'monotone-chain' (all give the same hull).");
}

}  // namespace mink::python
