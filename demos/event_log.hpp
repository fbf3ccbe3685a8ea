#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>

#include "mink/engine/world.hpp"

namespace mink::cli {

// `mink run --events`: the world's events as JSON Lines, one object per event, each with
// "step" (the step that raised it, 1-based), "type", "shape_a", "shape_b" (shape slot
// indices) and "body_a", "body_b" (indices into the scene's bodies array). Types so far:
// "contact_begin" and "contact_end".
//
// Each event type has its own member function filling one line, so a new engine event is a
// few lines: call pair_line() with its shapes (for a sensor event the sensor's shape first,
// so body_a is the sensor's body), add its own fields (a hit's "point", "normal", "speed"),
// write_line(), and call the function from write_step().
class EventLog {
 public:
  // `bodies[i]` is body i of the scene. Throws OutputError when `path` cannot be written.
  EventLog(const std::filesystem::path& path, const World& world, std::span<const BodyId> bodies);
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

  // A line with the fields every event has: step, type, the two shapes and their bodies.
  Line pair_line(const World& world, std::string_view type, ShapeId a, ShapeId b) const;
  void write_line(const Line& line);
  // The scene index of the shape's body; none for a shape neither live nor known at the
  // start (a stale id in an end event after its shape was destroyed).
  std::optional<std::size_t> body_index(const World& world, ShapeId shape) const;

  std::filesystem::path path_;
  std::ofstream out_;
  std::uint64_t step_ = 0;
  std::size_t events_ = 0;
  // Body slot -> scene index, and every shape's body index as the run began: end events may
  // name a shape (and body) destroyed since, which the world can no longer tell.
  std::unordered_map<std::uint64_t, std::size_t> body_indices_;
  std::unordered_map<std::uint64_t, std::size_t> shape_bodies_;
};

}  // namespace mink::cli
