// Sensors: shapes that report what overlaps them and never push. After each step every sensor
// finds its visitors (broadphase candidates, then the exact distance test), and the sorted
// set is merged with the last one into begin and end events, in sensor then visitor slot order.

#include "sensor.hpp"

#include <algorithm>

#include "world_state.hpp"

namespace mink {

using detail::SensorState;
using detail::Shape;

namespace {

bool slot_less(const ShapeId& a, const ShapeId& b) {
  return a.index != b.index ? a.index < b.index : a.generation < b.generation;
}

}  // namespace

void WorldState::update_sensors() {
  std::vector<ShapeId> found;
  for (SensorState& sensor : sensors) {
    const Shape& s = shapes[sensor.shape];
    const detail::Body& body = bodies[s.body];
    found.clear();
    if (s.sensor_events && body.enabled) {
      const Pose pose = body.pose();
      query_scratch.clear();
      broadphase.query(compute_aabb(s.geometry, pose), query_scratch);
      for (ProxyId proxy : query_scratch) {
        const auto index = static_cast<std::uint32_t>(broadphase.user_data(proxy));
        if (index >= shapes.size()) continue;
        const Shape& visitor = shapes[index];
        if (!visitor.alive || visitor.proxy != proxy || visitor.sensor || !visitor.sensor_events ||
            visitor.body == s.body || !should_collide(s.filter, visitor.filter)) {
          continue;
        }
        const ShapeDistance d =
            shape_distance(s.geometry, pose, visitor.geometry, bodies[visitor.body].pose());
        if (d.overlap) found.push_back(shape_id(index));
      }
      std::sort(found.begin(), found.end(), slot_less);
    }
    // Merge the sorted old and new sets: what is only in the new one began, only in the old
    // one ended.
    const ShapeId sensor_id = shape_id(sensor.shape);
    std::size_t i = 0, j = 0;
    const std::vector<ShapeId>& old = sensor.visitors;
    while (i < old.size() || j < found.size()) {
      if (j == found.size() || (i < old.size() && slot_less(old[i], found[j]))) {
        sensor_end_events.push_back({sensor_id, old[i++]});
      } else if (i == old.size() || slot_less(found[j], old[i])) {
        sensor_begin_events.push_back({sensor_id, found[j++]});
      } else {
        ++i, ++j;
      }
    }
    sensor.visitors.swap(found);
  }
}

void WorldState::destroy_sensor(std::uint32_t shape_index) {
  const auto at =
      std::lower_bound(sensors.begin(), sensors.end(), shape_index,
                       [](const SensorState& state, std::uint32_t i) { return state.shape < i; });
  if (at == sensors.end() || at->shape != shape_index) return;
  for (const ShapeId& visitor : at->visitors) {
    sensor_end_events.push_back({shape_id(shape_index), visitor});
  }
  sensors.erase(at);
}

}  // namespace mink
