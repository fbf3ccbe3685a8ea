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

// A fast body may cross a sensor within one step and be past it at the end: its sweep over the
// step (to where continuous collision stopped it) is tested too, so the sensor sees it come
// and, a step later, go.
bool WorldState::crossed_in_step(const Shape& sensor, const Pose& sensor_pose,
                                 const detail::FastBody& fast, const Shape& visitor) const {
  Sweep still;
  still.local_center = Vec2(0, 0);
  still.center0 = still.center1 = sensor_pose.position;
  still.angle0 = still.angle1 = sensor_pose.rotation.angle();
  TimeOfImpactInput input;
  input.shape_a = &sensor.geometry;
  input.sweep_a = still;
  input.shape_b = &visitor.geometry;
  input.sweep_b = fast.sweep;
  input.max_fraction = fast.fraction;
  // As near as the sweep can tell touching: a fifth of the slop, found within a tenth.
  input.target = 0.2 * def.linear_slop;
  input.tolerance = 0.1 * def.linear_slop;
  const TimeOfImpactOutput out = time_of_impact(input);
  return out.state == ToiState::hit || out.state == ToiState::overlapped;
}

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
      // Fast bodies are seen along their whole sweep: their boxes at the end of the step may
      // be past the sensor already.
      const Aabb box = compute_aabb(s.geometry, pose);
      for (const std::uint32_t fast_index : continuous.fast_list) {
        const detail::FastBody& fast = continuous.fast[fast_index];
        if (!fast.box.overlaps(box) || fast.body == s.body) continue;
        for (const std::uint32_t index : bodies[fast.body].shapes) {
          const Shape& visitor = shapes[index];
          if (visitor.sensor || !visitor.sensor_events ||
              !should_collide(s.filter, visitor.filter)) {
            continue;
          }
          const ShapeId id = shape_id(index);
          if (std::find(found.begin(), found.end(), id) != found.end()) continue;
          if (crossed_in_step(s, pose, fast, visitor)) found.push_back(id);
        }
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
