#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace mink {

/// @brief One timed input event of a script.
///
/// Timed input for scripted runs of an interactive window (`--script FILE`, tests under
/// Xvfb). One event a line, "TIME ACTION ARGUMENTS", times in seconds of simulated time, not
/// decreasing; blank lines and '#' comments are skipped:
/// @verbatim
///   0.5  key space            press and release a key (SDL key names: space, r, Escape, ...)
///   1.0  mouse_down 320 240   press a mouse button at a pixel (left unless a button is named:
///   1.0  mouse_down 320 240 right                                          left, middle, right)
///   1.2  mouse_move 400 260
///   1.4  mouse_up 400 260
///   2.0  screenshot           save the frame (to the --screenshot file)
///   2.5  quit
/// @endverbatim
struct ScriptEvent {
  /// @brief The ACTION of a script line.
  enum class Kind { key, mouse_down, mouse_up, mouse_move, screenshot, quit };
  double time = 0;         ///< seconds of simulated time
  Kind kind = Kind::quit;  ///< what happens
  std::string key;         ///< for key
  int x = 0;               ///< for mouse events, pixels from the window's left edge
  int y = 0;               ///< from its top edge
  int button = 1;          ///< 1 left, 2 middle, 3 right (SDL's numbering)
  std::size_t line = 0;    ///< 1-based line in the script, for messages
};

/// @brief Parses a whole script (format: see ScriptEvent).
/// @param in the script text
/// @param source the script's name for messages, such as its file name
/// @throws InvalidArgumentError naming `source` and the line for anything malformed.
std::vector<ScriptEvent> parse_input_script(std::istream& in, std::string_view source);

/// @brief Hands out the events whose time has come, in order.
class ScriptPlayer {
 public:
  /// @brief Plays `events` (in parse order, times not decreasing).
  explicit ScriptPlayer(std::vector<ScriptEvent> events) : events_(std::move(events)) {}
  /// @brief The events with time <= now not handed out yet.
  std::vector<ScriptEvent> due(double now);
  /// @brief True once every event was handed out.
  bool finished() const { return next_ == events_.size(); }

 private:
  std::vector<ScriptEvent> events_;
  std::size_t next_ = 0;
};

}  // namespace mink
