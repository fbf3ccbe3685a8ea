#include "mink/render/input_script.hpp"

#include <cmath>
#include <istream>
#include <sstream>

#include "mink/error.hpp"

namespace mink {

namespace {

[[noreturn]] void bad_line(std::string_view source, std::size_t line, const std::string& why) {
  throw InvalidArgumentError(std::string(source) + ":" + std::to_string(line) + ": " + why);
}

}  // namespace

std::vector<ScriptEvent> parse_input_script(std::istream& in, std::string_view source) {
  std::vector<ScriptEvent> events;
  std::string text;
  std::size_t line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (const std::size_t hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream fields(text);
    std::string time_text;
    if (!(fields >> time_text)) continue;  // blank
    ScriptEvent event;
    event.line = line;
    std::size_t used = 0;
    try {
      event.time = std::stod(time_text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != time_text.size() || !std::isfinite(event.time) || event.time < 0) {
      bad_line(source, line, "time '" + time_text + "' is not a number of seconds >= 0");
    }
    if (!events.empty() && event.time < events.back().time) {
      bad_line(source, line, "time " + time_text + " is earlier than the line before");
    }
    std::string action;
    if (!(fields >> action)) bad_line(source, line, "an action is missing after the time");
    const auto read_pixel = [&] {
      if (!(fields >> event.x >> event.y) || event.x < 0 || event.y < 0) {
        bad_line(source, line, action + " needs a pixel: X Y, both >= 0");
      }
    };
    if (action == "key") {
      event.kind = ScriptEvent::Kind::key;
      if (!(fields >> event.key)) bad_line(source, line, "key needs a key name");
    } else if (action == "mouse_down" || action == "mouse_up") {
      event.kind =
          action == "mouse_down" ? ScriptEvent::Kind::mouse_down : ScriptEvent::Kind::mouse_up;
      read_pixel();
      std::string button;
      if (fields >> button) {
        if (button == "left") {
          event.button = 1;
        } else if (button == "middle") {
          event.button = 2;
        } else if (button == "right") {
          event.button = 3;
        } else {
          bad_line(source, line, "button '" + button + "' is not left, middle or right");
        }
      }
    } else if (action == "mouse_move") {
      event.kind = ScriptEvent::Kind::mouse_move;
      read_pixel();
    } else if (action == "screenshot") {
      event.kind = ScriptEvent::Kind::screenshot;
    } else if (action == "quit") {
      event.kind = ScriptEvent::Kind::quit;
    } else {
      bad_line(source, line, "unknown action '" + action + "'");
    }
    std::string extra;
    if (fields >> extra) bad_line(source, line, "unexpected '" + extra + "' after " + action);
    events.push_back(std::move(event));
  }
  return events;
}

std::vector<ScriptEvent> ScriptPlayer::due(double now) {
  std::vector<ScriptEvent> ready;
  while (next_ < events_.size() && events_[next_].time <= now) ready.push_back(events_[next_++]);
  return ready;
}

}  // namespace mink
