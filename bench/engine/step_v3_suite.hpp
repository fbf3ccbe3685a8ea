#pragma once

// Box2D v3's benchmark suite as its benchmark app (benchmark/main.c) runs it: the ten scenes of
// its shared/benchmarks.c, how many steps each run takes, and which scenes turn sleeping off
// (the app leaves the world's default, sleeping on, for the rest). Both runners of the race
// read this table, so the two engines step the same scenes the same number of times; the
// Box2D v3 runner checks the sleep column against the world each scene leaves behind.

#include <array>
#include <string_view>

namespace mink::bench {

struct SuiteScene {
  std::string_view name;   ///< Box2D v3's name, and our built-in's
  int steps = 0;           ///< steps per run in Box2D v3's app
  bool sleep_off = false;  ///< the scene switches sleeping off (b2World_EnableSleeping)
};

inline constexpr std::array<SuiteScene, 10> kSuite = {{
    {"compounds", 500, false},
    {"joint_grid", 500, true},
    {"junkyard", 800, false},
    {"large_pyramid", 500, true},
    {"many_pyramids", 200, true},
    {"rain", 1000, false},
    {"smash", 300, false},
    {"spinner", 500, false},
    {"tumbler", 750, false},
    {"washer", 500, false},
}};

/// The suite's scene of that name, or nullptr.
inline const SuiteScene* find_suite_scene(std::string_view name) {
  for (const SuiteScene& scene : kSuite) {
    if (scene.name == name) return &scene;
  }
  return nullptr;
}

}  // namespace mink::bench
