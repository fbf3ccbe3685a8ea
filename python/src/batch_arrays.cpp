// The batch arrays: states of every body (or a selection) in one call as numpy arrays, and
// setters taking arrays, so that a Python loop over bodies is never needed.
#include "bindings.hpp"

namespace mink::python {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<BodyId> select_bodies(World& world, const py::handle& selection) {
  if (selection.is_none()) return world.bodies();
  // Slot index -> id, for selections by index.
  std::vector<BodyId> by_index;
  const auto lookup = [&](std::int64_t index) {
    if (by_index.empty()) {
      for (const BodyId id : world.bodies()) {
        if (by_index.size() <= id.index) by_index.resize(id.index + 1);
        by_index[id.index] = id;
      }
    }
    if (index < 0 || static_cast<std::size_t>(index) >= by_index.size() ||
        by_index[static_cast<std::size_t>(index)].is_null()) {
      throw InvalidArgumentError("bodies: no live body has index " + std::to_string(index));
    }
    return by_index[static_cast<std::size_t>(index)];
  };
  std::vector<BodyId> out;
  if (py::isinstance<py::array>(selection)) {
    const auto indices =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(selection);
    if (!indices || indices.ndim() != 1) {
      throw InvalidArgumentError("bodies: expected a 1-dimensional array of body indices");
    }
    out.reserve(static_cast<std::size_t>(indices.size()));
    for (py::ssize_t i = 0; i < indices.size(); ++i) out.push_back(lookup(indices.at(i)));
    return out;
  }
  for (const py::handle item : py::iter(selection)) {
    if (py::isinstance<BodyRef>(item)) {
      out.push_back(item.cast<const BodyRef&>().id);
    } else {
      out.push_back(lookup(item.cast<std::int64_t>()));
    }
  }
  return out;
}

namespace {

py::array_t<double> vectors(World& world, const py::handle& selection,
                            Vec2 (World::*get)(BodyId) const) {
  const std::vector<BodyId> ids = select_bodies(world, selection);
  py::array_t<double> out({static_cast<py::ssize_t>(ids.size()), py::ssize_t{2}});
  double* data = out.mutable_data();
  for (const BodyId id : ids) {
    const Vec2 v = (world.*get)(id);
    *data++ = v.x();
    *data++ = v.y();
  }
  return out;
}

template <class T, class Get>
py::array_t<T> scalars(World& world, const py::handle& selection, Get get) {
  const std::vector<BodyId> ids = select_bodies(world, selection);
  py::array_t<T> out(static_cast<py::ssize_t>(ids.size()));
  T* data = out.mutable_data();
  for (const BodyId id : ids) *data++ = static_cast<T>(get(world, id));
  return out;
}

// `values` as a C-contiguous float64 array of one row per selected body (each `columns`
// wide, or a plain vector for 0).
Doubles rows(const py::handle& values, std::size_t count, int columns, const char* function) {
  Doubles array = Doubles::ensure(values);
  if (!array) throw InvalidArgumentError(std::string(function) + ": expected an array of numbers");
  const bool fits = columns == 0 ? array.ndim() == 1 && array.shape(0) == py::ssize_t(count)
                                 : array.ndim() == 2 && array.shape(0) == py::ssize_t(count) &&
                                       array.shape(1) == columns;
  if (!fits) {
    std::string got = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d) {
      got += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
    }
    got += array.ndim() == 1 ? ",)" : ")";
    throw InvalidArgumentError(std::string(function) + ": expected an array of shape (" +
                               std::to_string(count) +
                               (columns == 0 ? ",)" : ", " + std::to_string(columns) + ")") +
                               " (one row per selected body), got " + got);
  }
  return array;
}

Vec2 row(const Doubles& array, std::size_t i) {
  const double* at = array.data() + 2 * i;
  return {at[0], at[1]};
}

// Applies `set(world, id, row i)` to each selected body; 2 columns per row, or 1 for 0.
template <class Set>
void set_rows(WorldHandle& w, const py::handle& values, const py::handle& selection, int columns,
              const char* function, Set set) {
  World& world = w.world();
  const std::vector<BodyId> ids = select_bodies(world, selection);
  const Doubles array = rows(values, ids.size(), columns, function);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (columns == 0) {
      set(world, ids[i], Vec2(array.data()[i], 0));
    } else {
      set(world, ids[i], row(array, i));
    }
  }
}

