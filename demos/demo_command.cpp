#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <vector>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/geometry/chan.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/geometry/polygon.hpp"

namespace mink::cli {

namespace {

struct DemoSettings {
  std::uint64_t seed = 2013;
  std::size_t count = 500;
  int repeats = 101;
};

// Median wall time of `repeats` builds, in microseconds, and the hull itself.
template <typename Build>
std::pair<ConvexHull, double> timed(Build build, int repeats) {
  std::vector<double> micros;
  std::optional<ConvexHull> hull;
  for (int i = 0; i < repeats; ++i) {
    const auto started = std::chrono::steady_clock::now();
    hull.emplace(build());
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started)
            .count());
  }
  std::nth_element(micros.begin(), micros.begin() + repeats / 2, micros.end());
  return {std::move(*hull), micros[repeats / 2]};
}

void print_hull(std::ostream& out, const char* title, const ConvexHull& hull, double micros) {
  const AreaProperties properties = area_properties(hull.vertices());
  char line[160];
  std::snprintf(line, sizeof line,
                "%s: %zu vertices, area %.6g, centroid (%.6g, %.6g), median build %.1f us\n", title,
                hull.size(), properties.area, properties.centroid.x(), properties.centroid.y(),
                micros);
  out << line;
  for (const Vec2& v : hull.vertices()) {
    std::snprintf(line, sizeof line, "  %.17g %.17g\n", v.x(), v.y());
    out << line;
  }
}

int run_demo(const DemoSettings& settings, Streams streams) {
  const auto [set_a, set_b] = paper_point_sets(settings.seed, settings.count);
  streams.out << "Minkowski demo: the paper's two random point sets (" << settings.count
              << " points each in a 400 x 400 canvas, seed " << settings.seed << ")\n";
  const auto [hull_a, micros_a] = timed([&] { return chan_hull(set_a); }, settings.repeats);
  const auto [hull_b, micros_b] =
      timed([&] { return divide_conquer_hull(set_b); }, settings.repeats);
  print_hull(streams.out, "Hull A (Chan)", hull_a, micros_a);
  print_hull(streams.out, "Hull B (divide and conquer)", hull_b, micros_b);
  return kSuccess;
}

}  // namespace

Action add_demo_command(CLI::App& app, Streams streams) {
  auto settings = std::make_shared<DemoSettings>();
  CLI::App* command = app.add_subcommand(
      "demo",
      "The main job: the paper's two random point sets hulled by Chan and by divide "
      "and conquer, printed with timings.");
  command->add_option("--seed", settings->seed, "random seed (default 2013)");
  command->add_option("--points", settings->count, "points in each set (default 500)")
      ->check(CLI::Range(std::size_t{3}, std::size_t{100'000'000}));
  command->add_option("--repeats", settings->repeats, "builds timed per hull (default 101)")
      ->check(CLI::Range(1, 100'000));
  return [settings, streams] { return run_demo(*settings, streams); };
}

}  // namespace mink::cli
