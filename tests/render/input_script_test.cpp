#include "mink/render/input_script.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "mink/error.hpp"

namespace {

using Kind = mink::ScriptEvent::Kind;

std::vector<mink::ScriptEvent> parse(const std::string& text) {
  std::istringstream in(text);
  return mink::parse_input_script(in, "script.txt");
}

TEST(InputScript, ReadsEveryActionWithItsArguments) {
  const auto events = parse(
      "# drag a body, then look\n"
      "0.5 key space\n"
      "\n"
      "1.0 mouse_down 320 240   # grab\n"
      "1.2 mouse_move 400 260\n"
      "1.4 mouse_up 400 260 right\n"
      "2 screenshot\n"
      "2.5 quit\n");
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[0].kind, Kind::key);
  EXPECT_EQ(events[0].key, "space");
  EXPECT_DOUBLE_EQ(events[0].time, 0.5);
  EXPECT_EQ(events[1].kind, Kind::mouse_down);
  EXPECT_EQ(events[1].x, 320);
  EXPECT_EQ(events[1].y, 240);
  EXPECT_EQ(events[1].button, 1);
  EXPECT_EQ(events[1].line, 4u);
  EXPECT_EQ(events[2].kind, Kind::mouse_move);
  EXPECT_EQ(events[3].kind, Kind::mouse_up);
  EXPECT_EQ(events[3].button, 3);
  EXPECT_EQ(events[4].kind, Kind::screenshot);
  EXPECT_EQ(events[5].kind, Kind::quit);
}

TEST(InputScript, NamesTheLineOfAMistake) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0.5 jump\n", "script.txt:1: unknown action 'jump'"},
      {"x key a\n", "script.txt:1: time 'x'"},
      {"-1 quit\n", "script.txt:1: time '-1'"},
      {"1 quit\n0.5 quit\n", "script.txt:2: time 0.5 is earlier"},
      {"1 mouse_down 3\n", "script.txt:1: mouse_down needs a pixel"},
      {"1 mouse_up 3 4 thumb\n", "script.txt:1: button 'thumb'"},
      {"1 key\n", "script.txt:1: key needs a key name"},
      {"1 quit now\n", "script.txt:1: unexpected 'now'"},
      {"1\n", "script.txt:1: an action is missing"},
  };
  for (const auto& [text, message] : cases) {
    try {
      parse(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const mink::InvalidArgumentError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
  }
}

TEST(ScriptPlayer, HandsOutEventsWhenTheirTimeComes) {
  mink::ScriptPlayer player(parse("0 key a\n0.5 key b\n0.5 key c\n1 quit\n"));
  EXPECT_EQ(player.due(0).size(), 1u);
  EXPECT_TRUE(player.due(0.25).empty());
  const auto both = player.due(0.5);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].key, "b");
  EXPECT_EQ(both[1].key, "c");
  EXPECT_FALSE(player.finished());
  EXPECT_EQ(player.due(10).size(), 1u);
  EXPECT_TRUE(player.finished());
}

}  // namespace
