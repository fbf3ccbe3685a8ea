// minkowski.World: settings as keyword arguments, stepping without the GIL, the bodies,
// shapes and joints it holds.
#include <span>
#include <stdexcept>
#include <string_view>

#include "bindings.hpp"
#include "mink/byte_stream.hpp"
#include "mink/engine/scene_fields.hpp"
#include "mink/engine/scene_file.hpp"
#include "names.hpp"

namespace mink::python {

// Marks the world as stepping for the guard's life, so that another thread's use of it raises.
class WorldHandle::StepGuard {
 public:
  explicit StepGuard(std::atomic<bool>& stepping) : stepping_(stepping) {
    bool idle = false;
    if (!stepping_.compare_exchange_strong(idle, true, std::memory_order_acq_rel)) {
      throw std::runtime_error("World.step: the world is already stepping in another thread");
    }
  }
  ~StepGuard() { stepping_.store(false, std::memory_order_release); }
  StepGuard(const StepGuard&) = delete;
  StepGuard& operator=(const StepGuard&) = delete;

 private:
  std::atomic<bool>& stepping_;
};

void WorldHandle::check_idle() const {
  if (stepping_.load(std::memory_order_acquire)) {
    throw std::runtime_error("the world is stepping in another thread; use it after step returns");
  }
}

void WorldHandle::step(long long count) {
  const StepGuard guard(stepping_);
  const py::gil_scoped_release unlocked;
  for (long long i = 0; i < count; ++i) run_.step();
}

void WorldHandle::step(long long count, Real time_step, int substeps) {
  const StepGuard guard(stepping_);
  const py::gil_scoped_release unlocked;
  for (long long i = 0; i < count; ++i) run_.world().step(time_step, substeps);
}

BodyId body_at(const World& world, std::int64_t index) {
  for (const BodyId id : world.bodies()) {
    if (id.index == index) return id;
  }
  throw InvalidArgumentError("no live body has index " + std::to_string(index));
}

ShapeId shape_at(const World& world, std::int64_t index) {
  for (const BodyId body : world.bodies()) {
    for (const ShapeId id : world.body_shapes(body)) {
      if (id.index == index) return id;
    }
  }
  throw InvalidArgumentError("no live shape has index " + std::to_string(index));
}

py::array_t<double> points_array(std::span<const Vec2> points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    view(static_cast<py::ssize_t>(i), 0) = points[i].x();
    view(static_cast<py::ssize_t>(i), 1) = points[i].y();
  }
  return out;
}

WorldDef world_def(WorldDef def, const py::kwargs& settings) {
  const py::object dumps = py::module_::import("json").attr("dumps");
  for (const auto& [key, value] : settings) {
    const std::string name = py::str(key);
    if (name == "workers") {
      def.worker_count = value.cast<int>();
      continue;
    }
    bool known = false;
    for (const SceneField<WorldDef>& field : world_fields()) known = known || field.key == name;
    if (!known) {
      throw py::type_error("World() got an unexpected keyword argument '" + name +
                           "' (the keys of a scene file's world object, and workers)");
    }
    // numpy arrays and scalars as plain Python values, for json.
    py::object plain = py::reinterpret_borrow<py::object>(value);
    if (py::hasattr(plain, "tolist")) plain = plain.attr("tolist")();
    set_world_setting(def, name, dumps(plain).cast<std::string>());
  }
  if (def.worker_count < 1 || def.worker_count > 256) {
    throw InvalidArgumentError("workers must be in 1..256, got " +
                               std::to_string(def.worker_count));
  }
  return def;
}

namespace {

// A world setting as Python sees it.
py::object setting_value(const FieldValue& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::vector<Vec2>>) {
          return points_array(v);
        } else {
          return py::cast(v);
        }
      },
      value);
}

py::dict world_settings(const World& world) {
  py::dict out;
  for (const SceneField<WorldDef>& field : world_fields()) {
    out[py::str(std::string(field.key))] = setting_value(field.get(world.def()));
  }
  out["workers"] = world.def().worker_count;
  return out;
}

py::dict counters_dict(const StepCounters& c) {
  py::dict out;
  out["broadphase_pairs"] = c.broadphase_pairs;
  out["contacts"] = c.contacts;
  out["touching_contacts"] = c.touching_contacts;
  out["collided_contacts"] = c.collided_contacts;
  out["awake_bodies"] = c.awake_bodies;
  out["islands"] = c.islands;
  out["constraint_colors"] = c.constraint_colors;
  out["overflow_constraints"] = c.overflow_constraints;
  out["stacked_constraints"] = c.stacked_constraints;
  out["joints"] = c.joints;
  out["fast_bodies"] = c.fast_bodies;
  out["continuous_hits"] = c.continuous_hits;
  return out;
}

py::dict profile_dict(const StepProfile& p) {
  py::dict out;
  out["pairs_ms"] = p.pairs;
  out["collide_ms"] = p.collide;
  out["islands_ms"] = p.islands;
  out["prepare_ms"] = p.prepare;
  out["solve_ms"] = p.solve;
  out["continuous_ms"] = p.continuous;
  out["finish_ms"] = p.finish;
  return out;
}