// Forces or impulses at points (default: each body's centre of mass).
template <class Apply>
void apply_rows(WorldHandle& w, const py::handle& values, const py::handle& points,
                const py::handle& selection, const char* function, Apply apply) {
  World& world = w.world();
  const std::vector<BodyId> ids = select_bodies(world, selection);
  const Doubles vectors = rows(values, ids.size(), 2, function);
  Doubles at;
  if (!points.is_none()) at = rows(points, ids.size(), 2, function);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    apply(world, ids[i], row(vectors, i),
          points.is_none() ? world.world_center(ids[i]) : row(at, i));
  }
}

constexpr const char* kSelection =
    " `bodies`: None for every live body (World.bodies order), or a sequence of Body objects "
    "or of body indices (an int array).";

std::string selection_doc(const char* text) {
  return std::string(text) + kSelection;
}

}  // namespace

void bind_batch_arrays(WorldClass& world) {
  // Docstrings must outlive the bindings.
  static const std::string positions_doc = selection_doc("Body origins, an (N, 2) float64 array.");
  static const std::string angles_doc =
      selection_doc("Body angles in radians, an (N,) float64 array.");
  static const std::string linear_doc =
      selection_doc("Velocities of the centres of mass (m/s), an (N, 2) float64 array.");
  static const std::string angular_doc =
      selection_doc("Angular velocities (rad/s), an (N,) float64 array.");
  static const std::string centers_doc =
      selection_doc("Centres of mass, world, an (N, 2) float64 array.");
  static const std::string masses_doc = selection_doc("Masses (kg), an (N,) float64 array.");
  static const std::string inertias_doc =
      selection_doc("Rotational inertias about the centres of mass, an (N,) float64 array.");
  static const std::string awake_doc = selection_doc("Awake flags, an (N,) bool array.");
  static const std::string states_doc = selection_doc(
      "Position, angle and velocities in one (N, 6) float64 array: x, y, angle, vx, vy, w "
      "(vx, vy of the centre of mass).");
  static const std::string set_positions_doc =
      selection_doc("Teleports the bodies' origins to the rows of an (N, 2) array (angles kept).");
  static const std::string set_angles_doc =
      selection_doc("Turns the bodies to an (N,) array of angles.");
  static const std::string set_transforms_doc =
      selection_doc("Teleports the bodies to (N, 2) positions and (N,) angles.");
  static const std::string set_linear_doc =
      selection_doc("Sets the centres of mass' velocities from an (N, 2) array.");
  static const std::string set_angular_doc =
      selection_doc("Sets angular velocities from an (N,) array.");
  static const std::string forces_doc = selection_doc(
      "Applies (N, 2) forces (N, world) for the next step at (N, 2) world points (default: "
      "the centres of mass).");
  static const std::string impulses_doc = selection_doc(
      "Applies (N, 2) linear impulses (N s, world) at (N, 2) world points (default: the "
      "centres of mass).");
  static const std::string torques_doc =
      selection_doc("Applies an (N,) array of torques for the next step.");

  const auto selection = py::arg("bodies") = py::none();
  world
      .def(
          "positions",
          [](WorldHandle& w, const py::object& bodies) {
            return vectors(w.world(), bodies, &World::position);
          },
          selection, positions_doc.c_str())
      .def(
          "angles",
          [](WorldHandle& w, const py::object& bodies) {
            return scalars<double>(w.world(), bodies,
                                   [](const World& world, BodyId id) { return world.angle(id); });
          },
          selection, angles_doc.c_str())
      .def(
          "linear_velocities",
          [](WorldHandle& w, const py::object& bodies) {
            return vectors(w.world(), bodies, &World::linear_velocity);
          },
          selection, linear_doc.c_str())
      .def(
          "angular_velocities",
          [](WorldHandle& w, const py::object& bodies) {
            return scalars<double>(w.world(), bodies, [](const World& world, BodyId id) {
              return world.angular_velocity(id);
            });
          },
          selection, angular_doc.c_str())
      .def(
          "world_centers",
          [](WorldHandle& w, const py::object& bodies) {
            return vectors(w.world(), bodies, &World::world_center);
          },
          selection, centers_doc.c_str())
      .def(
          "masses",
          [](WorldHandle& w, const py::object& bodies) {
            return scalars<double>(w.world(), bodies,
                                   [](const World& world, BodyId id) { return world.mass(id); });
          },
          selection, masses_doc.c_str())
      .def(
          "rotational_inertias",
          [](WorldHandle& w, const py::object& bodies) {
            return scalars<double>(w.world(), bodies, [](const World& world, BodyId id) {
              return world.rotational_inertia(id);
            });
          },
          selection, inertias_doc.c_str())
      .def(
          "awake",
          [](WorldHandle& w, const py::object& bodies) {
            return scalars<bool>(w.world(), bodies,
                                 [](const World& world, BodyId id) { return world.is_awake(id); });
          },
          selection, awake_doc.c_str())
      .def(
          "indices",
          [](WorldHandle& w) {
            return scalars<std::int64_t>(w.world(), py::none(),
                                         [](const World&, BodyId id) { return id.index; });
          },
          "The slot index (Body.index) of each row of the batch arrays, an (N,) int64 array.")
      .def(
          "states",
          [](WorldHandle& w, const py::object& bodies) {
            World& world = w.world();
            const std::vector<BodyId> ids = select_bodies(world, bodies);
            py::array_t<double> out({static_cast<py::ssize_t>(ids.size()), py::ssize_t{6}});
            double* data = out.mutable_data();
            for (const BodyId id : ids) {
              const Vec2 p = world.position(id);
              const Vec2 v = world.linear_velocity(id);
              *data++ = p.x();
              *data++ = p.y();
              *data++ = world.angle(id);
              *data++ = v.x();
              *data++ = v.y();
              *data++ = world.angular_velocity(id);
            }
            return out;
          },
          selection, states_doc.c_str())
      .def(
          "set_positions",
          [](WorldHandle& w, const py::object& values, const py::object& bodies) {
            set_rows(w, values, bodies, 2, "set_positions",
                     [](World& world, BodyId id, const Vec2& p) {
                       world.set_transform(id, p, world.angle(id));
                     });
          },
          py::arg("positions"), selection, set_positions_doc.c_str())
      .def(
          "set_angles",
          [](WorldHandle& w, const py::object& values, const py::object& bodies) {
            set_rows(w, values, bodies, 0, "set_angles",
                     [](World& world, BodyId id, const Vec2& angle) {
                       world.set_transform(id, world.position(id), angle.x());
                     });
          },
          py::arg("angles"), selection, set_angles_doc.c_str())
      .def(
          "set_transforms",
          [](WorldHandle& w, const py::object& positions, const py::object& angles,
             const py::object& bodies) {
            World& world = w.world();
            const std::vector<BodyId> ids = select_bodies(world, bodies);
            const Doubles p = rows(positions, ids.size(), 2, "set_transforms");
            const Doubles a = rows(angles, ids.size(), 0, "set_transforms");
            for (std::size_t i = 0; i < ids.size(); ++i) {
              world.set_transform(ids[i], row(p, i), a.data()[i]);
            }
          },
          py::arg("positions"), py::arg("angles"), selection, set_transforms_doc.c_str())
      .def(
          "set_linear_velocities",
          [](WorldHandle& w, const py::object& values, const py::object& bodies) {
            set_rows(
                w, values, bodies, 2, "set_linear_velocities",
                [](World& world, BodyId id, const Vec2& v) { world.set_linear_velocity(id, v); });
          },
          py::arg("velocities"), selection, set_linear_doc.c_str())
      .def(
          "set_angular_velocities",
          [](WorldHandle& w, const py::object& values, const py::object& bodies) {
            set_rows(w, values, bodies, 0, "set_angular_velocities",
                     [](World& world, BodyId id, const Vec2& v) {
                       world.set_angular_velocity(id, v.x());
                     });
          },
          py::arg("velocities"), selection, set_angular_doc.c_str())
      .def(
          "apply_forces",
          [](WorldHandle& w, const py::object& forces, const py::object& points,
             const py::object& bodies) {
            apply_rows(w, forces, points, bodies, "apply_forces",
                       [](World& world, BodyId id, const Vec2& f, const Vec2& p) {
                         world.apply_force(id, f, p);
                       });
          },
          py::arg("forces"), py::arg("points") = py::none(), selection, forces_doc.c_str())
      .def(
          "apply_impulses",
          [](WorldHandle& w, const py::object& impulses, const py::object& points,
             const py::object& bodies) {
            apply_rows(w, impulses, points, bodies, "apply_impulses",
                       [](World& world, BodyId id, const Vec2& j, const Vec2& p) {
                         world.apply_linear_impulse(id, j, p);
                       });
          },
          py::arg("impulses"), py::arg("points") = py::none(), selection, impulses_doc.c_str())
      .def(
          "apply_torques",
          [](WorldHandle& w, const py::object& values, const py::object& bodies) {
            set_rows(w, values, bodies, 0, "apply_torques",
                     [](World& world, BodyId id, const Vec2& t) { world.apply_torque(id, t.x()); });
          },
          py::arg("torques"), selection, torques_doc.c_str());
}

}  // namespace mink::python
