// minkowski._minkowski: the engine for Python. The package minkowski re-exports it and adds
// the pure-Python parts (sweeps, environment helpers).
#include "bindings.hpp"

PYBIND11_MODULE(_minkowski, m) {
  using namespace mink::python;
  m.doc() =
      "Minkowski, a 2D rigid-body physics engine: worlds, bodies, shapes, joints, events, "
      "queries, scene files, batch arrays and frames.";
  bind_errors(m);
  bind_definitions(m);
  WorldClass world = bind_world(m);
  bind_bodies(m, world);
  bind_shapes(m, world);
  bind_joints(m, world);
  bind_batch_arrays(world);
  bind_events(world);
  bind_queries(m, world);
  bind_scenes(m, world);
  bind_frames(m);
}
