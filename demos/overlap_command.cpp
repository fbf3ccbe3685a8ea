#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "overlap_query.hpp"
#include "point_reader.hpp"

namespace mink::cli {

namespace {

int run_overlap(const std::string& input, Streams streams) {
  std::ifstream file;
  std::istream& in = open_input(input, streams.in, file);
  std::string line;
  std::size_t line_number = 0;
  bool all_ok = true;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    bool ok = false;
    streams.out << overlap_line(line, line_number, ok) << '\n';
    all_ok = all_ok && ok;
  }
  return all_ok ? kSuccess : kBadInput;
}

}  // namespace

Action add_overlap_command(CLI::App& app, Streams streams) {
  auto input = std::make_shared<std::string>("-");
  CLI::App* command = app.add_subcommand(
      "overlap",
      "Do two convex hulls overlap, and by how much? GJK, with EPA for the depth.\n"
      "Input: JSON Lines, one query per line: {\"a\": [[x, y], ...], \"b\": [[x, y], ...]}, two\n"
      "point sets in world coordinates, each hulled first; blank lines are skipped.\n"
      "Output: one line per query, in order: {\"overlap\": bool, \"distance\": d, \"depth\": p,\n"
      "\"normal\": [nx, ny], \"iterations\": k}. distance >= 0 is the separation (0 when\n"
      "overlapping), depth >= 0 the penetration depth (0 when apart), normal the unit vector\n"
      "from a towards b (moving b by depth along it ends the overlap). Touching counts as\n"
      "overlap; the verdict near touching is exact.\n"
      "Exit codes: 0 success; 2 if any line was bad (that line gets {\"error\": \"line N: ...\"},\n"
      "the others are still answered) or the file is unreadable.");
  command->add_option("input", *input, "JSON Lines file, or - for standard input (default)");
  return [input, streams] { return run_overlap(*input, streams); };
}

}  // namespace mink::cli
