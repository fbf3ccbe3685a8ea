// What the last step saw, as numpy structured arrays: one record per event, shapes, bodies and
// joints named by their slot index (-1 for one destroyed since).
#include "bindings.hpp"

namespace mink::python {

struct ContactBeginRecord {
  std::int32_t shape_a, shape_b, body_a, body_b;
  double normal[2];  // unit, world, from A towards B
  std::int32_t point_count;
  double points[2][2];  // the first point_count are valid
  double separations[2];
};

struct ContactEndRecord {
  std::int32_t shape_a, shape_b, body_a, body_b;
};

struct HitRecord {
  std::int32_t shape_a, shape_b, body_a, body_b;
  double point[2];
  double normal[2];
  double speed;
};

struct SensorRecord {
  std::int32_t sensor, visitor, sensor_body, visitor_body;
};

struct JointBreakRecord {
  std::int32_t joint, body_a, body_b;
  double force[2];
  double torque;
  std::uint64_t user_data;
};

struct BodyMoveRecord {
  std::int32_t body;
  double position[2];
  double angle;
  bool fell_asleep;
  std::uint64_t user_data;
};

struct BodyStoppedRecord {
  std::int32_t body;
  bool diverged;
  std::uint64_t user_data;
};

namespace {

std::int32_t body_of(const World& world, ShapeId shape) {
  return world.is_valid(shape) ? static_cast<std::int32_t>(world.shape_body(shape).index) : -1;
}

std::int32_t index_of(ShapeId shape) {
  return static_cast<std::int32_t>(shape.index);
}

template <class Record>
void put_pair(Record& r, const World& world, ShapeId a, ShapeId b) {
  r.shape_a = index_of(a);
  r.shape_b = index_of(b);
  r.body_a = body_of(world, a);
  r.body_b = body_of(world, b);
}

void put(double (&out)[2], const Vec2& v) {
  out[0] = v.x();
  out[1] = v.y();
}

// One record per event, made by `fill`.
template <class Record, class Event, class Fill>
py::array_t<Record> records(std::span<const Event> events, Fill fill) {
  py::array_t<Record> out(static_cast<py::ssize_t>(events.size()));
  Record* data = out.mutable_data();
  for (const Event& event : events) {
    Record record{};
    fill(event, record);
    *data++ = record;
  }
  return out;
}

py::array_t<ContactBeginRecord> contact_begins(const World& world) {
  return records<ContactBeginRecord>(
      world.contact_begin_events(), [&](const ContactBeginEvent& e, ContactBeginRecord& r) {
        put_pair(r, world, e.shape_a, e.shape_b);
        put(r.normal, e.manifold.normal);
        r.point_count = e.manifold.point_count;
        for (int i = 0; i < e.manifold.point_count; ++i) {
          const ManifoldPoint& point = e.manifold.points[static_cast<std::size_t>(i)];
          put(r.points[i], point.point);
          r.separations[i] = point.separation;
        }
      });
}

py::array_t<ContactEndRecord> contact_ends(const World& world) {
  return records<ContactEndRecord>(world.contact_end_events(),
                                   [&](const ContactEndEvent& e, ContactEndRecord& r) {
                                     put_pair(r, world, e.shape_a, e.shape_b);
                                   });
}

py::array_t<HitRecord> hits(const World& world) {
  return records<HitRecord>(world.contact_hit_events(),
                            [&](const ContactHitEvent& e, HitRecord& r) {
                              put_pair(r, world, e.shape_a, e.shape_b);
                              put(r.point, e.point);
                              put(r.normal, e.normal);
                              r.speed = e.approach_speed;
                            });
}

template <class Event>
py::array_t<SensorRecord> sensor_records(const World& world, std::span<const Event> events) {
  return records<SensorRecord>(events, [&](const Event& e, SensorRecord& r) {
    r.sensor = index_of(e.sensor);
    r.visitor = index_of(e.visitor);
    r.sensor_body = body_of(world, e.sensor);
    r.visitor_body = body_of(world, e.visitor);
  });
}

py::array_t<JointBreakRecord> joint_breaks(const World& world) {
  return records<JointBreakRecord>(
      world.joint_break_events(), [&](const JointBreakEvent& e, JointBreakRecord& r) {
        const bool live = world.is_valid(e.joint);
        r.joint = static_cast<std::int32_t>(e.joint.index);
        r.body_a = live ? static_cast<std::int32_t>(world.joint_body_a(e.joint).index) : -1;
        r.body_b = live ? static_cast<std::int32_t>(world.joint_body_b(e.joint).index) : -1;
        put(r.force, e.force);
        r.torque = e.torque;
        r.user_data = e.user_data;
      });
}

py::array_t<BodyMoveRecord> body_moves(const World& world) {
  return records<BodyMoveRecord>(world.body_move_events(),
                                 [](const BodyMoveEvent& e, BodyMoveRecord& r) {
                                   r.body = static_cast<std::int32_t>(e.body.index);
                                   put(r.position, e.pose.position);
                                   r.angle = e.pose.rotation.angle();
                                   r.fell_asleep = e.fell_asleep;
                                   r.user_data = e.user_data;
                                 });
}

py::array_t<BodyStoppedRecord> body_stops(const World& world) {
  return records<BodyStoppedRecord>(world.body_stopped_events(),
                                    [](const BodyStoppedEvent& e, BodyStoppedRecord& r) {
                                      r.body = static_cast<std::int32_t>(e.body.index);
                                      r.diverged = e.diverged;
                                      r.user_data = e.user_data;
                                    });
}

}  // namespace

void bind_events(WorldClass& world) {
  PYBIND11_NUMPY_DTYPE(ContactBeginRecord, shape_a, shape_b, body_a, body_b, normal, point_count,
                       points, separations);
  PYBIND11_NUMPY_DTYPE(ContactEndRecord, shape_a, shape_b, body_a, body_b);
  PYBIND11_NUMPY_DTYPE(HitRecord, shape_a, shape_b, body_a, body_b, point, normal, speed);
  PYBIND11_NUMPY_DTYPE(SensorRecord, sensor, visitor, sensor_body, visitor_body);
  PYBIND11_NUMPY_DTYPE(JointBreakRecord, joint, body_a, body_b, force, torque, user_data);
  PYBIND11_NUMPY_DTYPE(BodyMoveRecord, body, position, angle, fell_asleep, user_data);
  PYBIND11_NUMPY_DTYPE(BodyStoppedRecord, body, diverged, user_data);
  world
      .def(
          "contact_begin_events", [](WorldHandle& w) { return contact_begins(w.world()); },
          "Pairs that began touching in the last step: a structured array of shape_a, shape_b, "
          "body_a, body_b (indices), normal (2, from A to B), point_count, points (2, 2) and "
          "separations (2).")
      .def(
          "contact_end_events", [](WorldHandle& w) { return contact_ends(w.world()); },
          "Pairs that stopped touching: shape_a, shape_b, body_a, body_b (-1 for a body "
          "destroyed since).")
      .def(
          "hit_events", [](WorldHandle& w) { return hits(w.world()); },
          "Contacts that began faster than hit_event_threshold (shapes with hit_events): "
          "shape_a, shape_b, body_a, body_b, point (2), normal (2), speed.")
      .def(
          "sensor_begin_events",
          [](WorldHandle& w) { return sensor_records(w.world(), w.world().sensor_begin_events()); },
          "Shapes that began overlapping a sensor: sensor, visitor, sensor_body, visitor_body.")
      .def(
          "sensor_end_events",
          [](WorldHandle& w) { return sensor_records(w.world(), w.world().sensor_end_events()); },
          "Shapes that stopped overlapping a sensor: sensor, visitor, sensor_body, visitor_body.")
      .def(
          "joint_break_events", [](WorldHandle& w) { return joint_breaks(w.world()); },
          "Joints whose force or torque exceeded their break thresholds: joint, body_a, body_b, "
          "force (2), torque, user_data.")
      .def(
          "body_move_events", [](WorldHandle& w) { return body_moves(w.world()); },
          "Bodies the last step moved: body, position (2), angle, fell_asleep, user_data.")
      .def(
          "body_stopped_events", [](WorldHandle& w) { return body_stops(w.world()); },
          "Bodies the last step put back where it began, at rest, because the solve diverged "
          "on them (diverged) or on bodies joined to them: body, diverged, user_data.")
      .def(
          "events",
          [](WorldHandle& w) {
            const World& world = w.world();
            py::dict out;
            out["contact_begin"] = contact_begins(world);
            out["contact_end"] = contact_ends(world);
            out["hit"] = hits(world);
            out["sensor_begin"] = sensor_records(world, world.sensor_begin_events());
            out["sensor_end"] = sensor_records(world, world.sensor_end_events());
            out["joint_break"] = joint_breaks(world);
            out["body_stopped"] = body_stops(world);
            return out;
          },
          "Every event list of the last step but body moves, by name (contact_begin, "
          "contact_end, hit, sensor_begin, sensor_end, joint_break, body_stopped).");
}

}  // namespace mink::python
