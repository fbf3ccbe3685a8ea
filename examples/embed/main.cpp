// Drops a few convex hulls (each made from a cloud of points) onto a static ground box read from
// scene-file text, runs four seconds of simulation and prints where each body came to rest.
#include <cstdio>
#include <vector>

#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"

int main() {
  // The ground comes from a scene file's text (docs/scene-format.md), the rest from the API.
  // Default world settings: gravity (0, -10), 60 Hz steps. Top face of the ground at y = 0.
  mink::World world = mink::build_world(mink::parse_scene_json(R"({"bodies": [
      {"type": "static", "position": [0, -1], "shapes": [{"box": {"half_extents": [20, 1]}}]}
  ]})"));

  std::vector<mink::BodyId> bodies;
  std::vector<double> start_heights;
  for (int i = 0; i < 4; ++i) {
    mink::BodyDef def;
    def.type = mink::BodyType::dynamic;
    def.position = {1.5 * i - 2.25, 2.0 + 1.5 * i};
    def.angle = 0.3 * i;
    mink::ShapeDef shape;  // any point set: the shape is its convex hull
    shape.points = {{-0.5, -0.4}, {0.6, -0.3}, {0.4, 0.5}, {-0.3, 0.6}, {0.0, 0.0}, {0.1, -0.2}};
    const mink::BodyId body = world.create_body(def);
    world.create_shape(body, shape);
    bodies.push_back(body);
    start_heights.push_back(def.position.y());
  }

  for (int step = 0; step < 240; ++step) world.step();

  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const mink::Vec2 p = world.position(bodies[i]);
    std::printf("body %zu start_y=%.3f x=%.3f y=%.3f speed=%.4f awake=%d\n", i, start_heights[i],
                p.x(), p.y(), world.linear_velocity(bodies[i]).norm(),
                world.is_awake(bodies[i]) ? 1 : 0);
  }
  return 0;
}
