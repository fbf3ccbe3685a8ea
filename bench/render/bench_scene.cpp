#include "bench_scene.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace mink::bench {

BenchScene synthetic_pyramid(int rows) {
  // The boxes' corners, computed once: the benchmark measures drawing, not the scene.
  auto boxes = std::make_shared<std::vector<std::array<Vec2, 4>>>();
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < rows - row; ++column) {
      const Vec2 centre(column - (rows - row) / 2.0 + 0.5, row + 0.5);
      const double angle = 0.05 * std::sin(row * 7.0 + column * 3.0);
      const Vec2 u = 0.48 * Vec2(std::cos(angle), std::sin(angle));
      const Vec2 v(-u.y(), u.x());
      boxes->push_back({centre - u - v, centre + u - v, centre + u + v, centre - u + v});
    }
  }
  const auto count = boxes->size();
  BenchScene scene;
  scene.bodies = count;
  scene.lower = Vec2(-rows / 2.0 - 1, -1);
  scene.upper = Vec2(rows / 2.0 + 1, rows + 1);
  scene.draw = [boxes](DebugDraw& draw) {
    std::size_t i = 0;
    for (const auto& box : *boxes) {
      // Sleeping bodies get their own colour in World::draw; a few here do too.
      const bool asleep = ++i % 7 == 0;
      const Color fill = asleep ? Color{0.45f, 0.45f, 0.55f, 1} : Color{0.85f, 0.55f, 0.25f, 1};
      draw.draw_polygon(box, fill, Color{0.1f, 0.1f, 0.1f, 1});
    }
  };
  return scene;
}

}  // namespace mink::bench
