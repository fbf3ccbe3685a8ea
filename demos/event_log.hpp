#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>

#include "mink/engine/world.hpp"
#include "mink/output_file.hpp"

namespace mink::cli {

// `mink run --events`: the world's events as JSON Lines, one object per event, each with
// "step" (the step that raised it, 1-based), "type", "shape_a", "shape_b" (shape slot
// indices) and "body_a", "body_b" (indices into the scene's bodies array). Types:
// "contact_begin" (with "normal" [x, y] from A to B, "points" [[x, y], ...] and
// "separations"), "contact_end", "sensor_begin" and "sensor_end" (shape_a and body_a are the
// sensor's), and "hit" (with "point", "normal" and "speed", the approach speed in m/s).
// "joint_break" lines name a joint instead of shapes: "joint" (index into the scene's joints
// array), its "body_a" and "body_b", "force" [x, y] (N, on body B) and "torque" (N m).
// "body_stopped" lines name a body the step stopped because its solve diverged ("body", and
// "diverged": whether on it, or on a body joined to it; World::body_stopped_events).
//
// Each event type has its own member function filling one line: pair_line() with its shapes,
// its own fields, write_line().
class EventLog {
 public:
  // `bodies[i]` is body i of the scene, `joints[i]` joint i. Throws OutputError when `path`
  // cannot be written.
  EventLog(const std::filesystem::path& path, const World& world, std::span<const BodyId> bodies,
           std::span<const JointId> joints = {});
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  // Writes every event of the world's last step.
  void write_step(const World& world);
  // Flushes and closes the file; throws OutputError when anything was lost.
  void close();
  std::size_t events_written() const { return events_; }

 private:
  struct Line;  // one JSON object being filled (defined with the JSON library, in the .cpp)

  void contact_begin(const World& world, const ContactBeginEvent& event);
  void contact_end(const World& world, const ContactEndEvent& event);
  void sensor_begin(const World& world, const SensorBeginEvent& event);
  void sensor_end(const World& world, const SensorEndEvent& event);
  void hit(const World& world, const ContactHitEvent& event);
  void joint_break(const World& world, const JointBreakEvent& event);
  void body_stopped(const BodyStoppedEvent& event);

  // A line with the fields every event has: step, type, the two shapes and their bodies.
  Line pair_line(const World& world, std::string_view type, ShapeId a, ShapeId b) const;
  void write_line(const Line& line);
  // The scene index of the shape's body; none for a shape neither live nor known at the
  // start (a stale id in an end event after its shape was destroyed).
  std::optional<std::size_t> body_index(const World& world, ShapeId shape) const;
  // The scene index of a body; none for one the scene did not have (made during the run).
  std::optional<std::size_t> body_index(BodyId body) const;

  std::filesystem::path path_;
  OutputFile out_;
  std::uint64_t step_ = 0;
  std::size_t events_ = 0;
  // Body slot -> scene index, and every shape's body index as the run began: end events may
  // name a shape (and body) destroyed since, which the world can no longer tell.
  std::unordered_map<std::uint64_t, std::size_t> body_indices_;
  std::unordered_map<std::uint64_t, std::size_t> shape_bodies_;
  std::unordered_map<std::uint64_t, std::size_t> joint_indices_;  // joint slot -> scene index
};

}  // namespace mink::cli