template <class Ref, class Id>
std::vector<Ref> refs(const WorldPtr& world, const std::vector<Id>& ids) {
  std::vector<Ref> out;
  out.reserve(ids.size());
  for (const Id id : ids) out.push_back(Ref{world, id});
  return out;
}

// What a pickled World holds: this number, the built-in scene whose schedule it follows (or
// ""), its worker count and its snapshot.
constexpr int kPickleFormat = 1;

py::bytes run_snapshot(WorldHandle& w) {
  const std::vector<std::uint8_t> bytes = w.run().snapshot();
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

void restore_run(WorldHandle& w, const py::bytes& snapshot) {
  const std::string_view bytes = snapshot;
  w.run().restore(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

WorldPtr unpickle_world(const py::tuple& state) {
  if (state.size() != 4 || !py::isinstance<py::int_>(state[0]) ||
      state[0].cast<int>() != kPickleFormat || !py::isinstance<py::str>(state[1]) ||
      !py::isinstance<py::int_>(state[2]) || !py::isinstance<py::bytes>(state[3])) {
    throw SnapshotError("a pickled World is (" + std::to_string(kPickleFormat) +
                        ", scene name, workers, snapshot bytes); got another tuple");
  }
  const auto schedule_scene = state[1].cast<std::string>();
  SceneDef scene = schedule_scene.empty() ? SceneDef{} : builtin_scene(schedule_scene);
  scene.world.worker_count = state[2].cast<int>();
  auto world = std::make_shared<WorldHandle>(scene, schedule_scene);
  restore_run(*world, state[3].cast<py::bytes>());
  return world;
}

}  // namespace

WorldClass bind_world(py::module_& m) {
  WorldClass world(m, "World", R"(A 2D rigid-body world.

Keyword arguments are the keys of a scene file's ``world`` object (gravity, time_step,
substeps, contact_hertz, enable_sleep, enable_continuous, ...; see docs/scene-format.md),
checked as the scene reader checks them, plus ``workers`` (threads a step runs on, the
calling one among them; the result is bitwise the same at any count).

Example::

    world = minkowski.World(gravity=(0, -9.8), substeps=4)
    ground = world.create_body("static")
    ground.add_box(10, 0.5)
    ball = world.create_body("dynamic", position=(0, 5))
    ball.add_circle(0.5, restitution=0.5)
    world.step(60)
    print(world.positions())
)");
  world
      .def(py::init([](const py::kwargs& settings) {
             SceneDef scene;
             scene.world = world_def(WorldDef{}, settings);
             return std::make_shared<WorldHandle>(scene);
           }),
           "World(**settings): an empty world.")
      .def_property_readonly(
          "settings", [](WorldHandle& w) { return world_settings(w.world()); },
          "Every setting in force, as a dict of the scene file's world keys (and workers).")
      .def_property(
          "gravity", [](WorldHandle& w) { return w.world().def().gravity; },
          [](WorldHandle& w, const Vec2& gravity) { w.world().set_gravity(gravity); },
          "Gravity, m/s^2.")
      .def_property(
          "sleep_enabled", [](WorldHandle& w) { return w.world().def().enable_sleep; },
          [](WorldHandle& w, bool enabled) { w.world().enable_sleep(enabled); },
          "Whether resting bodies may sleep; turning it off wakes every body.")
      .def_property_readonly(
          "time_step", [](WorldHandle& w) { return w.world().def().time_step; },
          "Seconds per fixed step.")
      .def_property_readonly(
          "time", [](WorldHandle& w) { return w.world().time(); }, "Simulated seconds.")
      .def_property_readonly(
          "step_count", [](WorldHandle& w) { return w.world().step_count(); },
          "Fixed steps run since the world was made.")
      .def(
          "step",
          [](WorldHandle& w, long long count, std::optional<Real> time_step,
             std::optional<int> substeps) {
            if (count < 0) {
              throw InvalidArgumentError("step count must be >= 0, got " + std::to_string(count));
            }
            if (time_step || substeps) {
              const WorldDef& def = w.world().def();
              w.step(count, time_step.value_or(def.time_step), substeps.value_or(def.substeps));
            } else {
              w.step(count);
            }
          },
          py::arg("count") = 1, py::kw_only(), py::arg("time_step") = py::none(),
          py::arg("substeps") = py::none(),
          R"(Runs `count` fixed steps (a built-in scene's schedule acts before each), without
holding the GIL. With time_step or substeps, steps of that length and substep count instead
(no schedule). The events then cover the last step.)")
      .def(
          "advance",
          [](WorldHandle& w, Real seconds) {
            const AdvanceResult result = w.world().advance(seconds);
            return py::make_tuple(result.steps, result.alpha);
          },
          py::arg("seconds"),
          "Runs the whole steps that fit in the accumulated time; returns (steps, alpha).")
      .def_property_readonly(
          "body_count", [](WorldHandle& w) { return w.world().body_count(); }, "Live bodies.")
      .def_property_readonly(
          "shape_count", [](WorldHandle& w) { return w.world().shape_count(); }, "Live shapes.")
      .def_property_readonly(
          "joint_count", [](WorldHandle& w) { return w.world().joint_count(); }, "Live joints.")
      .def("__len__", [](WorldHandle& w) { return w.world().body_count(); })
      .def_property_readonly(
          "bodies", [](const WorldPtr& w) { return refs<BodyRef>(w, w->world().bodies()); },
          "Live bodies in slot order: the row order of the batch arrays (for a scene, the "
          "file's order while no body was destroyed).")
      .def_property_readonly(
          "joints", [](const WorldPtr& w) { return refs<JointRef>(w, w->world().joints()); },
          "Live joints in slot order.")
      .def_property_readonly(
          "shapes",
          [](const WorldPtr& w) {
            std::vector<ShapeId> ids;
            for (const BodyId body : w->world().bodies()) {
              for (const ShapeId shape : w->world().body_shapes(body)) ids.push_back(shape);
            }
            std::sort(ids.begin(), ids.end(),
                      [](const ShapeId& a, const ShapeId& b) { return a.index < b.index; });
            return refs<ShapeRef>(w, ids);
          },
          "Live shapes in slot order.")
      .def_property_readonly(
          "scene_bodies", [](const WorldPtr& w) { return refs<BodyRef>(w, w->run().ids().bodies); },
          "The bodies of the scene the world was built from, in the scene's order (not those "
          "a schedule made); empty for a world made empty.")
      .def_property_readonly(
          "scene_joints",
          [](const WorldPtr& w) { return refs<JointRef>(w, w->run().ids().joints); },
          "The joints of the scene the world was built from, in the scene's order.")
      .def(
          "body",
          [](const WorldPtr& w, std::int64_t index) {
            return BodyRef{w, body_at(w->world(), index)};
          },
          py::arg("index"), "The live body of slot `index` (Body.index).")
      .def(
          "shape",
          [](const WorldPtr& w, std::int64_t index) {
            return ShapeRef{w, shape_at(w->world(), index)};
          },
          py::arg("index"), "The live shape of slot `index` (Shape.index, as events name it).")
      .def(
          "joint",
          [](const WorldPtr& w, std::int64_t index) {
            for (const JointId id : w->world().joints()) {
              if (id.index == index) return JointRef{w, id};
            }
            throw InvalidArgumentError("no live joint has index " + std::to_string(index));
          },
          py::arg("index"), "The live joint of slot `index`.")
      .def(
          "create_body",
          [](const WorldPtr& w, const py::object& type, const py::kwargs& settings) {
            BodyDef def;
            if (py::isinstance<BodyDef>(type)) {
              def = type.cast<BodyDef>();
            } else {
              def.type = parse_body_type(type.cast<std::string>());
            }
            def = with_settings(def, settings, "create_body");
            return BodyRef{w, w->world().create_body(def)};
          },
          py::arg("type") = "static",
          R"(Adds a body with no shapes: type 'static', 'kinematic' or 'dynamic' (or a BodyDef),
keyword arguments as BodyDef's properties (position, angle, linear_velocity, ...).)")
      .def_property_readonly(
          "counters", [](WorldHandle& w) { return counters_dict(w.world().counters()); },
          "What the last step did: pairs, contacts, awake bodies, islands, ...")
      .def_property_readonly(
          "profile", [](WorldHandle& w) { return profile_dict(w.world().profile()); },
          "Wall time of each phase of the last step, in milliseconds.")
      .def(
          "snapshot", [](WorldHandle& w) { return run_snapshot(w); },
          "The whole simulation state as bytes (World::snapshot, with a built-in scene's "
          "schedule): restore() rolls this world back to it exactly.")
      .def(
          "restore", [](WorldHandle& w, const py::bytes& snapshot) { restore_run(w, snapshot); },
          py::arg("snapshot"),
          "Rolls the world back (or forward) to a snapshot() of it, in place: it then continues "
          "bitwise as the world it was taken from. Bodies, shapes and joints made after the "
          "snapshot are gone (using them raises StaleIdError). Raises SnapshotError for bytes "
          "from another build or a corrupt or truncated snapshot, the world left as it was.")
      .def_property_readonly(
          "state_hash", [](WorldHandle& w) { return w.world().state_hash(); },
          "A 64-bit hash of the simulation state, for desync checks: worlds with equal states "
          "have equal hashes.")
      .def(py::pickle(
          [](WorldHandle& w) {
            return py::make_tuple(kPickleFormat, w.schedule_scene(), w.world().def().worker_count,
                                  run_snapshot(w));
          },
          [](const py::tuple& state) { return unpickle_world(state); }))
      .def("__repr__", [](WorldHandle& w) {
        return "<minkowski.World: " + std::to_string(w.world().body_count()) + " bodies, " +
               std::to_string(w.world().joint_count()) + " joints, step " +
               std::to_string(w.world().step_count()) + ">";
      });
  return world;
}

}  // namespace mink::python
