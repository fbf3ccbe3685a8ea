#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"

namespace py = pybind11;

// Vectors cross as plain tuples: any sequence of two numbers (a tuple, a list, a numpy
// array) comes in, a (x, y) tuple of floats goes out. Cheaper than a numpy array for one
// vector, and what Python code writes anyway.
namespace pybind11::detail {
template <>
struct type_caster<mink::Vec2> {
  PYBIND11_TYPE_CASTER(mink::Vec2, const_name("tuple[float, float]"));

  bool load(handle source, bool convert) {
    if (!source || isinstance<str>(source) || isinstance<bytes>(source) ||
        PySequence_Check(source.ptr()) == 0) {
      return false;
    }
    if (PySequence_Size(source.ptr()) != 2) {
      PyErr_Clear();
      return false;
    }
    for (Py_ssize_t i = 0; i < 2; ++i) {
      const object item = reinterpret_steal<object>(PySequence_GetItem(source.ptr(), i));
      if (!item) {
        PyErr_Clear();
        return false;
      }
      make_caster<double> number;
      if (!number.load(item, convert)) return false;
      value[i] = cast_op<double>(number);
    }
    return true;
  }

  static handle cast(const mink::Vec2& v, return_value_policy, handle) {
    return make_tuple(v.x(), v.y()).release();
  }
};
}  // namespace pybind11::detail

namespace mink::python {

/// A World as Python holds it: the scene run that steps it (so a built-in's schedule keeps
/// acting), shared by the Body, Shape and Joint handles that keep it alive. While step()
/// runs with the GIL released, any other use of the world from another thread raises instead
/// of racing with the step.
class WorldHandle {
 public:
  /// `schedule_scene`: the built-in scene whose schedule the run follows (empty: none), so
  /// that a pickled world can be rebuilt with it.
  explicit WorldHandle(const SceneDef& scene, std::string schedule_scene = {})
      : run_(scene), schedule_scene_(std::move(schedule_scene)) {}
  const std::string& schedule_scene() const noexcept { return schedule_scene_; }

  /// @throws std::runtime_error (RuntimeError) while another thread steps the world.
  World& world() {
    check_idle();
    return run_.world();
  }
  /// @brief The scene run (its world and the ids of the scene's bodies and joints).
  SceneRun& run() {
    check_idle();
    return run_;
  }
  /// @brief Runs `count` steps (each: the schedule, then World::step) without the GIL.
  void step(long long count);
  /// @brief Runs `count` steps of `time_step` and `substeps` (no schedule) without the GIL.
  void step(long long count, Real time_step, int substeps);

 private:
  void check_idle() const;
  class StepGuard;
  SceneRun run_;
  std::string schedule_scene_;
  std::atomic<bool> stepping_{false};
};
using WorldPtr = std::shared_ptr<WorldHandle>;

/// @brief A body of a world, as Python sees it.
struct BodyRef {
  WorldPtr world;
  BodyId id;
  World& w() const { return world->world(); }
};
/// @brief A shape of a world.
struct ShapeRef {
  WorldPtr world;
  ShapeId id;
  World& w() const { return world->world(); }
};
/// @brief A joint of a world.
struct JointRef {
  WorldPtr world;
  JointId id;
  World& w() const { return world->world(); }
};

using WorldClass = py::class_<WorldHandle, WorldPtr>;

/// @brief Handles of one object compare equal and hash alike (ids carry their world and the
/// slot's generation, so a reused slot is another object).
template <class Ref>
void bind_identity(py::class_<Ref>& cls) {
  cls.def("__eq__", [](const Ref& a, const Ref& b) { return a.id == b.id; })
      .def("__hash__", [](const Ref& r) {
        return py::hash(py::make_tuple(r.id.world, r.id.index, r.id.generation));
      });
}

/// @brief Copies `def` into its bound Python class, sets each keyword argument as one of its
/// properties and copies it back; a name that is not a property raises TypeError naming
/// `function`, as Python does for an unexpected keyword argument.
template <class Def>
Def with_settings(Def def, const py::kwargs& settings, std::string_view function) {
  if (settings.empty()) return def;
  py::object object = py::cast(std::move(def));
  const py::handle type = py::type::handle_of(object);
  const py::object property = py::module_::import("builtins").attr("property");
  for (const auto& [key, value] : settings) {
    const std::string name = py::str(key);
    if (!py::isinstance(py::getattr(type, name.c_str(), py::none()), property)) {
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                           name + "'");
    }
    py::setattr(object, key, value);
  }
  return object.cast<Def>();
}

/// @brief The body ids a batch call works on: every live body (slot order) for None, else
/// a sequence of Body objects or of body indices (Body.index, an int array).
/// @throws InvalidArgumentError (or StaleIdError) naming a selection entry that is no body.
std::vector<BodyId> select_bodies(World& world, const py::handle& selection);

/// @brief The live body of slot `index`.
/// @throws InvalidArgumentError naming the index when no live body has it.
BodyId body_at(const World& world, std::int64_t index);
/// @brief The live shape of slot `index`.
/// @throws InvalidArgumentError naming the index when no live shape has it.
ShapeId shape_at(const World& world, std::int64_t index);

/// @brief `def` with the keyword arguments: the scene file's world keys, checked as the scene
/// reader checks them (set_world_setting), and `workers` (WorldDef::worker_count).
/// @throws TypeError for another keyword, SceneFileError for a bad value.
WorldDef world_def(WorldDef def, const py::kwargs& settings);

/// @brief An (n, 2) float64 array of points.
py::array_t<double> points_array(std::span<const Vec2> points);

// Each file binds one part of the module; bind_errors comes first (the others' docstrings
// name its classes).
void bind_errors(py::module_& m);
void bind_definitions(py::module_& m);
WorldClass bind_world(py::module_& m);
void bind_bodies(py::module_& m, WorldClass& world);
void bind_shapes(py::module_& m, WorldClass& world);
void bind_joints(py::module_& m, WorldClass& world);
void bind_batch_arrays(WorldClass& world);
void bind_events(WorldClass& world);
void bind_queries(py::module_& m, WorldClass& world);
void bind_scenes(py::module_& m, WorldClass& world);
void bind_frames(py::module_& m);

}  // namespace mink::python
