#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "point_reader.hpp"

namespace mink::cli {

namespace {

struct HullSettings {
  std::string algorithm = "chan";
  std::string input = "-";
  bool time = false;
  bool prefilter = false;
};

int run_hull(const HullSettings& settings, Streams streams) {
  const HullAlgorithm algorithm = parse_hull_algorithm(settings.algorithm);
  std::ifstream file;
  const std::vector<Vec2> points = read_points(open_input(settings.input, streams.in, file));

  const auto started = std::chrono::steady_clock::now();
  const ConvexHull hull = build_hull(points, algorithm, HullOptions{settings.prefilter});
  const auto elapsed = std::chrono::steady_clock::now() - started;

  char line[64];
  for (const Vec2& v : hull.vertices()) {
    std::snprintf(line, sizeof line, "%.17g %.17g\n", v.x(), v.y());
    streams.out << line;
  }
  if (settings.time) {
    const double ms = std::chrono::duration<double, std::milli>(elapsed).count();
    std::snprintf(line, sizeof line, "%.3f", ms);
    streams.err << "hull: " << points.size() << " points -> " << hull.size() << " vertices in "
                << line << " ms (" << to_string(algorithm)
                << (settings.prefilter ? ", prefilter" : "") << ")\n";
  }
  return kSuccess;
}

}  // namespace

Action add_hull_command(CLI::App& app, Streams streams) {
  auto settings = std::make_shared<HullSettings>();
  CLI::App* command = app.add_subcommand(
      "hull",
      "Convex hull of a point set.\n"
      "Input: one point per line, 'x y' separated by spaces, tabs or one comma; blank lines and\n"
      "lines starting with '#' are skipped. Output: the hull's vertices, one 'x y' per line with\n"
      "17 significant digits, counter-clockwise from the lowest-x (then lowest-y) vertex, with no\n"
      "duplicate or collinear vertices.\n"
      "Exit codes: 0 success; 2 malformed line or non-finite value ('line N: ...' on stderr) or\n"
      "unreadable file; 3 fewer than 3 distinct non-collinear points.");
  command
      ->add_option("--algorithm,-a", settings->algorithm,
                   "chan (default), divide-conquer, graham, jarvis or monotone-chain")
      ->check(CLI::IsMember({"chan", "divide-conquer", "graham", "jarvis", "monotone-chain"}));
  command->add_option("input", settings->input, "point file, or - for standard input (default)");
  command->add_flag("--time", settings->time, "print the time to build the hull alone to stderr");
  command->add_flag("--prefilter", settings->prefilter,
                    "drop points inside the polygon of extreme points first (Akl-Toussaint); "
                    "same hull, often faster");
  return [settings, streams] { return run_hull(*settings, streams); };
}

}  // namespace mink::cli
