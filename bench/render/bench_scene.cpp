#include "bench_scene.hpp"

#include <memory>

#include "mink/engine/scene.hpp"
#include "mink/engine/world.hpp"

namespace mink::bench {

BenchScene large_pyramid(int steps) {
  auto world = std::make_shared<World>(build_world(builtin_scene("large_pyramid")));
  for (int i = 0; i < steps; ++i) world->step();
  BenchScene scene;
  // The camera fits the pyramid; the ground reaches past the frame's edges.
  bool first = true;
  for (const BodyId body : world->bodies()) {
    if (world->body_type(body) != BodyType::dynamic) continue;
    ++scene.bodies;
    for (const ShapeId shape : world->body_shapes(body)) {
      const Aabb box = world->shape_aabb(shape);
      scene.lower = first ? box.lower : scene.lower.cwiseMin(box.lower);
      scene.upper = first ? box.upper : scene.upper.cwiseMax(box.upper);
      first = false;
    }
  }
  scene.lower.y() -= 1;  // a strip of the ground
  scene.draw = [world](DebugDraw& draw) { world->draw(draw); };
  return scene;
}

const BenchScene& bench_scene() {
  static const BenchScene scene = large_pyramid();
  return scene;
}

}  // namespace mink::bench
