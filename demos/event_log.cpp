#include "event_log.hpp"

#include <nlohmann/json.hpp>
#include <string>

#include "output_files.hpp"

namespace mink::cli {

namespace {

constexpr std::string_view kWhat = "--events file";

// Ids are compared with their generation, so a reused slot is not mistaken for the old object.
template <typename Id>
std::uint64_t key(Id id) {
  return (std::uint64_t{id.index} << 32) | id.generation;
}

nlohmann::ordered_json xy(const Vec2& v) {
  return nlohmann::ordered_json::array({v.x(), v.y()});
}

}  // namespace

struct EventLog::Line {
  nlohmann::ordered_json json;  // ordered: step and type come first, for people reading it
};

EventLog::EventLog(const std::filesystem::path& path, const World& world,
                   std::span<const BodyId> bodies, std::span<const JointId> joints)
    : path_(path), out_(path, std::string(kWhat)) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    body_indices_[key(bodies[i])] = i;
    for (const ShapeId shape : world.body_shapes(bodies[i])) shape_bodies_[key(shape)] = i;
  }
  for (std::size_t i = 0; i < joints.size(); ++i) joint_indices_[key(joints[i])] = i;
}

EventLog::~EventLog() = default;

void EventLog::write_step(const World& world) {
  step_ = world.step_count();
  for (const ContactBeginEvent& event : world.contact_begin_events()) contact_begin(world, event);
  for (const ContactEndEvent& event : world.contact_end_events()) contact_end(world, event);
  for (const ContactHitEvent& event : world.contact_hit_events()) hit(world, event);
  for (const SensorBeginEvent& event : world.sensor_begin_events()) sensor_begin(world, event);
  for (const SensorEndEvent& event : world.sensor_end_events()) sensor_end(world, event);
  for (const JointBreakEvent& event : world.joint_break_events()) joint_break(world, event);
  for (const BodyStoppedEvent& event : world.body_stopped_events()) body_stopped(event);
}

void EventLog::close() {
  out_.commit();
}

void EventLog::contact_begin(const World& world, const ContactBeginEvent& event) {
  Line line = pair_line(world, "contact_begin", event.shape_a, event.shape_b);
  const Manifold& m = event.manifold;
  line.json["normal"] = xy(m.normal);
  line.json["points"] = nlohmann::ordered_json::array();
  line.json["separations"] = nlohmann::ordered_json::array();
  for (int i = 0; i < m.point_count; ++i) {
    line.json["points"].push_back(xy(m.points[static_cast<std::size_t>(i)].point));
    line.json["separations"].push_back(m.points[static_cast<std::size_t>(i)].separation);
  }
  write_line(line);
}

void EventLog::sensor_begin(const World& world, const SensorBeginEvent& event) {
  write_line(pair_line(world, "sensor_begin", event.sensor, event.visitor));
}

void EventLog::sensor_end(const World& world, const SensorEndEvent& event) {
  write_line(pair_line(world, "sensor_end", event.sensor, event.visitor));
}

void EventLog::hit(const World& world, const ContactHitEvent& event) {
  Line line = pair_line(world, "hit", event.shape_a, event.shape_b);
  line.json["point"] = xy(event.point);
  line.json["normal"] = xy(event.normal);
  line.json["speed"] = event.approach_speed;
  write_line(line);
}

void EventLog::contact_end(const World& world, const ContactEndEvent& event) {
  write_line(pair_line(world, "contact_end", event.shape_a, event.shape_b));
}

// A joint made during the run has no scene index: the line then names none. The joint is
// live (breaking does not destroy it), so its bodies are the world's.
void EventLog::joint_break(const World& world, const JointBreakEvent& event) {
  Line line;
  line.json["step"] = step_;
  line.json["type"] = "joint_break";
  if (const auto known = joint_indices_.find(key(event.joint)); known != joint_indices_.end()) {
    line.json["joint"] = known->second;
  }
  for (const auto& [name, body] : {std::pair{"body_a", world.joint_body_a(event.joint)},
                                   std::pair{"body_b", world.joint_body_b(event.joint)}}) {
    if (const auto index = body_index(body)) line.json[name] = *index;
  }
  line.json["force"] = xy(event.force);
  line.json["torque"] = event.torque;
  write_line(line);
}

// A body made during the run has no scene index: the line then names none.
void EventLog::body_stopped(const BodyStoppedEvent& event) {
  Line line;
  line.json["step"] = step_;
  line.json["type"] = "body_stopped";
  if (const auto index = body_index(event.body)) line.json["body"] = *index;
  line.json["diverged"] = event.diverged;
  write_line(line);
}

EventLog::Line EventLog::pair_line(const World& world, std::string_view type, ShapeId a,
                                   ShapeId b) const {
  Line line;
  line.json["step"] = step_;
  line.json["type"] = std::string(type);
  line.json["shape_a"] = a.index;
  line.json["shape_b"] = b.index;
  if (const auto body = body_index(world, a)) line.json["body_a"] = *body;
  if (const auto body = body_index(world, b)) line.json["body_b"] = *body;
  return line;
}

void EventLog::write_line(const Line& line) {
  out_.stream() << line.json.dump() << '\n';
  ++events_;
}

std::optional<std::size_t> EventLog::body_index(const World& world, ShapeId shape) const {
  if (const auto known = shape_bodies_.find(key(shape)); known != shape_bodies_.end()) {
    return known->second;
  }
  // A shape made during the run, on a body of the scene.
  if (!world.is_valid(shape)) return std::nullopt;
  return body_index(world.shape_body(shape));
}

std::optional<std::size_t> EventLog::body_index(BodyId body) const {
  const auto known = body_indices_.find(key(body));
  if (known == body_indices_.end()) return std::nullopt;
  return known->second;
}

}  // namespace mink::cli
